package org.fresa.pocket;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Intersections;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;

/**
 * Exact offset of a closed line/arc contour: the boundary of the set of points at distance
 * |t| from the region the contour encloses (t > 0, growing) or from its complement (t < 0,
 * shrinking). Lines move by |t| along their normal, arcs keep their centre and change radius by
 * |t|, convex corners get a round join (an arc of radius |t| about the corner), and concave
 * corners are trimmed. Result arcs are true arcs, not polygons.
 *
 * <p>Method: the raw offset (every element offset, every corner joined by an arc of sweep equal
 * to the turn of the tangent, an arc whose radius passes zero turned inside out) is split at
 * all its self-intersections, every piece whose middle lies closer than |t| to the original is
 * dropped, and the remaining pieces are chained into loops. The result may be several loops
 * (a narrow waist pinches off) or none (the shape vanishes: a hole smaller than the kerf).
 *
 * <p>Orientation: loops that run the same way as the input bound the result region; loops that
 * run the other way (a grown C-shape closing over its mouth) bound voids inside it. Every point
 * of every loop is |t| from the input within about 1e-9 mm for drawings of metre size.
 */
public final class LineArcOffsetter {

    private static final Tolerance EXACT = new Tolerance(1e-10, 1e-13);

    private LineArcOffsetter() {}

    /**
     * Offsets a closed contour.
     *
     * @param contour the closed contour (either orientation)
     * @param outwardMm the signed distance: positive grows the enclosed region, negative shrinks it
     * @param tol the tolerance below which a piece is degenerate (its linear part, e.g. 1e-6 mm)
     * @return the offset loops, oriented like the input; empty when the region vanishes
     */
    public static List<Contour> offset(Contour contour, double outwardMm, Tolerance tol) {
        if (outwardMm == 0) {
            return List.of(contour);
        }
        boolean ccw = contour.isCcw();
        // positive left distance moves into a CCW region
        double left = ccw ? -outwardMm : outwardMm;
        List<Curve2> src = prepared(contour, tol);
        if (src.isEmpty()) {
            return List.of();
        }
        double dist = Math.abs(outwardMm);
        Box2 box = contour.bounds();
        double scale = Math.max(
                1,
                Math.max(
                                Math.max(Math.abs(box.minX()), Math.abs(box.maxX())),
                                Math.max(Math.abs(box.minY()), Math.abs(box.maxY())))
                        + dist);
        double eps = 1e-9 * scale;
        List<Curve2> raw = rawOffset(src, left, eps);
        List<Curve2> pieces = split(raw, eps);
        List<Curve2> kept = new ArrayList<>();
        OffsetDistance near = new OffsetDistance(src);
        for (Curve2 p : pieces) {
            if (p.length() <= eps) {
                continue;
            }
            Vec2 m = p.pointAt(0.5);
            if (!near.closerThan(m, dist - 1e-10 * scale)) {
                kept.add(p);
            }
        }
        return OffsetChains.closedLoops(kept, tol, scale);
    }

    /** The curves without zero-length pieces, full circles halved so every arc has a sweep < 2 pi. */
    static List<Curve2> prepared(Contour contour, Tolerance tol) {
        List<Curve2> out = new ArrayList<>();
        for (Curve2 c : contour.curves()) {
            if (c.length() <= tol.linear() * 1e-3) {
                continue;
            }
            if (c instanceof Arc2 a && a.isFullCircle()) {
                Vec2 opposite = a.center().times(2).minus(a.start());
                out.add(new Arc2(a.center(), a.start(), opposite, a.ccw()));
                out.add(new Arc2(a.center(), opposite, a.start(), a.ccw()));
            } else {
                out.add(c);
            }
        }
        return out;
    }

    /** The raw offset by a signed distance to the left of travel, with arc joins at every corner. */
    static List<Curve2> rawOffset(List<Curve2> src, double left, double eps) {
        int n = src.size();
        List<Curve2> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Curve2 c = src.get(i);
            Curve2 o = offsetOne(c, left, eps);
            if (o != null) {
                out.add(o);
            }
            Curve2 next = src.get((i + 1) % n);
            Vec2 t1 = c.endTangent();
            Vec2 t2 = next.startTangent();
            Vec2 v = c.end();
            Vec2 e = v.plus(t1.leftNormal().times(left));
            Vec2 s = v.plus(t2.leftNormal().times(left));
            if (e.distance(s) > eps) {
                double turn = Math.atan2(t1.cross(t2), t1.dot(t2));
                out.add(new Arc2(v, e, s, turn > 0));
            }
        }
        return out;
    }

    private static Curve2 offsetOne(Curve2 c, double left, double eps) {
        if (c instanceof Segment2 s) {
            Vec2 n = s.direction().normalized().leftNormal().times(left);
            return new Segment2(s.start().plus(n), s.end().plus(n));
        }
        Arc2 a = (Arc2) c;
        double rs = a.radius();
        // chained drawings may leave the end a hair off the start's radius: offset each end from its own
        double re = a.center().distance(a.end());
        double r2s = a.ccw() ? rs - left : rs + left;
        double r2e = a.ccw() ? re - left : re + left;
        if (Math.abs(r2s) <= eps || Math.abs(r2e) <= eps || Math.signum(r2s) != Math.signum(r2e)) {
            return null;
        }
        Vec2 us = a.start().minus(a.center()).times(1 / rs);
        Vec2 ue = a.end().minus(a.center()).times(1 / re);
        // a negative radius is the arc turned inside out: same centre and sense, opposite side
        return new Arc2(a.center(), a.center().plus(us.times(r2s)), a.center().plus(ue.times(r2e)), a.ccw());
    }

    /** Every raw curve split at its intersections with every other. */
    static List<Curve2> split(List<Curve2> raw, double eps) {
        int n = raw.size();
        Box2[] boxes = new Box2[n];
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) {
            Box2 b = raw.get(i).bounds();
            boxes[i] = new Box2(b.minX() - eps, b.minY() - eps, b.maxX() + eps, b.maxY() + eps);
            order[i] = i;
        }
        java.util.Arrays.sort(order, Comparator.comparingDouble(i -> boxes[i].minX()));
        List<List<Vec2>> cuts = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            cuts.add(new ArrayList<>());
        }
        Tolerance t = new Tolerance(Math.max(EXACT.linear(), eps * 0.1), EXACT.angularRad());
        for (int oi = 0; oi < n; oi++) {
            int i = order[oi];
            for (int oj = oi + 1; oj < n; oj++) {
                int j = order[oj];
                if (boxes[j].minX() > boxes[i].maxX()) {
                    break;
                }
                if (!boxes[i].intersects(boxes[j])) {
                    continue;
                }
                for (Vec2 p : Intersections.of(raw.get(i), raw.get(j), t)) {
                    cuts.get(i).add(p);
                    cuts.get(j).add(p);
                }
            }
        }
        List<Curve2> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            OffsetSplit.splitAt(raw.get(i), cuts.get(i), eps, out);
        }
        return out;
    }
}
