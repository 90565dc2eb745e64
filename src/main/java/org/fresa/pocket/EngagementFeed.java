package org.fresa.pocket;

import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;
import org.fresa.model.ToolpathSection;

/**
 * The feed of an adaptive program where its walks cannot hold the engagement: a face of the
 * offset too small for an entry, a channel narrower than the tool's centre can turn in, or a
 * narrow end that only the contour passes reach, are cut wider than the stepover, up to a slot.
 * There the feed drops so that the tool removes no more material per minute than a straight cut
 * of the bound's width (1.1 times the stepover) at the programmed feed: a cut of width w is fed at
 * F 1.1 s / w, a slot at F 1.1 s / D. The engagement is measured from the program's own moves by
 * {@link Engagement} (the first depth layer: every layer meets the same floor), and the factor is
 * kept per curve of the plan, so that every layer's move made for that curve is slowed alike.
 *
 * @param factors for each curve of the plan (or the cut whose link led to it) whose move engages
 *     more than the bound, the fraction of its feed it is written with
 * @param slowed what the factors amount to
 */
public record EngagementFeed(Map<Object, Double> factors, Slowed slowed) {

    /** The slowest a move is fed, as a fraction of its feed: a slot of the least stepover. */
    static final double LEAST_FACTOR = 0.05;

    /**
     * The moves slowed at each depth layer.
     *
     * @param moves how many curves of the plan are fed slower (each layer alike)
     * @param lengthMm their length at one layer
     * @param worstDeg the largest engagement measured
     * @param worstAt where it was measured
     * @param boundDeg the engagement above which the feed drops
     * @param lowestFactor the smallest fraction of the feed written
     */
    public record Slowed(
            int moves, double lengthMm, double worstDeg, Vec2 worstAt, double boundDeg, double lowestFactor) {
        /** Whether any move is slowed. */
        public boolean any() {
            return moves > 0;
        }
    }

    /**
     * Measures the section's first layer and finds the factors.
     *
     * @param boundary the pocket's walls and islands
     * @param tech the technology (tool radius, finishing feed)
     * @param stepoverMm the stepover the walks hold
     * @param section the program as first planned, every feed as programmed
     * @param owners for each of the first layer's moves, the curve (or the cut of a link) it was
     *     made for, null for rapids and entries
     */
    static EngagementFeed of(
            List<Contour> boundary,
            PocketTechnology tech,
            double stepoverMm,
            ToolpathSection section,
            List<Object> owners) {
        double r = tech.radiusMm();
        double boundWidthMm = 1.1 * stepoverMm;
        double boundDeg = Engagement.angleDeg(boundWidthMm, r);
        Map<Object, Double> factors = new IdentityHashMap<>();
        double[] worst = {0};
        Vec2[] worstAt = {null};
        Engagement.of(
                boundary,
                r,
                section.start(),
                section.moves().subList(0, owners.size()),
                tech.finishFeedMmPerMin(),
                (mi, p, deg) -> {
                    if (deg > worst[0]) {
                        worst[0] = deg;
                        worstAt[0] = p;
                    }
                    Object owner = owners.get(mi);
                    if (deg <= boundDeg || owner == null) {
                        return;
                    }
                    double f = Math.max(LEAST_FACTOR, Math.min(1, boundWidthMm / Engagement.widthMm(deg, r)));
                    factors.merge(owner, f, Math::min);
                });
        double length = 0;
        double lowest = 1;
        for (Map.Entry<Object, Double> e : factors.entrySet()) {
            if (e.getKey() instanceof Curve2 c) {
                length += c.length();
            }
            lowest = Math.min(lowest, e.getValue());
        }
        return new EngagementFeed(factors, new Slowed(factors.size(), length, worst[0], worstAt[0], boundDeg, lowest));
    }

    public EngagementFeed {
        // by identity: two cuts may hold equal curves, each judged where it is cut
        factors = java.util.Collections.unmodifiableMap(new IdentityHashMap<>(factors));
    }

    /** The feed a move is written with: the programmed one times its factor, in whole mm/min, at least 1. */
    static double feed(double feedMmPerMin, Double factor) {
        if (factor == null || factor >= 1) {
            return feedMmPerMin;
        }
        return Math.max(1, Math.floor(feedMmPerMin * factor));
    }
}
