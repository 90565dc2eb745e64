package org.fresa.pocket;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;

/**
 * Exact inward offset of a pocket region with islands: the boundary of the set of points of the
 * region (inside the outer contour, outside every island) that are at least d from its boundary.
 * Lines move by d, arcs change radius by d, corners that open get round joins (arcs of radius d);
 * the result is true lines and arcs.
 *
 * <p>Method: the region's boundary is oriented with the region on its left (outer loop
 * counter-clockwise, islands clockwise); the raw offsets of all loops (with arc joins) are split
 * at all their mutual intersections, every piece whose middle is closer than d to any boundary
 * element is dropped, and the rest is chained into loops. Offsetting the loops together is what
 * makes an island's grown offset merge with the outer loop's shrunk one where they meet.
 *
 * <p>Result orientation: counter-clockwise loops bound the faces of the offset region, clockwise
 * loops bound holes (around islands) in the face that contains them.
 */
public final class RegionOffsetter {

    private RegionOffsetter() {}

    /**
     * The region's boundary with the region on the left: the outer counter-clockwise, the islands
     * clockwise, whatever the input orientation.
     */
    public static List<Contour> oriented(Contour outer, List<Contour> islands) {
        List<Contour> out = new ArrayList<>();
        out.add(outer.ccw());
        for (Contour i : islands) {
            out.add(i.isCcw() ? i.reversed() : i);
        }
        return out;
    }

    /**
     * Offsets a region inwards.
     *
     * @param boundary the region's loops with the region on their left ({@link #oriented})
     * @param d the distance in mm, > 0
     * @param tol pieces shorter than tol.linear() / 1000 are left out of the input
     * @return the offset loops, largest area first; empty when nothing of the region is d from its boundary
     */
    public static List<Contour> inward(List<Contour> boundary, double d, Tolerance tol) {
        if (!(d > 0)) {
            throw new IllegalArgumentException("offset distance must be > 0: " + d);
        }
        List<Curve2> src = new ArrayList<>();
        List<Curve2> raw = new ArrayList<>();
        Box2 box = boundary.get(0).bounds();
        for (Contour c : boundary) {
            box = box.union(c.bounds());
        }
        double scale = Math.max(
                1,
                Math.max(
                                Math.max(Math.abs(box.minX()), Math.abs(box.maxX())),
                                Math.max(Math.abs(box.minY()), Math.abs(box.maxY())))
                        + d);
        double eps = 1e-9 * scale;
        for (Contour c : boundary) {
            List<Curve2> p = LineArcOffsetter.prepared(c, tol);
            if (p.isEmpty()) {
                continue;
            }
            src.addAll(p);
            raw.addAll(LineArcOffsetter.rawOffset(p, d, eps));
        }
        List<Curve2> pieces = LineArcOffsetter.split(raw, eps);
        OffsetDistance near = new OffsetDistance(src);
        List<Curve2> kept = new ArrayList<>();
        for (Curve2 p : pieces) {
            if (p.length() <= eps) {
                continue;
            }
            if (!near.closerThan(p.pointAt(0.5), d - 1e-10 * scale)) {
                kept.add(p);
            }
        }
        return OffsetChains.closedLoops(kept, tol, scale);
    }

    /**
     * The distance from the region's boundary to its innermost point (the radius of the largest
     * circle inside the region), by bisection on the offset, within tol.linear().
     */
    public static double inradius(List<Contour> boundary, Tolerance tol) {
        Box2 b = boundary.get(0).bounds();
        double lo = 0;
        double hi = Math.max(b.width(), b.height()) / 2 + 1e-9;
        while (hi - lo > Math.max(tol.linear(), 1e-6)) {
            double mid = (lo + hi) / 2;
            if (inward(boundary, mid, tol).isEmpty()) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        return lo;
    }

    /** A point strictly inside the loop's region side, near its first element: for containment tests. */
    static Vec2 probe(Contour loop) {
        Curve2 c = loop.get(0);
        return c.pointAt(0.5);
    }
}
