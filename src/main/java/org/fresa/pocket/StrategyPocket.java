package org.fresa.pocket;

import java.util.List;
import org.fresa.geom.Contour;
import org.fresa.geom.Tolerance;
import org.fresa.model.Toolpath;

/**
 * A pocket planned by a {@link PocketStrategy} other than the thesis's own passes: zigzag lines
 * ({@link ZigzagPocket}), walks at a constant engagement ({@link AdaptivePocket}), or offset passes ({@link RegionPocket}) with stock left or cut from the
 * outside in. Stock to leave: the region is offset inwards by it (walls and islands that much
 * nearer) and the floor raised by it, so that every pass keeps it from what it finishes later.
 * A rest tool: a second section, T2, that cuts only what the first tool left and it can reach
 * ({@link RestMachining}), in the same region with the same stock. Units mm.
 */
public final class StrategyPocket {

    private StrategyPocket() {}

    /**
     * The toolpath.
     *
     * @param outer the outer contour (either orientation)
     * @param islands closed contours inside it (either orientation), not touching it or each other
     * @param tech the technology; its floor is the finished floor
     * @param strategy the pattern, stock and order
     * @param climb climb milling of the contour passes
     * @param entry the entries allowed
     * @throws IllegalArgumentException when the stock is as deep as the pocket
     * @throws ToolTooLargeException when the walls less the stock leave no room, the tool does not
     *     fit, an entry has no room, or the program would have too many moves
     */
    public static Toolpath toolpath(
            Contour outer,
            List<Contour> islands,
            PocketTechnology tech,
            PocketStrategy strategy,
            boolean climb,
            EntryRule entry)
            throws ToolTooLargeException {
        return plan(outer, islands, tech, strategy, climb, entry).toolpath();
    }

    /**
     * A planned pocket.
     *
     * @param toolpath the first tool's section, then the rest tool's when it has something to cut
     * @param rest the rest tool's plan, empty without a rest tool
     * @param passes the first tool's cuts at one depth: the offset loops, or the zigzag's chains of
     *     lines and its contour passes, or the adaptive walks' chains and the contour passes
     * @param slowed for adaptive clearing, the moves fed slower where the geometry forces a wider
     *     cut; empty for the other strategies
     */
    public record Planned(
            Toolpath toolpath,
            java.util.Optional<RestMachining.Plan> rest,
            int passes,
            java.util.Optional<EngagementFeed.Slowed> slowed) {}

    /**
     * Plans the pocket as {@link #toolpath}, the rest tool too.
     *
     * @throws IllegalArgumentException as {@link #toolpath}, or for a rest tool not smaller than the
     *     first as {@link PocketStrategy#restToolFits} asks
     * @throws ToolTooLargeException as {@link #toolpath}, or where the rest tool cannot go down or
     *     both tools leave material it could reach
     */
    public static Planned plan(
            Contour outer,
            List<Contour> islands,
            PocketTechnology tech,
            PocketStrategy strategy,
            boolean climb,
            EntryRule entry)
            throws ToolTooLargeException {
        return plan(outer, islands, tech, strategy, climb, entry, f -> {});
    }

    /**
     * As {@link #plan(Contour, List, PocketTechnology, PocketStrategy, boolean, EntryRule)}, telling
     * how far adaptive clearing's walks are.
     *
     * @param progress told the fraction (0 to 1) of the floor adaptive clearing's walks have
     *     cleared; the other strategies plan in a moment and tell nothing
     */
    public static Planned plan(
            Contour outer,
            List<Contour> islands,
            PocketTechnology tech,
            PocketStrategy strategy,
            boolean climb,
            EntryRule entry,
            java.util.function.DoubleConsumer progress)
            throws ToolTooLargeException {
        if (strategy.restTool() && !PocketStrategy.restToolFits(strategy.restToolDiameterMm(), tech.toolDiameterMm())) {
            throw new IllegalArgumentException("the rest tool (" + strategy.restToolDiameterMm()
                    + " mm) must be at least " + PocketStrategy.MIN_REST_TOOL_MM + " mm and smaller than the first ("
                    + tech.toolDiameterMm() + " mm) by more than " + PocketStrategy.REST_TOOL_MARGIN_MM + " mm");
        }
        double stock = strategy.stockToLeaveMm();
        List<Contour> boundary = RegionOffsetter.oriented(outer, islands);
        PocketTechnology t = tech;
        if (stock > 0) {
            if (!(tech.zBottomMm() + stock < tech.zTopMm())) {
                throw new IllegalArgumentException(stock + " mm of stock is as much as the pocket's depth ("
                        + (tech.zTopMm() - tech.zBottomMm()) + " mm): nothing would be cut");
            }
            t = new PocketTechnology(
                    tech.toolDiameterMm(),
                    tech.cutFraction(),
                    tech.finishFraction(),
                    tech.zTopMm(),
                    tech.zBottomMm() + stock,
                    tech.maxDepthMm(),
                    tech.spindleRpm(),
                    tech.feedMmPerMin(),
                    tech.finishFeedMmPerMin());
            boundary = RegionOffsetter.inward(boundary, stock, Tolerance.DEFAULT);
            if (boundary.isEmpty()) {
                throw new ToolTooLargeException(
                        "the walls less " + stock + " mm of stock leave no room for the pocket: leave less stock");
            }
        }
        Toolpath first;
        int passes;
        java.util.Optional<EngagementFeed.Slowed> slowed = java.util.Optional.empty();
        if (strategy.adaptive()) {
            AdaptivePocket.Plan a = AdaptivePocket.plan(boundary, t, climb, entry, progress);
            first = a.toolpath();
            passes = a.order().size();
            slowed = java.util.Optional.of(a.slowed());
        } else if (strategy.zigzag()) {
            ZigzagPocket.Plan z = ZigzagPocket.plan(boundary, t, strategy.angleDeg(), climb, entry);
            first = z.toolpath();
            passes = z.order().size();
        } else {
            RegionPocket.Plan r = RegionPocket.plan(
                    boundary, t, climb, entry, true, strategy.order() == PocketStrategy.Order.OUTSIDE_IN);
            first = r.toolpath();
            passes = r.order().size();
        }
        if (!strategy.restTool()) {
            return new Planned(first, java.util.Optional.empty(), passes, slowed);
        }
        RestMachining.Plan rest = RestMachining.plan(
                boundary,
                first,
                t.radiusMm(),
                RestMachining.technology(t, strategy.restToolDiameterMm()),
                climb,
                entry);
        if (rest.section().isEmpty()) {
            return new Planned(first, java.util.Optional.of(rest), passes, slowed);
        }
        List<org.fresa.model.ToolpathSection> sections = new java.util.ArrayList<>(first.sections());
        sections.add(rest.section().get());
        return new Planned(new Toolpath(sections), java.util.Optional.of(rest), passes, slowed);
    }
}
