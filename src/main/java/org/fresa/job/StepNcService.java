package org.fresa.job;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.OptionalDouble;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.io.Json;
import org.fresa.io.OutputFolder;
import org.fresa.model.CamInputException;
import org.fresa.model.ExactDecimal;
import org.fresa.stepnc.Executable;
import org.fresa.stepnc.Feature;
import org.fresa.stepnc.MachiningWorkingstep;
import org.fresa.stepnc.Operation;
import org.fresa.stepnc.Profile;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.StepNcReader;
import org.fresa.stepnc.Tool;
import org.fresa.stepnc.Workpiece;
import org.fresa.stepnc.Workplan;

/**
 * STEP-NC import as a task: reads a Part 21 file and describes it, for {@code fresa stepnc},
 * {@code fresa run} (task stepnc) and the GUI. The JSON summary follows spec/cli.md.
 */
public final class StepNcService {

    private StepNcService() {}

    /** Reads and binds the file. */
    public static StepNcProgram read(Path file, ProgressMonitor progress) throws CamInputException, IOException {
        progress.progress(0, "reading " + file.getFileName());
        StepNcProgram p = StepNcReader.read(file);
        progress.progress(1, "read " + p.instanceCount() + " instances");
        return p;
    }

    /** The description of a program, without files (the {@code fresa stepnc} command). */
    public static TaskOutcome describe(StepNcProgram p) {
        return new TaskOutcome(0, List.of(), summary(p), List.of());
    }

    /** A workingstep the planner leaves out, and its reason in the planner's words. */
    public record NotPlanned(long instanceId, String id, String reason) {}

    /**
     * The workingsteps the planner (default choices) leaves out, in program order, each with the
     * reason it gives: what {@code fresa toolpath} would refuse, its 3-axis programs included (a
     * workingstep whose tool axis is not +Z needs another setup, {@link
     * ToolpathService#alongMachineZ}; {@code fresa robot} keeps those).
     */
    public static List<NotPlanned> notPlanned(StepNcProgram p) {
        org.fresa.toolpath.ToolpathPlanner.Plan plan =
                ToolpathService.alongMachineZ(org.fresa.toolpath.ToolpathPlanner.plan(
                        p, org.fresa.geom.Tolerance.DEFAULT, org.fresa.toolpath.PlanningChoices.DEFAULT));
        java.util.Set<Long> planned = new java.util.HashSet<>();
        plan.steps().forEach(s -> planned.add(s.workingstepInstanceId()));
        List<NotPlanned> out = new ArrayList<>();
        for (MachiningWorkingstep w : p.workingsteps()) {
            if (!planned.contains(w.instanceId())) {
                out.add(new NotPlanned(
                        w.instanceId(), w.id(), plan.refusals().getOrDefault(w.instanceId(), "not planned")));
            }
        }
        return out;
    }

    /** {@link #describe(StepNcProgram)} with the workingsteps the planner leaves out and why. */
    public static TaskOutcome describe(StepNcProgram p, List<NotPlanned> notPlanned) {
        Map<String, Object> m = summary(p);
        List<Object> np = new ArrayList<>();
        for (NotPlanned n : notPlanned) {
            np.add(leftOut(n.id(), n.instanceId(), n.reason()));
        }
        m.put("not_planned", np);
        return new TaskOutcome(0, List.of(), m, List.of());
    }

    /** A workingstep left out (not in any workplan, or not planned) as the summary lists it. */
    private static Map<String, Object> leftOut(String id, long instanceId, String reason) {
        Map<String, Object> x = new LinkedHashMap<>();
        x.put("id", id);
        x.put("instance", instanceId);
        x.put("reason", reason);
        return x;
    }

    /** A workingstep left out as the prose lists it: "  #12 'WS1': reason". */
    private static void leftOutLine(StringBuilder sb, String id, long instanceId, String reason) {
        sb.append("  #")
                .append(instanceId)
                .append(" '")
                .append(id)
                .append("': ")
                .append(reason)
                .append('\n');
    }

    /** The lines of {@link #prose} for the workingsteps the planner leaves out; empty when none. */
    public static String notPlannedProse(List<NotPlanned> notPlanned) {
        if (notPlanned.isEmpty()) {
            return "";
        }
        StringBuilder sb = new StringBuilder();
        sb.append(notPlanned.size())
                .append(notPlanned.size() == 1 ? " workingstep" : " workingsteps")
                .append(" not planned:\n");
        for (NotPlanned n : notPlanned) {
            leftOutLine(sb, n.id(), n.instanceId(), n.reason());
        }
        return sb.toString();
    }

    /**
     * The job task: reads the job's STEP-NC file and writes {@code summary.json} and
     * {@code description.txt} into the output folder.
     */
    public static TaskOutcome run(Job job, OutputFolder out, ProgressMonitor progress)
            throws CamInputException, IOException {
        JobSettings.StepNcSettings s = JobRunner.require(job.stepnc(), "stepnc", job);
        StepNcProgram p = read(s.file(), progress);
        out.create();
        out.writeString("summary.json", Json.writePretty(summary(p)));
        out.writeString("description.txt", prose(p));
        return new TaskOutcome(0, List.of(), summary(p), out.written());
    }

    /** The JSON summary: spec/cli.md's fields first, then the reader's reports. */
    public static Map<String, Object> summary(StepNcProgram p) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("schema", p.schema());
        m.put("instances", p.instanceCount());
        m.put("project", p.projectId());
        List<Object> ws = new ArrayList<>();
        for (MachiningWorkingstep w : p.workingsteps()) {
            ws.add(workingstep(w));
        }
        m.put("workingsteps", ws);
        List<Object> skipped = new ArrayList<>();
        for (StepNcProgram.Skipped s : p.skipped()) {
            skipped.add(leftOut(s.id(), s.instanceId(), s.reason()));
        }
        m.put("skipped", skipped);
        m.put("dialect", p.dialect().name());
        m.put("form", p.form());
        m.put("workplans", p.mainWorkplan().map(StepNcService::workplan).orElse(null));
        List<Object> wps = new ArrayList<>();
        for (Workpiece w : p.workpieces()) {
            Map<String, Object> x = new LinkedHashMap<>();
            x.put("id", w.id());
            w.material().ifPresent(mat -> x.put("material", mat));
            w.block().ifPresent(b -> {
                x.put("block", new double[] {b.xMm(), b.yMm(), b.zMm()});
                x.put("block_placement", vec(b.placement().translationPart()));
            });
            wps.add(x);
        }
        m.put("workpieces", wps);
        m.put("unknown_entities", new LinkedHashMap<>(p.unknownEntities()));
        m.put("spellings", p.spellings());
        m.put("warnings", p.warnings());
        return m;
    }

    private static Map<String, Object> workplan(Workplan w) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("id", w.id());
        m.put("instance", w.instanceId());
        w.setup().ifPresent(s -> m.put("setup", s.id()));
        List<Object> elements = new ArrayList<>();
        for (Executable e : w.elements()) {
            if (e instanceof Workplan sub) {
                elements.add(workplan(sub));
            } else if (e instanceof MachiningWorkingstep ws) {
                elements.add("#" + ws.instanceId());
            } else if (e instanceof Executable.Other o) {
                elements.add("#" + o.instanceId() + " " + o.entity());
            }
        }
        m.put("elements", elements);
        return m;
    }

    private static Map<String, Object> workingstep(MachiningWorkingstep w) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("id", w.id());
        m.put("instance", w.instanceId());
        Feature f = w.feature();
        Map<String, Object> fm = new LinkedHashMap<>();
        fm.put("type", f.entity());
        fm.put("id", f.id());
        fm.put("instance", f.instanceId());
        fm.put("placement", vec(f.location()));
        fm.put("axis", vec(f.axis()));
        fm.put("ref_direction", vec(f.placement().xAxis()));
        putIf(fm, "depth", f.depthMm());
        putIf(fm, "diameter", f.diameterMm());
        f.bottomCondition().ifPresent(b -> fm.put("bottom", b));
        putIf(fm, "orthogonal_radius", f.orthogonalRadiusMm());
        putIf(fm, "planar_radius", f.planarRadiusMm());
        f.profile().ifPresent(p -> fm.put("profile", profile(p)));
        if (!f.slotEnds().isEmpty()) {
            List<Object> ends = new ArrayList<>();
            for (org.fresa.stepnc.Feature.SlotEnd e : f.slotEnds()) {
                Map<String, Object> em = new LinkedHashMap<>();
                em.put("type", e.entity());
                putIf(em, "radius1", e.firstRadiusMm());
                putIf(em, "radius2", e.secondRadiusMm());
                ends.add(em);
            }
            fm.put("ends", ends);
        }
        m.put("feature", fm);
        Operation o = w.operation();
        Map<String, Object> om = new LinkedHashMap<>();
        om.put("type", o.entity());
        om.put("id", o.id());
        om.put("instance", o.instanceId());
        o.strategy().ifPresent(s -> {
            om.put(
                    "strategy",
                    s.type() == org.fresa.stepnc.Strategy.StrategyType.OTHER
                            ? s.entity()
                            : s.type().name());
            om.put("strategy_entity", s.entity());
            putIf(om, "overlap", s.overlap());
            putIf(om, "overlap_fraction", s.overlapFraction());
            s.overlapInterpretation().ifPresent(x -> om.put("overlap_read_as", x));
            s.rotationDirection().ifPresent(x -> om.put("rotation", x));
            s.cutmode().ifPresent(x -> om.put("cutmode", x));
        });
        o.tool().ifPresent(t -> om.put("tool", tool(t)));
        var tech = o.technology();
        putIf(om, "feedrate", tech.feedrate());
        om.put("feedrate_unit", tech.feedrateUnit());
        putIf(om, "feed_mm_per_min", tech.feedMmPerMin());
        putIf(om, "spindle", tech.spindle());
        om.put("spindle_unit", tech.spindleUnit());
        putIf(om, "spindle_rpm", tech.spindleRpm());
        putIf(om, "cutspeed", tech.cutSpeed());
        om.put("cutspeed_unit", tech.cutSpeedUnit());
        putIf(om, "retract_plane", o.retractPlaneMm());
        o.startPoint().ifPresent(sp -> om.put("start_point", vec(sp)));
        putIf(om, "axial_cutting_depth", o.axialCuttingDepthMm());
        putIf(om, "radial_cutting_depth", o.radialCuttingDepthMm());
        putIf(om, "allowance_side", o.allowanceSideMm());
        putIf(om, "allowance_bottom", o.allowanceBottomMm());
        putIf(om, "cutting_depth", o.cuttingDepthMm());
        o.approach().ifPresent(a -> om.put("approach", a.entity()));
        o.retract().ifPresent(a -> om.put("retract", a.entity()));
        m.put("operation", om);
        w.setup().ifPresent(s -> m.put("setup", s.id()));
        return m;
    }

    private static Map<String, Object> tool(Tool t) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("type", t.body());
        m.put("id", t.id());
        putIf(m, "diameter", t.diameterMm());
        putIf(m, "edge_radius", t.edgeRadiusMm());
        putIf(m, "cutting_edge_length", t.cuttingEdgeLengthMm());
        putIf(m, "overall_assembly_length", t.overallAssemblyLengthMm());
        putIf(m, "tool_offset_length", t.toolOffsetLengthMm());
        t.teeth().ifPresent(n -> m.put("teeth", n));
        return m;
    }

    private static Map<String, Object> profile(Profile p) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("type", p.entity());
        if (p instanceof Profile.Rectangular r) {
            m.put("width", r.widthMm());
            m.put("length", r.lengthMm());
        } else if (p instanceof Profile.Circular c) {
            m.put("diameter", c.diameterMm());
        } else if (p instanceof Profile.Ngon n) {
            m.put("diameter", n.diameterMm());
            m.put("sides", n.sides());
            m.put("circumscribed", n.circumscribed());
        } else if (p instanceof Profile.Linear l) {
            m.put("length", l.lengthMm());
        } else if (p instanceof Profile.U u) {
            m.put("width", u.widthMm());
        } else if (p instanceof Profile.Vee v) {
            putIf(m, "radius", v.profileRadiusMm());
            m.put("angle_deg", v.profileAngleDeg());
            m.put("tilt_deg", v.tiltAngleDeg());
        } else if (p instanceof Profile.Tee t) {
            m.put("width", t.widthMm());
            m.put("cross_bar_width", t.crossBarWidthMm());
            m.put("cross_bar_depth", t.crossBarDepthMm());
            putIf(m, "radius", t.radiusMm());
            m.put("first_angle_deg", t.firstAngleDeg());
            m.put("second_angle_deg", t.secondAngleDeg());
        } else if (p instanceof Profile.PartialCircular pc) {
            m.put("radius", pc.radiusMm());
            m.put("sweep_angle_deg", pc.sweepAngleDeg());
        } else if (p instanceof Profile.General g) {
            m.put("curve", g.curveEntity());
            m.put("segments", g.segments().size());
            m.put("closed", g.closed());
        }
        if (!p.placement().equals(Transform3.IDENTITY)) {
            m.put("placement", vec(p.placement().translationPart()));
        }
        return m;
    }

    private static void putIf(Map<String, Object> m, String key, OptionalDouble v) {
        if (v.isPresent()) {
            m.put(key, v.getAsDouble() + 0.0);
        }
    }

    private static double[] vec(Vec3 v) {
        // + 0.0 turns the files' -0.0 into 0.0
        return new double[] {v.x() + 0.0, v.y() + 0.0, v.z() + 0.0};
    }

    /** A description for people: the {@code fresa stepnc} output without {@code --json}. */
    public static String prose(StepNcProgram p) {
        StringBuilder sb = new StringBuilder();
        sb.append(p.source())
                .append(": ")
                .append(p.schema().isEmpty() ? "no schema" : p.schema())
                .append(", ")
                .append(p.instanceCount())
                .append(" instances (")
                .append(
                        switch (p.dialect()) {
                            case ISO_14649 -> "ISO 14649 units";
                            case STEP_MODELER -> "STEP Modeler units";
                            case AP238_AIM -> "AP238 AIM; every value converted from its own unit to mm, mm/min, rpm";
                        })
                .append(")\n");
        sb.append("project '").append(p.projectId()).append("'\n");
        for (Workpiece w : p.workpieces()) {
            sb.append("workpiece '").append(w.id()).append('\'');
            w.material().ifPresent(mat -> sb.append(", material ").append(mat));
            w.block()
                    .ifPresent(b -> sb.append(", block ")
                            .append(n(b.xMm()))
                            .append(" x ")
                            .append(n(b.yMm()))
                            .append(" x ")
                            .append(n(b.zMm()))
                            .append(" mm at ")
                            .append(v(b.placement().translationPart())));
            sb.append('\n');
        }
        int[] counter = {0};
        p.mainWorkplan().ifPresent(w -> workplanProse(sb, w, "", counter));
        if (!p.skipped().isEmpty()) {
            sb.append(p.skipped().size()).append(" workingsteps skipped:\n");
            for (StepNcProgram.Skipped s : p.skipped()) {
                leftOutLine(sb, s.id(), s.instanceId(), s.reason());
            }
        }
        if (!p.unknownEntities().isEmpty()) {
            sb.append("entities kept raw (not interpreted): ");
            List<String> parts = new ArrayList<>();
            p.unknownEntities().forEach((k, c) -> parts.add(k + " x" + c));
            sb.append(String.join(", ", parts)).append('\n');
        }
        for (String s : p.spellings()) {
            sb.append("seen: ").append(s).append('\n');
        }
        for (String s : p.warnings()) {
            sb.append("warning: ").append(s).append('\n');
        }
        return sb.toString();
    }

    private static void workplanProse(StringBuilder sb, Workplan w, String indent, int[] counter) {
        sb.append(indent).append("workplan '").append(w.id()).append('\'');
        w.setup().ifPresent(s -> sb.append(" (setup '").append(s.id()).append("')"));
        sb.append('\n');
        for (Executable e : w.elements()) {
            if (e instanceof Workplan sub) {
                workplanProse(sb, sub, indent + "  ", counter);
            } else if (e instanceof MachiningWorkingstep ws) {
                counter[0]++;
                sb.append(indent)
                        .append("  ")
                        .append(counter[0])
                        .append(". ")
                        .append(line(ws))
                        .append('\n');
            } else if (e instanceof Executable.Other o) {
                sb.append(indent)
                        .append("  - #")
                        .append(o.instanceId())
                        .append(' ')
                        .append(o.entity())
                        .append(" (not interpreted)\n");
            }
        }
    }

    private static String line(MachiningWorkingstep ws) {
        Feature f = ws.feature();
        Operation o = ws.operation();
        StringBuilder sb = new StringBuilder();
        sb.append('#')
                .append(ws.instanceId())
                .append(" '")
                .append(ws.id())
                .append("': ")
                .append(o.entity());
        o.strategy().ifPresent(s -> sb.append(" (").append(s.entity()).append(')'));
        sb.append(" on ")
                .append(f.entity())
                .append(" '")
                .append(f.id())
                .append("' at ")
                .append(v(f.location()))
                .append(" axis ")
                .append(v(f.axis()));
        f.depthMm().ifPresent(d -> sb.append(", depth ").append(n(d)).append(" mm"));
        f.diameterMm().ifPresent(d -> sb.append(", diameter ").append(n(d)).append(" mm"));
        f.profile().ifPresent(pr -> {
            if (pr instanceof Profile.Rectangular r) {
                sb.append(", ")
                        .append(n(r.lengthMm()))
                        .append(" x ")
                        .append(n(r.widthMm()))
                        .append(" mm");
            }
        });
        o.tool().ifPresent(t -> {
            sb.append("; tool '").append(t.id()).append("' ").append(t.body());
            t.diameterMm().ifPresent(d -> sb.append(" D").append(n(d)).append(" mm"));
        });
        var tech = o.technology();
        tech.feedrate()
                .ifPresent(fd -> sb.append("; feed ")
                        .append(n(fd))
                        .append(' ')
                        .append(tech.feedrateUnit().equals("unstated") ? "(unit not stated)" : tech.feedrateUnit()));
        tech.spindleRpm().ifPresent(s -> sb.append(", spindle ").append(n(s)).append(" rpm"));
        return sb.toString();
    }

    private static String n(double d) {
        return ExactDecimal.of(Math.round(d * 1e4) / 1e4 + 0.0);
    }

    private static String v(Vec3 p) {
        return "(" + n(p.x()) + ", " + n(p.y()) + ", " + n(p.z()) + ")";
    }
}
