package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.stepnc.Feature;
import org.fresa.stepnc.MachiningWorkingstep;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.Workpiece;

/**
 * What a STEP-NC file says of a feature that cannot be what its writer meant, told once per
 * feature so that the planner reading the warnings sees it before the machine does: a feature
 * wholly above its workpiece's block (its workingsteps cut the air over the part), a security
 * plane below a feature's top (the links between workingsteps, which run in the plane, pass
 * through the feature), and a blind hole whose workingsteps all stop short of its depth (the
 * part is left with a shallow hole). The program is still planned as the file says: these are
 * the file's choices, and the program check refuses what would crash.
 */
final class FeatureChecks {

    private FeatureChecks() {}

    /** The warnings for the file's workingsteps, in the order of their features' first workingstep. */
    static List<String> of(StepNcProgram program, Tolerance tol) {
        List<String> out = new ArrayList<>();
        Map<Long, List<MachiningWorkingstep>> byFeature = new LinkedHashMap<>();
        for (MachiningWorkingstep w : program.workingsteps()) {
            byFeature
                    .computeIfAbsent(w.feature().instanceId(), k -> new ArrayList<>())
                    .add(w);
        }
        OptionalDouble blockTop = program.workpieces().size() == 1
                ? program.workpieces()
                        .get(0)
                        .block()
                        .map(FeatureChecks::topZMm)
                        .map(OptionalDouble::of)
                        .orElse(OptionalDouble.empty())
                : OptionalDouble.empty();
        for (List<MachiningWorkingstep> steps : byFeature.values()) {
            Feature f = steps.get(0).feature();
            aboveBlock(f, blockTop, tol).ifPresent(out::add);
            belowSecurityPlane(f, steps, tol).ifPresent(out::add);
            shortHole(f, steps, tol).ifPresent(out::add);
        }
        leftHandTools(program).ifPresent(out::add);
        return out;
    }

    /**
     * The tools written left-hand cutting (ISO 14649-111 hand_of_cut LEFT), told in one line:
     * every program turns the spindle clockwise (M3), as a right-hand cutter cuts, and a left-hand
     * cutter turned so rubs and breaks. Some writers (STEP Modeler) put LEFT on every tool, so the
     * direction is not taken from the file: the shop checks the tools it loads.
     */
    static Optional<String> leftHandTools(StepNcProgram program) {
        // writers repeat one physical tool as an instance per operation: same name, body and size
        Map<String, String> left = new LinkedHashMap<>();
        for (MachiningWorkingstep w : program.workingsteps()) {
            w.operation().tool().ifPresent(t -> {
                if (t.handOfCut().filter(h -> h.equalsIgnoreCase("LEFT")).isPresent()) {
                    String size = t.diameterMm().isPresent()
                            ? " " + ToolpathPlanner.mm(t.diameterMm().getAsDouble()) + " mm"
                            : "";
                    left.putIfAbsent(
                            t.id() + "|" + t.body() + "|" + size,
                            "'" + t.id() + "' (" + (t.body().isEmpty() ? "no body" : t.body()) + size + ")");
                }
            });
        }
        if (left.isEmpty()) {
            return Optional.empty();
        }
        return Optional.of((left.size() == 1 ? "1 tool is" : left.size() + " tools are")
                + " written left-hand cutting (hand_of_cut LEFT): " + String.join(", ", left.values())
                + "; the program turns every tool clockwise (M3), for a right-hand cutter, which is what writers that"
                + " put LEFT on every tool mean: a left-hand cutter loaded would rub and break");
    }

    /** A feature along +Z whose bottom is at or above the block's top. */
    static Optional<String> aboveBlock(Feature f, OptionalDouble blockTopZMm, Tolerance tol) {
        // a feature whose depth lies in its profile (a slot's) states no bottom of its own here
        if (blockTopZMm.isEmpty()
                || f.depthMm().isEmpty()
                || !(f.depthMm().getAsDouble() > tol.linear())
                || !upright(f.placement(), tol)) {
            return Optional.empty();
        }
        double top = f.placement().applyToPoint(Vec3.ZERO).z();
        double bottom = top - f.depthMm().getAsDouble();
        if (bottom < blockTopZMm.getAsDouble() - tol.linear()) {
            return Optional.empty();
        }
        return Optional.of("feature " + name(f) + " lies wholly above the workpiece's block: its bottom is at Z "
                + ToolpathPlanner.mm(bottom) + " mm, the block's top at Z "
                + ToolpathPlanner.mm(blockTopZMm.getAsDouble())
                + " mm, so its workingsteps cut the air; the feature's placement or the block is not what the part is");
    }

    /** The deepest the security plane of any of the feature's workingsteps lies below its top. */
    static Optional<String> belowSecurityPlane(Feature f, List<MachiningWorkingstep> steps, Tolerance tol) {
        double worst = 0;
        Transform3 worstPlane = null;
        for (MachiningWorkingstep w : steps) {
            if (w.securityPlane().isEmpty()) {
                continue;
            }
            Transform3 plane = w.securityPlane().get();
            Vec3 top = w.workpieceToSetup().applyToPoint(f.placement().applyToPoint(Vec3.ZERO));
            double above = top.minus(plane.translationPart()).dot(plane.zAxis());
            if (above > worst + tol.linear()) {
                worst = above;
                worstPlane = plane;
            }
        }
        if (worstPlane == null) {
            return Optional.empty();
        }
        return Optional.of("the top of feature " + name(f) + " is " + ToolpathPlanner.mm(worst)
                + " mm above its workingsteps' security plane (through " + point(worstPlane.translationPart())
                + ", normal " + ToolpathPlanner.axis(worstPlane.zAxis()) + "): the links between workingsteps,"
                + " which run in the plane, pass through the feature");
    }

    /**
     * A blind round hole whose every workingstep is a drilling one with a cutting_depth short of
     * the hole's depth: under either reading of a shaped bottom's depth (to the shoulder, or to the
     * tip) no tool reaches it.
     */
    static Optional<String> shortHole(Feature f, List<MachiningWorkingstep> steps, Tolerance tol) {
        if (f.type() != Feature.FeatureType.ROUND_HOLE
                || ToolpathPlanner.isThrough(f)
                || f.depthMm().isEmpty()) {
            return Optional.empty();
        }
        double depth = f.depthMm().getAsDouble();
        double reached = 0;
        for (MachiningWorkingstep w : steps) {
            if (!w.operation().type().isDrillingType()
                    || w.operation().cuttingDepthMm().isEmpty()) {
                return Optional.empty();
            }
            reached = Math.max(reached, w.operation().cuttingDepthMm().getAsDouble());
        }
        if (reached >= depth - tol.linear()) {
            return Optional.empty();
        }
        return Optional.of("hole " + name(f) + " is " + ToolpathPlanner.mm(depth) + " mm deep, and its workingsteps'"
                + " cutting_depth reaches " + ToolpathPlanner.mm(reached) + " mm at most: the hole is left "
                + ToolpathPlanner.mm(depth - reached) + " mm short, as the file says");
    }

    private static boolean upright(Transform3 t, Tolerance tol) {
        return t.zAxis().distance(Vec3.UNIT_Z) <= tol.angularRad() * 1e3;
    }

    /** The block's highest corner in the workpiece frame. */
    static double topZMm(Workpiece.Block b) {
        double top = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < 8; k++) {
            Vec3 c = b.placement()
                    .applyToPoint(new Vec3((k & 1) * b.xMm(), ((k >> 1) & 1) * b.yMm(), ((k >> 2) & 1) * b.zMm()));
            top = Math.max(top, c.z());
        }
        return top;
    }

    /** A feature by its id and instance, as two features may share an id. */
    private static String name(Feature f) {
        return "'" + f.id() + "' (#" + f.instanceId() + ")";
    }

    private static String point(Vec3 p) {
        return "(" + ToolpathPlanner.mm(p.x()) + ", " + ToolpathPlanner.mm(p.y()) + ", " + ToolpathPlanner.mm(p.z())
                + ")";
    }
}
