package org.fresa.toolpath;

import java.util.Objects;
import org.fresa.geom.Vec2;

/**
 * How a pocket (or any closed profile) is cleared.
 *
 * @param strategy the pass pattern
 * @param stepoverMm nominal distance between passes ({@link Stepover#nominal} or the radial
 *     depth); loops are further limited by the corner rule
 * @param axialDepthMm depth of each layer; 0 or less for one layer at full depth
 * @param sideAllowanceMm material left on the walls, >= 0
 * @param bottomAllowanceMm material left on the floor, >= 0
 * @param feedDirection direction of parallel passes in the feature plane
 * @param clockwise loop sense seen from the tool (+Z of the feature): with an M3 spindle,
 *     counter-clockwise loops climb-mill a pocket's walls, clockwise ones mill them conventionally
 * @param approach how each layer is entered
 * @param finishPass after roughing with allowances, run the pattern once more at full depth
 * @param entry the entry the user asks for ({@link PlanningChoices#entry()}), with the approach
 *     giving the kind where it is {@code auto} ({@link PocketMilling#rule})
 *     without allowances
 */
public record MillingPlan(
        Strategy strategy,
        double stepoverMm,
        double axialDepthMm,
        double sideAllowanceMm,
        double bottomAllowanceMm,
        Vec2 feedDirection,
        boolean clockwise,
        Approach approach,
        boolean finishPass,
        org.fresa.pocket.EntryRule entry) {

    /** A plan entered as the file's approach allows, at the default entry angle ({@link org.fresa.pocket.EntryRule#DEFAULT}). */
    public MillingPlan(
            Strategy strategy,
            double stepoverMm,
            double axialDepthMm,
            double sideAllowanceMm,
            double bottomAllowanceMm,
            Vec2 feedDirection,
            boolean clockwise,
            Approach approach,
            boolean finishPass) {
        this(
                strategy,
                stepoverMm,
                axialDepthMm,
                sideAllowanceMm,
                bottomAllowanceMm,
                feedDirection,
                clockwise,
                approach,
                finishPass,
                org.fresa.pocket.EntryRule.DEFAULT);
    }

    public MillingPlan {
        Objects.requireNonNull(strategy, "strategy");
        Objects.requireNonNull(entry, "entry");
        Objects.requireNonNull(feedDirection, "feedDirection");
        Objects.requireNonNull(approach, "approach");
        if (!(stepoverMm > 0) || sideAllowanceMm < 0 || bottomAllowanceMm < 0) {
            throw new IllegalArgumentException(
                    "bad plan: stepover " + stepoverMm + ", allowances " + sideAllowanceMm + "/" + bottomAllowanceMm);
        }
    }

    /** A plan with plunges, no allowances, passes along +x, counter-clockwise loops. */
    public static MillingPlan simple(Strategy strategy, double stepoverMm, double axialDepthMm) {
        return new MillingPlan(
                strategy, stepoverMm, axialDepthMm, 0, 0, Vec2.UNIT_X, false, new Approach.Plunge(), false);
    }

    public MillingPlan withApproach(Approach a) {
        return withEntering(feedDirection, clockwise, a, entry);
    }

    public MillingPlan withAllowances(double side, double bottom, boolean finish) {
        return new MillingPlan(
                strategy, stepoverMm, axialDepthMm, side, bottom, feedDirection, clockwise, approach, finish, entry);
    }

    public MillingPlan withDirection(Vec2 feed, boolean cw) {
        return withEntering(feed, cw, approach, entry);
    }

    /** The same plan entered as the user asks ({@link PlanningChoices#entry()}). */
    public MillingPlan withEntry(org.fresa.pocket.EntryRule e) {
        return withEntering(feedDirection, clockwise, approach, e);
    }

    /** The same pattern, depths and allowances, run in this direction and sense and entered so. */
    private MillingPlan withEntering(Vec2 feed, boolean cw, Approach a, org.fresa.pocket.EntryRule e) {
        return new MillingPlan(
                strategy, stepoverMm, axialDepthMm, sideAllowanceMm, bottomAllowanceMm, feed, cw, a, finishPass, e);
    }
}
