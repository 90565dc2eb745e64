package org.fresa.pocket;

import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.model.ToolpathSection;

/**
 * The feed of an adaptive program where its walks cannot hold the engagement: a face of the
 * offset too small for an entry, a channel narrower than the tool's centre can turn in, or a
 * narrow end that only the contour passes reach, are cut wider than the stepover, up to a slot.
 * There the feed drops so that the tool removes no more material per minute than a straight cut
 * of the bound's width (1.1 times the stepover) at the programmed feed: a cut of width w is fed at
 * F 1.1 s / w, a slot at F 1.1 s / D. The engagement is measured from the program's own moves by
 * {@link Engagement} (the first depth layer: every layer meets the same floor). Only the stretch
 * of a line or arc that engages more is slowed, with {@link #MARGIN_MM} either side: a wall's
 * pass that meets a narrow end at its corner keeps its feed along the wall. The stretches are kept
 * per curve of the plan, so that every layer's move made for that curve is slowed alike; arcs
 * stay arcs.
 *
 * @param stretches for each curve of the plan (or the cut whose link led to it) that engages more
 *     than the bound, its stretches fed slower
 * @param slowed what the stretches amount to
 */
public record EngagementFeed(Map<Object, List<Stretch>> stretches, Slowed slowed) {

    /** The slowest a move is fed, as a fraction of its feed: a slot of the least stepover. */
    static final double LEAST_FACTOR = 0.05;

    /**
     * How far (mm) a slowed stretch reaches beyond the first and last samples that engage more than
     * the bound: the measure samples every 0.05 mm at most, and the engagement rises over a few
     * tenths as the tool comes into a corner.
     */
    static final double MARGIN_MM = 0.5;

    /** Stretches of one curve closer than this (mm) are slowed as one: no feed change for a few tenths. */
    static final double JOIN_MM = 2;

    /** No feed and no program at all: nothing is slowed. */
    static final EngagementFeed NONE = new EngagementFeed(Map.of(), new Slowed(0, 0, 0, null, 0, 1));

    /**
     * A stretch of a curve fed slower.
     *
     * @param from where it starts, a fraction of the curve's length
     * @param to where it ends, a fraction of the curve's length
     * @param factor the fraction of the programmed feed
     */
    public record Stretch(double from, double to, double factor) {}

    /** A piece of a curve and the fraction of the programmed feed it is written with. */
    record Piece(Curve2 curve, double factor) {}

    /**
     * The moves slowed at each depth layer.
     *
     * @param moves how many curves of the plan are fed slower in some stretch (each layer alike)
     * @param lengthMm the slowed stretches' length at one layer
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

    public EngagementFeed {
        // by identity: two cuts may hold equal curves, each judged where it is cut
        stretches = Collections.unmodifiableMap(new IdentityHashMap<>(stretches));
    }

    /**
     * Measures the section's first layer and finds the stretches.
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
        // for each owner, the samples over the bound: where along it (fraction) and their factor
        Map<Object, List<double[]>> over = new IdentityHashMap<>();
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
                    double at = owner instanceof Curve2 c ? fractionAlong(c, p) : 0;
                    over.computeIfAbsent(owner, k -> new ArrayList<>()).add(new double[] {at, f});
                });
        Map<Object, List<Stretch>> stretches = new IdentityHashMap<>();
        double length = 0;
        double lowest = 1;
        for (Map.Entry<Object, List<double[]>> e : over.entrySet()) {
            List<Stretch> s = e.getKey() instanceof Curve2 c
                    ? stretches(e.getValue(), c.length())
                    : List.of(new Stretch(
                            0,
                            1,
                            e.getValue().stream().mapToDouble(v -> v[1]).min().orElse(1)));
            stretches.put(e.getKey(), s);
            for (Stretch st : s) {
                length += e.getKey() instanceof Curve2 c ? (st.to() - st.from()) * c.length() : 0;
                lowest = Math.min(lowest, st.factor());
            }
        }
        return new EngagementFeed(
                stretches, new Slowed(stretches.size(), length, worst[0], worstAt[0], boundDeg, lowest));
    }

    /** The samples over the bound along a curve of this length, grouped into stretches with their margins. */
    private static List<Stretch> stretches(List<double[]> samples, double lengthMm) {
        samples.sort((a, b) -> Double.compare(a[0], b[0]));
        double join = lengthMm > 0 ? JOIN_MM / lengthMm : 1;
        double margin = lengthMm > 0 ? MARGIN_MM / lengthMm : 1;
        List<Stretch> out = new ArrayList<>();
        double from = samples.get(0)[0];
        double to = from;
        double factor = samples.get(0)[1];
        for (double[] s : samples) {
            if (s[0] - to > join) {
                out.add(stretch(from - margin, to + margin, factor, join));
                from = s[0];
                factor = 1;
            }
            to = s[0];
            factor = Math.min(factor, s[1]);
        }
        out.add(stretch(from - margin, to + margin, factor, join));
        // margins may have made neighbours overlap
        List<Stretch> merged = new ArrayList<>();
        for (Stretch s : out) {
            Stretch last = merged.isEmpty() ? null : merged.get(merged.size() - 1);
            if (last != null && s.from() <= last.to()) {
                merged.set(merged.size() - 1, new Stretch(last.from(), s.to(), Math.min(last.factor(), s.factor())));
            } else {
                merged.add(s);
            }
        }
        return merged;
    }

    /** A stretch clipped to the curve, reaching its end where it would leave less than a join before it. */
    private static Stretch stretch(double from, double to, double factor, double join) {
        double a = from < join ? 0 : from;
        double b = to > 1 - join ? 1 : to;
        return new Stretch(a, b, factor);
    }

    /** Where along the curve (a fraction of its length) the point nearest p lies. */
    static double fractionAlong(Curve2 c, Vec2 p) {
        if (c instanceof Segment2 s) {
            Vec2 d = s.end().minus(s.start());
            double ll = d.dot(d);
            return ll > 0 ? Math.max(0, Math.min(1, p.minus(s.start()).dot(d) / ll)) : 0;
        }
        if (c instanceof Arc2 a) {
            double sweep = Math.abs(a.sweepRad());
            if (!(sweep > 0)) {
                return 0;
            }
            double off = p.minus(a.center()).angleRad() - a.startAngleRad();
            if (!a.ccw()) {
                off = -off;
            }
            off = ((off % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI);
            if (off > sweep) {
                // beyond the arc's end: nearer its end or its start
                return off - sweep < 2 * Math.PI - off ? 1 : 0;
            }
            return off / sweep;
        }
        return 0;
    }

    /** The pieces a curve of the plan is written in, each with its fraction of the feed. */
    List<Piece> pieces(Curve2 c) {
        List<Stretch> s = stretches.get(c);
        if (s == null) {
            return List.of(new Piece(c, 1));
        }
        List<Piece> out = new ArrayList<>();
        double at = 0;
        for (Stretch st : s) {
            if (st.from() > at) {
                out.add(new Piece(part(c, at, st.from()), 1));
            }
            out.add(new Piece(part(c, st.from(), st.to()), st.factor()));
            at = st.to();
        }
        if (at < 1) {
            out.add(new Piece(part(c, at, 1), 1));
        }
        return out;
    }

    /** The fraction of the feed of a link into this cut. */
    double linkFactor(Object cut) {
        List<Stretch> s = stretches.get(cut);
        return s == null ? 1 : s.get(0).factor();
    }

    private static Curve2 part(Curve2 c, double from, double to) {
        if (from == 0 && to == 1) {
            return c;
        }
        Vec2 a = c.pointAt(from);
        Vec2 b = c.pointAt(to);
        return c instanceof Arc2 arc ? new Arc2(arc.center(), a, b, arc.ccw()) : new Segment2(a, b);
    }

    /** The feed a move is written with: the programmed one times its factor, in whole mm/min, at least 1. */
    static double feed(double feedMmPerMin, double factor) {
        if (factor >= 1) {
            return feedMmPerMin;
        }
        return Math.max(1, Math.floor(feedMmPerMin * factor));
    }
}
