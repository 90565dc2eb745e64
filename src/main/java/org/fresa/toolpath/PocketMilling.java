package org.fresa.toolpath;

import java.util.List;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.ToolpathSection;
import org.fresa.pocket.Entries;
import org.fresa.pocket.Entry;
import org.fresa.pocket.EntryRule;

/**
 * A closed pocket cleared layer by layer (thesis section 3.2.2.2), in the feature frame: the
 * profile in the XY plane, the tool along +Z, material from {@code topZ} down to
 * {@code bottomZ}.
 *
 * <p>Each layer repeats the strategy's passes ({@link PlanarPasses}). A pass that cannot be
 * joined at depth is reached by lifting just above the previous layer (1 mm, or less under the
 * retract height), traversing, and entering again within the entry angle ({@link #enter}). The section starts
 * and ends at the clearance height above the first pass.
 */
public final class PocketMilling {

    /** Height above the last cut layer where the tool may traverse within the pocket (mm). */
    static final double LIFT_MM = 1.0;

    private PocketMilling() {}

    /** The stepover used between loops: the nominal one limited by D and the corner rule. */
    public static double loopStepover(Profile profile, Tooling tool, MillingPlan plan) {
        double wall = tool.radiusMm() + plan.sideAllowanceMm();
        return Stepover.forLoops(plan.stepoverMm(), tool.diameterMm(), profile.sharpCornerAngleRad(wall));
    }

    /**
     * @throws IllegalArgumentException when the tool does not fit in the profile
     */
    public static ToolpathSection section(
            String label, Profile profile, Heights h, Tooling tool, MillingPlan plan, Tolerance tol) {
        double r = tool.radiusMm();
        double d = switch (plan.strategy()) {
            case UNIDIRECTIONAL, BIDIRECTIONAL -> Math.min(plan.stepoverMm(), tool.diameterMm());
            default -> loopStepover(profile, tool, plan);
        };
        double wall = r + plan.sideAllowanceMm();
        double floor = h.bottomZ() + plan.bottomAllowanceMm();
        List<Pass> passes =
                PlanarPasses.of(plan.strategy(), profile, wall, d, plan.feedDirection(), plan.clockwise(), tol);
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
            List<Pass> fin =
                    PlanarPasses.of(plan.strategy(), profile, r, df, plan.feedDirection(), plan.clockwise(), tol);
            Ring finRegion = profile.inset(r, tol).orElseThrow();
            layer(b, fin, finRegion, h.bottomZ(), prev, h, tool, plan, tol);
        }
        b.rapid(new Vec3(b.at().x(), b.at().y(), h.retractZ()));
        b.rapid(new Vec3(b.at().x(), b.at().y(), h.clearanceZ()));
        return tool.section(label, Vec3.of(first, h.clearanceZ()), b.moves());
    }

    static void layer(
            MoveBuilder b,
            List<Pass> passes,
            Ring region,
            double z,
            double prevZ,
            Heights h,
            Tooling tool,
            MillingPlan plan,
            Tolerance tol) {
        double lift = Math.min(h.retractZ(), prevZ + LIFT_MM);
        for (int i = 0; i < passes.size(); i++) {
            Pass p = passes.get(i);
            if (i > 0 && p.joinAtDepth()) {
                b.feed(Vec3.of(p.start(), z), tool.feedMmPerMin());
            } else {
                b.liftAndTraverse(p.start(), lift);
                enter(b, p, ahead(passes, i), region, z, tool, plan, tol);
            }
            b.curves(p.curves(), z, tool.feedMmPerMin());
        }
        b.rapid(new Vec3(b.at().x(), b.at().y(), lift));
    }

    /**
     * From the tool's height straight above the pass start (the lift height, just above the
     * material) down to z by the entry the plan's approach and the entry angle allow ({@link #rule}, {@link Entries}): a helix inside the tool-centre region,
     * else a zig-zag ramp along the pass.
     *
     * @param ahead the path the tool follows at depth from the pass start ({@link #ahead})
     * @throws IllegalArgumentException when there is room for neither (the workingstep is refused)
     */
    static void enter(
            MoveBuilder b,
            Pass p,
            List<Curve2> ahead,
            Ring region,
            double z,
            Tooling tool,
            MillingPlan plan,
            Tolerance tol) {
        Vec3 bottom = Vec3.of(p.start(), z);
        // from the lift height just above the material: no straight feed down, even through the air
        double top = b.at().z();
        if (top <= z) {
            b.feed(bottom, tool.plungeFeedMmPerMin());
            return;
        }
        EntryRule rule = rule(plan.approach(), plan.entry());
        Contour boundary = new Contour(region.curves());
        Entries.Room room =
                (centre, r) -> boundary.distanceTo(centre) >= r - tol.linear() && boundary.windingNumber(centre) != 0;
        Entry entry = Entries.choose(rule, p.start(), ahead, !plan.clockwise(), room, tool.radiusMm(), top - z)
                .orElse(null);
        if (entry == null) {
            throw new IllegalArgumentException(String.format(
                    java.util.Locale.ROOT,
                    "no room for a helix or a ramp no steeper than %.1f deg to enter at X%.3f Y%.3f, and a milling"
                            + " cutter is not taken to cut at its centre",
                    rule.angleDeg(),
                    p.start().x(),
                    p.start().y()));
        }
        b.append(entry.moves(top, z, tool.plungeFeedMmPerMin()));
    }

    /**
     * The path the tool will follow at depth from pass i's start: its curves, then those of the
     * passes joined to it at depth, with the straight links between them (a ramp may run along
     * it: the tool cuts there anyway).
     */
    static List<Curve2> ahead(List<Pass> passes, int i) {
        List<Curve2> out = new java.util.ArrayList<>(passes.get(i).curves());
        Vec2 end = passes.get(i).end();
        for (int j = i + 1; j < passes.size() && passes.get(j).joinAtDepth(); j++) {
            Pass q = passes.get(j);
            if (end.distance(q.start()) > 1e-9) {
                out.add(new Segment2(end, q.start()));
            }
            out.addAll(q.curves());
            end = q.end();
        }
        return out;
    }

    /**
     * The entry rule of a file's approach under the user's: ISO 14649-111 does not say whether a
     * milling cutter cuts at its centre, so none is taken to unless the user says so
     * ({@code --centre-cutting}). A kind asked for other than {@code auto} replaces the file's;
     * with {@code auto} a file's plunge (or no approach) is entered as {@code auto}, its ramp or
     * helix as it says. Never steeper than the user's entry angle (3 degrees by default).
     */
    static EntryRule rule(Approach a, EntryRule asked) {
        double limit = asked.angleDeg();
        if (asked.kind() != EntryRule.Kind.AUTO) {
            return asked;
        }
        if (a instanceof Approach.Ramp r) {
            return new EntryRule(EntryRule.Kind.RAMP, Math.min(r.angleDeg(), limit), asked.centreCutting());
        }
        if (a instanceof Approach.Helix h) {
            return new EntryRule(EntryRule.Kind.HELIX, Math.min(h.angleDeg(), limit), asked.centreCutting());
        }
        return asked;
    }

    /** {@link #rule(Approach, EntryRule)} with the default entries. */
    static EntryRule rule(Approach a) {
        return rule(a, EntryRule.DEFAULT);
    }
}
