package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Intersections;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;

/**
 * The passes of one layer of a pocket for each strategy, in the feature plane (thesis section
 * 3.2.2.1, generalised from rectangles to every convex profile here).
 *
 * <p>The tool-centre region is the profile inset by {@code wallOffsetMm} (tool radius plus side
 * allowance), the "first inner contour". Offset loops are spaced evenly, at most the stepover
 * apart, from the wall loop to the collapsed centre loop (a segment or a point), so the middle
 * is always reached; they are cut inside out. Parallel passes are spaced evenly, at most the
 * stepover apart, from one extreme of the region to the other, and clipped to it. Every profile
 * here is convex, so a straight link between two points of the region stays inside it.
 */
public final class PlanarPasses {
    private PlanarPasses() {}

    /**
     * @param feedDirection unit direction of parallel passes in the feature plane
     * @param clockwise run loops clockwise (conventional milling of a pocket's walls with an M3 spindle)
     * @throws IllegalArgumentException when the tool does not fit in the profile
     */
    public static List<Pass> of(
            Strategy strategy,
            Profile profile,
            double wallOffsetMm,
            double stepoverMm,
            Vec2 feedDirection,
            boolean clockwise,
            Tolerance tol) {
        Ring wall = profile.inset(wallOffsetMm, tol)
                .orElseThrow(() -> new IllegalArgumentException("the tool does not fit in the profile"));
        if (!profile.convex()) {
            return nonConvex(strategy, profile, wall, wallOffsetMm, stepoverMm, feedDirection, clockwise, tol);
        }
        List<Pass> out = new ArrayList<>();
        switch (strategy) {
            case UNIDIRECTIONAL -> out.addAll(parallel(wall, stepoverMm, feedDirection, false, tol));
            case BIDIRECTIONAL -> out.addAll(parallel(wall, stepoverMm, feedDirection, true, tol));
            case CONTOUR_PARALLEL -> out.addAll(loops(profile, wallOffsetMm, stepoverMm, clockwise, tol));
            case CONTOUR_SPIRAL -> out.add(spiral(loops(profile, wallOffsetMm, stepoverMm, clockwise, tol)));
            case BIDIRECTIONAL_CONTOUR -> {
                out.addAll(parallel(wall, stepoverMm, feedDirection, true, tol));
                out.add(new Pass(wall.start(), oriented(wall, clockwise).curves(), true));
            }
            case CONTOUR_BIDIRECTIONAL -> {
                out.add(new Pass(wall.start(), oriented(wall, clockwise).curves(), false));
                // half a stepover in: the wall loop clears that band, and the passes' end discs the rest
                Optional<Ring> inner = profile.inset(wallOffsetMm + stepoverMm / 2, tol);
                if (inner.isEmpty() && !Double.isNaN(profile.maxInsetMm())) {
                    inner = profile.inset(profile.maxInsetMm(), tol);
                }
                if (inner.isPresent()) {
                    List<Pass> zig = parallel(inner.get(), stepoverMm, feedDirection, true, tol);
                    for (Pass p : zig) {
                        out.add(new Pass(p.start(), p.curves(), true));
                    }
                }
            }
            case CENTER_MILLING -> {
                Ring centre = centreRing(profile, wallOffsetMm, tol);
                out.add(new Pass(centre.start(), centre.curves(), false));
            }
        }
        return out;
    }

    /**
     * A non-convex profile: a straight link may leave the region, so every pass is entered from
     * above; parallel passes are split where they leave the region; a spiral becomes nested loops.
     */
    private static List<Pass> nonConvex(
            Strategy strategy,
            Profile profile,
            Ring wall,
            double wallOffsetMm,
            double stepoverMm,
            Vec2 feedDirection,
            boolean clockwise,
            Tolerance tol) {
        List<Pass> out = new ArrayList<>();
        switch (strategy) {
            case UNIDIRECTIONAL, BIDIRECTIONAL ->
                out.addAll(parallelSplit(wall, stepoverMm, feedDirection, strategy == Strategy.BIDIRECTIONAL, tol));
            case BIDIRECTIONAL_CONTOUR -> {
                out.addAll(parallelSplit(wall, stepoverMm, feedDirection, true, tol));
                out.add(new Pass(wall.start(), oriented(wall, clockwise).curves(), false));
            }
            case CONTOUR_BIDIRECTIONAL -> {
                out.add(new Pass(wall.start(), oriented(wall, clockwise).curves(), false));
                profile.inset(wallOffsetMm + stepoverMm / 2, tol)
                        .ifPresent(r -> out.addAll(parallelSplit(r, stepoverMm, feedDirection, true, tol)));
            }
            case CENTER_MILLING ->
                out.add(new Pass(wall.start(), oriented(wall, clockwise).curves(), false));
            default -> out.addAll(loops(profile, wallOffsetMm, stepoverMm, clockwise, tol));
        }
        List<Pass> entered = new ArrayList<>();
        for (Pass p : out) {
            entered.add(new Pass(p.start(), p.curves(), false));
        }
        return entered;
    }

    /** Parallel passes cut into the pieces that lie inside the region (even-odd crossings). */
    static List<Pass> parallelSplit(Ring region, double stepoverMm, Vec2 feedDirection, boolean zigzag, Tolerance tol) {
        Vec2 u = feedDirection.normalized();
        Vec2 n = u.leftNormal();
        org.fresa.geom.Contour c = new org.fresa.geom.Contour(region.curves());
        org.fresa.geom.Box2 box = c.bounds();
        Band band = Band.across(region, n);
        double lo = band.lo();
        double hi = band.hi();
        double reach =
                4 * (Math.abs(box.minX()) + Math.abs(box.maxX()) + Math.abs(box.minY()) + Math.abs(box.maxY()) + 1);
        int m = (int) Math.ceil((hi - lo) / stepoverMm - 1e-9);
        List<Pass> out = new ArrayList<>();
        for (int k = m; k >= 0; k--) {
            // a hair inside the extremes: crossings there, not grazing contacts
            double s = m == 0 ? (lo + hi) / 2 : lo + (hi - lo) * k / m;
            s = Math.max(lo + 1e-4, Math.min(hi - 1e-4, s));
            Vec2 base = n.times(s);
            Segment2 line = new Segment2(base.minus(u.times(reach)), base.plus(u.times(reach)));
            List<Double> ts = new ArrayList<>();
            for (Curve2 cu : region.curves()) {
                for (Vec2 p : Intersections.of(line, cu, tol)) {
                    ts.add(p.dot(u));
                }
            }
            ts.sort(Double::compare);
            List<double[]> pieces = new ArrayList<>();
            for (int i = 0; i + 1 < ts.size(); i++) {
                double a = ts.get(i);
                double b = ts.get(i + 1);
                if (b - a > tol.linear() && c.contains(base.plus(u.times((a + b) / 2)), tol)) {
                    pieces.add(new double[] {a, b});
                }
            }
            boolean reverse = zigzag && (out.size() % 2 == 1);
            for (double[] ab : pieces) {
                Vec2 from = base.plus(u.times(reverse ? ab[1] : ab[0]));
                Vec2 to = base.plus(u.times(reverse ? ab[0] : ab[1]));
                out.add(new Pass(from, List.of(new Segment2(from, to)), false));
            }
        }
        return out;
    }

    static Ring oriented(Ring r, boolean clockwise) {
        return clockwise ? r.reversed() : r;
    }

    private static Ring centreRing(Profile profile, double wallOffsetMm, Tolerance tol) {
        double max = profile.maxInsetMm();
        if (Double.isNaN(max)) {
            return profile.inset(wallOffsetMm, tol).orElseThrow();
        }
        return profile.inset(max, tol).orElseThrow();
    }

    /** The offset loops from the centre outwards, the wall loop last. */
    static List<Pass> loops(Profile profile, double wallOffsetMm, double stepoverMm, boolean clockwise, Tolerance tol) {
        double max = profile.maxInsetMm();
        List<Ring> rings = new ArrayList<>();
        if (Double.isNaN(max)) {
            // find where the offsets vanish (to 1e-4 mm), then space the loops evenly up to there
            double ok = wallOffsetMm;
            double gone = wallOffsetMm + stepoverMm;
            while (profile.inset(gone, tol).isPresent()) {
                ok = gone;
                gone += stepoverMm;
            }
            while (gone - ok > 1e-4) {
                double mid = (ok + gone) / 2;
                if (profile.inset(mid, tol).isPresent()) {
                    ok = mid;
                } else {
                    gone = mid;
                }
            }
            double span = ok - wallOffsetMm;
            // loops of a general outline change shape as they shrink (reflex joins, collapsing arms): the
            // corner rule's spacing can leave islands where the last loops are far apart, so at most
            // the tool radius, which keeps every point within the radius of a loop
            double step = Math.min(stepoverMm, wallOffsetMm);
            int n = (int) Math.ceil(span / step - 1e-9);
            for (int k = 0; k <= n; k++) {
                double d = n == 0 ? wallOffsetMm : wallOffsetMm + span * k / n;
                List<Ring> at = profile.insetAll(d, tol);
                // the offsetter drops loops that are nearly points: step back until the innermost loop exists
                for (double back = 1e-3; at.isEmpty() && k > 0 && back < span / n; back *= 2) {
                    at = profile.insetAll(d - back, tol);
                }
                rings.addAll(at);
            }
        } else {
            double span = Math.max(0, max - wallOffsetMm);
            int n = (int) Math.ceil(span / stepoverMm - 1e-9);
            for (int k = 0; k <= n; k++) {
                double d = n == 0 ? wallOffsetMm : wallOffsetMm + span * k / n;
                profile.inset(d, tol).ifPresent(rings::add);
            }
        }
        List<Pass> out = new ArrayList<>();
        for (int k = rings.size() - 1; k >= 0; k--) {
            Ring r = oriented(rings.get(k), clockwise);
            out.add(new Pass(r.start(), r.curves(), k != rings.size() - 1));
        }
        return out;
    }

    /**
     * The loops joined into one spiral: each loop but the last leaves out its final element and
     * runs from that element's start straight (or, for a circular loop, on a half circle tangent
     * to both) to the next loop's start.
     */
    static Pass spiral(List<Pass> loops) {
        List<Curve2> all = new ArrayList<>();
        for (int k = 0; k < loops.size(); k++) {
            Pass p = loops.get(k);
            if (k == loops.size() - 1) {
                all.addAll(p.curves());
                break;
            }
            Vec2 next = loops.get(k + 1).start();
            if (p.curves().isEmpty()) {
                all.add(new Segment2(p.start(), next));
                continue;
            }
            List<Curve2> cs = p.curves();
            all.addAll(cs.subList(0, cs.size() - 1));
            Curve2 last = cs.get(cs.size() - 1);
            Vec2 from = last.start();
            if (last instanceof Arc2 a && from.distance(next) > 0) {
                Vec2 c = from.interpolate(next, 0.5);
                all.add(new Arc2(c, from, next, a.ccw()));
            } else {
                all.add(new Segment2(from, next));
            }
        }
        return new Pass(loops.get(0).start(), all, false);
    }

    /** Passes parallel to the feed direction clipped to the region inside the ring. */
    static List<Pass> parallel(Ring region, double stepoverMm, Vec2 feedDirection, boolean zigzag, Tolerance tol) {
        Vec2 u = feedDirection.normalized();
        Vec2 n = u.leftNormal();
        if (region.curves().isEmpty()) {
            return List.of(new Pass(region.start(), List.of(), false));
        }
        Band band = Band.across(region, n);
        double lo = band.lo();
        double hi = band.hi();
        double span = hi - lo;
        double reach = 0;
        for (Curve2 c : region.curves()) {
            reach = Math.max(reach, Math.max(c.start().norm(), c.end().norm()));
        }
        reach = 4 * (reach + span + 1);
        int m = (int) Math.ceil(span / stepoverMm - 1e-9);
        List<Pass> out = new ArrayList<>();
        for (int k = m; k >= 0; k--) {
            double s = m == 0 ? (lo + hi) / 2 : lo + span * k / m;
            Vec2 base = n.times(s);
            Segment2 line = new Segment2(base.minus(u.times(reach)), base.plus(u.times(reach)));
            double t0 = Double.POSITIVE_INFINITY;
            double t1 = Double.NEGATIVE_INFINITY;
            for (Curve2 c : region.curves()) {
                List<Vec2> hits = new ArrayList<>(Intersections.of(line, c, tol));
                // an element lying along the line (the extreme lines on flat sides) gives no crossing
                for (Vec2 e : List.of(c.start(), c.end())) {
                    if (Math.abs(e.dot(n) - s) <= tol.linear()) {
                        hits.add(e);
                    }
                }
                for (Vec2 p : hits) {
                    t0 = Math.min(t0, p.dot(u));
                    t1 = Math.max(t1, p.dot(u));
                }
            }
            if (t0 > t1) {
                continue;
            }
            Vec2 a = base.plus(u.times(t0));
            Vec2 b = base.plus(u.times(t1));
            boolean reverse = zigzag && (out.size() % 2 == 1);
            Vec2 from = reverse ? b : a;
            Vec2 to = reverse ? a : b;
            List<Curve2> cs = from.distance(to) > 0 ? List.of(new Segment2(from, to)) : List.of();
            out.add(new Pass(from, cs, zigzag && !out.isEmpty()));
        }
        return out;
    }

    /**
     * The band of lines square to {@code n} that the ring lies within: the least and the greatest
     * {@code p . n} over its curves, arcs' bulges included.
     */
    private record Band(double lo, double hi) {
        static Band across(Ring region, Vec2 n) {
            double lo = Double.POSITIVE_INFINITY;
            double hi = Double.NEGATIVE_INFINITY;
            for (Curve2 c : region.curves()) {
                for (Vec2 p : extremes(c, n)) {
                    lo = Math.min(lo, p.dot(n));
                    hi = Math.max(hi, p.dot(n));
                }
            }
            return new Band(lo, hi);
        }
    }

    private static List<Vec2> extremes(Curve2 c, Vec2 n) {
        List<Vec2> pts = new ArrayList<>(List.of(c.start(), c.end()));
        if (c instanceof Arc2 a && a.radius() > 0) {
            for (Vec2 dir : List.of(n, n.negated())) {
                if (a.containsAngle(dir.angleRad())) {
                    pts.add(a.center().plus(dir.times(a.radius())));
                }
            }
        }
        return pts;
    }
}
