package org.fresa.ui;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.chart.PlotScene;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.ExactDecimal;
import org.fresa.stepnc.Executable;
import org.fresa.stepnc.Feature;
import org.fresa.stepnc.MachiningWorkingstep;
import org.fresa.stepnc.Operation;
import org.fresa.stepnc.Profile;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.Technology;
import org.fresa.stepnc.Tool;
import org.fresa.stepnc.Workpiece;
import org.fresa.stepnc.Workplan;

/**
 * The STEP-NC tab's state without Swing: the program read, its tree (project, workplans,
 * workingsteps, then skipped workingsteps and unknown entities, never hidden), the details of
 * the selected workingstep with units, and a plot of the workpiece block and the feature
 * outline seen along the feature axis.
 */
final class StepNcViewModel {

    /** A node of the tree; {@code workingstep} is set on workingstep leaves. */
    record Node(String label, List<Node> children, Optional<MachiningWorkingstep> workingstep) {
        Node {
            Objects.requireNonNull(label);
            children = List.copyOf(children);
            Objects.requireNonNull(workingstep);
        }

        static Node leaf(String label) {
            return new Node(label, List.of(), Optional.empty());
        }

        @Override
        public String toString() {
            return label;
        }
    }

    private Optional<StepNcProgram> program = Optional.empty();
    private Optional<MachiningWorkingstep> selected = Optional.empty();

    Optional<StepNcProgram> program() {
        return program;
    }

    void load(StepNcProgram p) {
        program = Optional.of(p);
        selected = p.workingsteps().isEmpty() ? Optional.empty() : Optional.of(p.workingsteps().get(0));
    }

    Optional<MachiningWorkingstep> selected() {
        return selected;
    }

    void select(Optional<MachiningWorkingstep> ws) {
        selected = ws;
    }

    /** The tree: project > workplans > workingsteps; skipped workingsteps; unknown entities. */
    Optional<Node> tree() {
        if (program.isEmpty()) {
            return Optional.empty();
        }
        StepNcProgram p = program.get();
        List<Node> top = new ArrayList<>();
        int[] counter = {0};
        p.mainWorkplan().ifPresent(w -> top.add(workplanNode(w, counter)));
        if (!p.skipped().isEmpty()) {
            List<Node> sk = new ArrayList<>();
            for (StepNcProgram.Skipped s : p.skipped()) {
                sk.add(new Node("#" + s.instanceId() + " " + s.id() + " (" + s.reason() + ")", List.of(),
                        s.workingstep()));
            }
            top.add(new Node("Skipped workingsteps (" + p.skipped().size() + ")", sk, Optional.empty()));
        }
        if (!p.unknownEntities().isEmpty()) {
            List<Node> un = new ArrayList<>();
            p.unknownEntities().forEach((k, c) -> un.add(Node.leaf(k + " x" + c)));
            top.add(new Node("Entities not interpreted (" + p.unknownEntities().size() + " types)", un,
                    Optional.empty()));
        }
        if (!p.spellings().isEmpty() || !p.warnings().isEmpty()) {
            List<Node> notes = new ArrayList<>();
            p.spellings().forEach(s -> notes.add(Node.leaf("seen: " + s)));
            p.warnings().forEach(s -> notes.add(Node.leaf("warning: " + s)));
            top.add(new Node("Notes (" + notes.size() + ")", notes, Optional.empty()));
        }
        return Optional.of(new Node("Project '" + p.projectId() + "' (" + p.source() + ", " + p.instanceCount()
                + " instances)", top, Optional.empty()));
    }

    private static Node workplanNode(Workplan w, int[] counter) {
        List<Node> children = new ArrayList<>();
        for (Executable e : w.elements()) {
            if (e instanceof Workplan sub) {
                children.add(workplanNode(sub, counter));
            } else if (e instanceof MachiningWorkingstep ws) {
                counter[0]++;
                children.add(new Node(counter[0] + ". " + ws.id() + ": " + ws.operation().entity() + " on "
                        + ws.feature().entity(), List.of(), Optional.of(ws)));
            } else if (e instanceof Executable.Other o) {
                children.add(Node.leaf("#" + o.instanceId() + " " + o.entity() + " (not interpreted)"));
            }
        }
        String setup = w.setup().map(s -> ", setup '" + s.id() + "'").orElse("");
        return new Node("Workplan '" + w.id() + "'" + setup, children, Optional.empty());
    }

    /** The selected workingstep's feature, operation, strategy, tool and technology, with units. */
    List<String> details() {
        List<String> out = new ArrayList<>();
        if (selected.isEmpty()) {
            program.ifPresent(p -> {
                out.add(p.source() + ": " + p.workingsteps().size() + " workingsteps, " + p.skipped().size()
                        + " skipped");
                for (Workpiece w : p.workpieces()) {
                    out.add("Workpiece '" + w.id() + "'" + w.material().map(m -> ", " + m).orElse("")
                            + w.block().map(b -> ", block " + n(b.xMm()) + " x " + n(b.yMm()) + " x " + n(b.zMm())
                                    + " mm").orElse(""));
                }
            });
            return out;
        }
        MachiningWorkingstep ws = selected.get();
        Feature f = ws.feature();
        out.add("Workingstep #" + ws.instanceId() + " '" + ws.id() + "'");
        out.add("Feature: " + f.entity() + " '" + f.id() + "' (#" + f.instanceId() + ")");
        out.add("  location " + v(f.location()) + " mm, axis " + v(f.axis()));
        f.depthMm().ifPresent(d -> out.add("  depth " + n(d) + " mm"));
        f.diameterMm().ifPresent(d -> out.add("  diameter " + n(d) + " mm"));
        f.bottomCondition().ifPresent(b -> out.add("  bottom " + b));
        f.orthogonalRadiusMm().ifPresent(r -> out.add("  corner radius " + n(r) + " mm"));
        f.profile().ifPresent(pr -> out.add("  profile " + profileText(pr)));
        Operation o = ws.operation();
        out.add("Operation: " + o.entity() + " '" + o.id() + "' (#" + o.instanceId() + ")");
        o.strategy().ifPresent(s -> {
            String overlap = s.overlapFraction().isPresent()
                    ? ", overlap " + n(s.overlapFraction().getAsDouble() * 100) + " % of the tool diameter (written as "
                    + s.overlapInterpretation().orElse("?") + " " + n(s.overlap().orElse(0)) + ")"
                    : "";
            out.add("  strategy " + s.entity() + overlap + s.rotationDirection().map(r -> ", " + r).orElse("")
                    + s.cutmode().map(c -> ", " + c).orElse(""));
        });
        mm(out, "  axial cutting depth", o.axialCuttingDepthMm());
        mm(out, "  radial cutting depth", o.radialCuttingDepthMm());
        mm(out, "  allowance side", o.allowanceSideMm());
        mm(out, "  allowance bottom", o.allowanceBottomMm());
        mm(out, "  cutting depth", o.cuttingDepthMm());
        mm(out, "  retract plane", o.retractPlaneMm());
        o.approach().ifPresent(a -> out.add("  approach " + a.entity()));
        o.retract().ifPresent(a -> out.add("  retract " + a.entity()));
        o.tool().ifPresent(t -> toolText(out, t));
        Technology t = o.technology();
        out.add("Technology:");
        t.feedrate().ifPresent(fd -> out.add("  feed " + n(fd) + " " + unit(t.feedrateUnit())
                + t.feedMmPerMin().stream().mapToObj(x -> " = " + n(x) + " mm/min").findFirst().orElse("")));
        t.cutSpeed().ifPresent(c -> out.add("  cutting speed " + n(c) + " " + t.cutSpeedUnit()));
        t.spindle().ifPresent(s -> out.add("  spindle " + n(s) + " " + t.spindleUnit()
                + t.spindleRpm().stream().mapToObj(x -> " = " + n(x) + " rpm").findFirst().orElse("")
                + (t.spindleClockwise() ? ", clockwise" : "")));
        return out;
    }

    private static void toolText(List<String> out, Tool t) {
        out.add("Tool: '" + t.id() + "' " + t.body() + " (#" + t.instanceId() + ")");
        mm(out, "  diameter", t.diameterMm());
        mm(out, "  edge radius", t.edgeRadiusMm());
        mm(out, "  cutting edge length", t.cuttingEdgeLengthMm());
        mm(out, "  overall assembly length", t.overallAssemblyLengthMm());
        mm(out, "  tool offset length", t.toolOffsetLengthMm());
        t.teeth().ifPresent(k -> out.add("  teeth " + k));
    }

    private static String profileText(Profile p) {
        if (p instanceof Profile.Rectangular r) {
            return p.entity() + " " + n(r.lengthMm()) + " x " + n(r.widthMm()) + " mm";
        } else if (p instanceof Profile.Circular c) {
            return p.entity() + " diameter " + n(c.diameterMm()) + " mm";
        } else if (p instanceof Profile.Ngon g) {
            return p.entity() + " " + g.sides() + " sides, diameter " + n(g.diameterMm()) + " mm";
        } else if (p instanceof Profile.General g) {
            return p.entity() + " (" + g.curveEntity() + ", " + g.segments().size() + " segments)";
        } else if (p instanceof Profile.U u) {
            return p.entity() + " width " + n(u.widthMm()) + " mm";
        } else if (p instanceof Profile.Linear l) {
            return p.entity() + " length " + n(l.lengthMm()) + " mm";
        }
        return p.entity() + " (not drawn)";
    }

    private static String unit(String u) {
        return u.equals("unstated") ? "(unit not stated by the file's writer)" : u;
    }

    private static void mm(List<String> out, String label, OptionalDouble v) {
        v.ifPresent(d -> out.add(label + " " + n(d) + " mm"));
    }

    /**
     * The workpiece block and the selected feature's outline, seen along the feature axis: from
     * above (XY) for a feature on the top face, from the front (XZ) or the side (YZ) otherwise.
     */
    PlotScene plot() {
        if (program.isEmpty()) {
            return PlotScene.empty("STEP-NC");
        }
        int drop = selected.map(ws -> dominant(ws.feature().axis())).orElse(2);
        String[] names = {"Side view (YZ)", "Front view (XZ)", "Top view (XY)"};
        PlotScene scene = PlotScene.empty(names[drop]);
        for (Workpiece w : program.get().workpieces()) {
            if (w.block().isPresent()) {
                Workpiece.Block b = w.block().get();
                List<Vec2> pts = new ArrayList<>();
                for (int i = 0; i < 8; i++) {
                    Vec3 c = b.placement().applyToPoint(new Vec3((i & 1) * b.xMm(), ((i >> 1) & 1) * b.yMm(),
                            ((i >> 2) & 1) * b.zMm()));
                    pts.add(project(c, drop));
                }
                scene = scene.with(new PlotScene.Layer("block '" + w.id() + "'", PlotScene.Style.OUTLINE,
                        box(pts)));
            }
        }
        if (selected.isPresent()) {
            Feature f = selected.get().feature();
            List<Curve2> outline = outline(f, drop);
            if (!outline.isEmpty()) {
                scene = scene.with(new PlotScene.Layer(f.entity() + " '" + f.id() + "'", PlotScene.Style.FEED, outline));
            }
            scene = scene.withLabel(project(f.location(), drop), f.id());
        }
        return scene;
    }

    /** The feature outline in the view plane; empty when the profile is not drawable. */
    static List<Curve2> outline(Feature f, int drop) {
        List<Curve2> out = new ArrayList<>();
        Transform3 frame = f.placement();
        if (f.type() == Feature.FeatureType.ROUND_HOLE && f.diameterMm().isPresent()) {
            Vec2 c = project(frame.translationPart(), drop);
            out.add(Arc2.circle(c, f.diameterMm().getAsDouble() / 2, true));
            return out;
        }
        if (f.profile().isEmpty()) {
            return out;
        }
        Profile p = f.profile().get();
        Transform3 t = frame.times(p.placement());
        List<Vec3> local = new ArrayList<>();
        if (p instanceof Profile.Rectangular r) {
            double hx = r.lengthMm() / 2;
            double hy = r.widthMm() / 2;
            local.addAll(List.of(new Vec3(-hx, -hy, 0), new Vec3(hx, -hy, 0), new Vec3(hx, hy, 0), new Vec3(-hx, hy, 0),
                    new Vec3(-hx, -hy, 0)));
        } else if (p instanceof Profile.Circular c) {
            out.add(Arc2.circle(project(t.translationPart(), drop), c.diameterMm() / 2, true));
            return out;
        } else if (p instanceof Profile.Ngon g) {
            double r = g.circumscribed() ? g.diameterMm() / 2 / Math.cos(Math.PI / g.sides()) : g.diameterMm() / 2;
            // ISO 14649-10: one side parallel to x, crossing -y
            for (int i = 0; i <= g.sides(); i++) {
                double a = -Math.PI / 2 - Math.PI / g.sides() + 2 * Math.PI * i / g.sides();
                local.add(new Vec3(r * Math.cos(a), r * Math.sin(a), 0));
            }
        } else if (p instanceof Profile.General g) {
            for (Profile.Segment s : g.segments()) {
                Vec2 a = project(t.applyToPoint(s.start()), drop);
                Vec2 b = project(t.applyToPoint(s.end()), drop);
                if (a.distance(b) > 0) {
                    out.add(Segment2.of(a, b));
                }
            }
            return out;
        }
        for (int i = 0; i + 1 < local.size(); i++) {
            Vec2 a = project(t.applyToPoint(local.get(i)), drop);
            Vec2 b = project(t.applyToPoint(local.get(i + 1)), drop);
            if (a.distance(b) > 0) {
                out.add(Segment2.of(a, b));
            }
        }
        return out;
    }

    private static List<Curve2> box(List<Vec2> pts) {
        double x0 = Double.POSITIVE_INFINITY;
        double y0 = Double.POSITIVE_INFINITY;
        double x1 = Double.NEGATIVE_INFINITY;
        double y1 = Double.NEGATIVE_INFINITY;
        for (Vec2 p : pts) {
            x0 = Math.min(x0, p.x());
            y0 = Math.min(y0, p.y());
            x1 = Math.max(x1, p.x());
            y1 = Math.max(y1, p.y());
        }
        return List.of(Segment2.of(x0, y0, x1, y0), Segment2.of(x1, y0, x1, y1), Segment2.of(x1, y1, x0, y1),
                Segment2.of(x0, y1, x0, y0));
    }

    /** 0, 1 or 2: the coordinate the axis mostly points along (the one a view along it drops). */
    static int dominant(Vec3 axis) {
        double ax = Math.abs(axis.x());
        double ay = Math.abs(axis.y());
        double az = Math.abs(axis.z());
        if (az >= ax && az >= ay) {
            return 2;
        }
        return ay >= ax ? 1 : 0;
    }

    static Vec2 project(Vec3 p, int drop) {
        return switch (drop) {
            case 0 -> new Vec2(p.y(), p.z());
            case 1 -> new Vec2(p.x(), p.z());
            default -> new Vec2(p.x(), p.y());
        };
    }

    private static String n(double d) {
        return ExactDecimal.of(Math.round(d * 1e4) / 1e4 + 0.0);
    }

    private static String v(Vec3 p) {
        return String.format(Locale.ROOT, "(%s, %s, %s)", n(p.x()), n(p.y()), n(p.z()));
    }
}
