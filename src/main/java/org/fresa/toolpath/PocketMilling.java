package org.fresa.toolpath;

import java.util.List;
import java.util.Optional;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.ToolpathSection;

/**
 * A closed pocket cleared layer by layer (thesis section 3.2.2.2), in the feature frame: the
 * profile in the XY plane, the tool along +Z, material from {@code topZ} down to
 * {@code bottomZ}.
 *
 * <p>Each layer repeats the strategy's passes ({@link PlanarPasses}). A pass that cannot be
 * joined at depth is reached by lifting just above the previous layer (1 mm, or less under the
 * retract height), traversing, and entering again with the plan's approach. The section starts
 * and ends at the clearance height above the first pass.
 */
public final class PocketMilling {

    /** Height above the last cut layer where the tool may traverse within the pocket (mm). */
    static final double LIFT_MM = 1.0;

    private PocketMilling() {
    }

    /** The stepover used between loops: the nominal one limited by D and the corner rule. */
    public static double loopStepover(Profile profile, Tooling tool, MillingPlan plan) {
        double wall = tool.radiusMm() + plan.sideAllowanceMm();
        return Stepover.forLoops(plan.stepoverMm(), tool.diameterMm(), profile.sharpCornerAngleRad(wall));
    }

    /**
     * @throws IllegalArgumentException when the tool does not fit in the profile
     */
    public static ToolpathSection section(String label, Profile profile, Heights h, Tooling tool, MillingPlan plan,
            Tolerance tol) {
        double r = tool.radiusMm();
        double d = switch (plan.strategy()) {
            case UNIDIRECTIONAL, BIDIRECTIONAL -> Math.min(plan.stepoverMm(), tool.diameterMm());
            default -> loopStepover(profile, tool, plan);
        };
        double wall = r + plan.sideAllowanceMm();
        double floor = h.bottomZ() + plan.bottomAllowanceMm();
        List<Pass> passes = PlanarPasses.of(plan.strategy(), profile, wall, d, plan.feedDirection(), plan.clockwise(), tol);
        Ring region = profile.inset(wall, tol).orElseThrow();
        Vec2 first = passes.get(0).start();
        MoveBuilder b = new MoveBuilder(Vec3.of(first, h.clearanceZ()));
        Heights rough = new Heights(h.clearanceZ(), h.retractZ(), h.topZ(), Math.min(h.topZ(), floor));
        double prev = h.topZ();
        for (double z : rough.layers(plan.axialDepthMm())) {
            layer(b, passes, region, z, prev, h, tool, plan, tol);
            prev = z;
        }
        boolean allowances = plan.sideAllowanceMm() > 0 || plan.bottomAllowanceMm() > 0;
        if (plan.finishPass() && allowances) {
            double df = switch (plan.strategy()) {
                case UNIDIRECTIONAL, BIDIRECTIONAL -> Math.min(plan.stepoverMm(), tool.diameterMm());
                default -> Stepover.forLoops(plan.stepoverMm(), tool.diameterMm(), profile.sharpCornerAngleRad(r));
            };
            List<Pass> fin = PlanarPasses.of(plan.strategy(), profile, r, df, plan.feedDirection(), plan.clockwise(), tol);
            Ring finRegion = profile.inset(r, tol).orElseThrow();
            layer(b, fin, finRegion, h.bottomZ(), prev, h, tool, plan, tol);
        }
        b.rapid(new Vec3(b.at().x(), b.at().y(), h.retractZ()));
        b.rapid(new Vec3(b.at().x(), b.at().y(), h.clearanceZ()));
        return new ToolpathSection(label, Vec3.UNIT_Z, tool.diameterMm(), tool.toolNumber(), tool.spindleRpm(),
                Vec3.of(first, h.clearanceZ()), b.moves());
    }

    static void layer(MoveBuilder b, List<Pass> passes, Ring region, double z, double prevZ, Heights h, Tooling tool,
            MillingPlan plan, Tolerance tol) {
        double lift = Math.min(h.retractZ(), prevZ + LIFT_MM);
        for (int i = 0; i < passes.size(); i++) {
            Pass p = passes.get(i);
            if (i > 0 && p.joinAtDepth()) {
                b.feed(Vec3.of(p.start(), z), tool.feedMmPerMin());
            } else {
                b.liftAndTraverse(p.start(), lift);
                enter(b, p, region, z, tool, plan, tol);
            }
            b.curves(p.curves(), z, tool.feedMmPerMin());
        }
        b.rapid(new Vec3(b.at().x(), b.at().y(), lift));
    }

    /** From the tool's height straight above the pass start down to z, by the plan's approach. */
    static void enter(MoveBuilder b, Pass p, Ring region, double z, Tooling tool, MillingPlan plan, Tolerance tol) {
        double top = b.at().z();
        double dz = top - z;
        Vec3 bottom = Vec3.of(p.start(), z);
        if (dz <= 0) {
            b.feed(bottom, tool.plungeFeedMmPerMin());
            return;
        }
        if (plan.approach() instanceof Approach.Ramp ramp && !p.curves().isEmpty()
                && p.curves().get(0) instanceof Segment2 s && s.length() > tol.linear()) {
            double horizontal = dz / Math.tan(Math.toRadians(ramp.angleDeg()));
            int legs = 2 * (int) Math.ceil(horizontal / (2 * s.length()) - 1e-12);
            legs = Math.max(2, legs);
            double leg = Math.min(s.length(), horizontal / legs);
            Vec2 far = p.start().plus(s.direction().normalized().times(leg));
            for (int k = 1; k <= legs; k++) {
                Vec2 xy = k % 2 == 1 ? far : p.start();
                b.feed(Vec3.of(xy, top - dz * k / legs), tool.plungeFeedMmPerMin());
            }
            return;
        }
        if (plan.approach() instanceof Approach.Helix helix) {
            Optional<Vec2> centre = helixCentre(p, region, helix.radiusMm(), tol);
            if (centre.isPresent()) {
                double pitch = 2 * Math.PI * helix.radiusMm() * Math.tan(Math.toRadians(helix.angleDeg()));
                int turns = Math.max(1, (int) Math.ceil(dz / pitch - 1e-12));
                b.arc(bottom, Vec3.of(centre.get(), top), !plan.clockwise(), turns - 1, tool.plungeFeedMmPerMin());
                return;
            }
        }
        b.feed(bottom, tool.plungeFeedMmPerMin());
    }

    private static Optional<Vec2> helixCentre(Pass p, Ring region, double rh, Tolerance tol) {
        if (region.curves().size() < 2) {
            return Optional.empty();
        }
        Contour c = new Contour(region.curves());
        Vec2 dir = p.curves().isEmpty() ? Vec2.UNIT_X : firstDirection(p.curves().get(0));
        for (Vec2 d : List.of(dir, dir.leftNormal(), dir.negated(), dir.leftNormal().negated())) {
            Vec2 centre = p.start().plus(d.times(rh));
            if (c.distanceTo(centre) >= rh - tol.linear() && c.windingNumber(centre) != 0) {
                return Optional.of(centre);
            }
        }
        return Optional.empty();
    }

    private static Vec2 firstDirection(Curve2 c) {
        try {
            return c.startTangent();
        } catch (IllegalArgumentException e) {
            return Vec2.UNIT_X;
        }
    }
}
