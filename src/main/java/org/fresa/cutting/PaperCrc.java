package org.fresa.cutting;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Intersections;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;

/**
 * The 2010 paper's kerf compensation ("Correção do Raio de Corte", section 2.4): each element
 * is offset by S on the nozzle's side and each corner iT1 moves to the intersection iT2 of the
 * two offset elements, the root nearest iT1 (line-line, line-arc, arc-arc), so convex corners
 * stay sharp. Concave corners (for the nozzle) are invalid unless the elements are tangent
 * there; they are reported, as the paper marks them on screen.
 *
 * <p>Eq. (3) as printed, G = S / cos(gamma / 2) with gamma the angle between the edge vectors of
 * eq. (2), is wrong except at 90 degrees; the distance from iT1 to iT2 is S / sin(gamma / 2)
 * ({@link #lineLineDistance}); {@link #lineLineDistanceAsPrinted} keeps the printed form for the
 * record. Line-arc and arc-arc corners are computed as intersections of the offset carriers (the
 * paper's "iT2 = iT1 + M" cannot be literal).
 */
public final class PaperCrc {

    /** The compensated path (empty when it collapses) and the invalid vertices (original corners). */
    public record Result(Optional<Contour> path, List<Vec2> invalidVertices) {
        public Result {
            invalidVertices = List.copyOf(invalidVertices);
        }
    }

    private static final Tolerance TOL = new Tolerance(1e-9, 1e-9);

    private PaperCrc() {}

    /**
     * Eq. (1)-(5) corrected: the distance from the corner to the offset corner for edge vectors
     * u and v leaving the corner (gamma = the interior angle between them, eq. 2).
     */
    public static double lineLineDistance(Vec2 u, Vec2 v, double s) {
        double gamma = Math.acos(Math.max(-1, Math.min(1, u.dot(v) / (u.norm() * v.norm()))));
        return s / Math.sin(gamma / 2);
    }

    /** Eq. (3) as printed: G = S / cos(gamma / 2); right only for gamma = 90 degrees. */
    public static double lineLineDistanceAsPrinted(Vec2 u, Vec2 v, double s) {
        double gamma = Math.acos(Math.max(-1, Math.min(1, u.dot(v) / (u.norm() * v.norm()))));
        return s / Math.cos(gamma / 2);
    }

    /** The paper's contour area: each arc replaced by the two chords start-middle-end; circles exact. */
    public static double triangleArea(Contour c) {
        if (c.size() == 1 && c.get(0) instanceof Arc2 a && a.isFullCircle()) {
            return Math.PI * a.radius() * a.radius() * (a.ccw() ? 1 : -1);
        }
        double sum = 0;
        for (Curve2 cv : c.curves()) {
            if (cv instanceof Arc2 a) {
                Vec2 m = a.pointAt(0.5);
                sum += 0.5 * (a.start().cross(m) + m.cross(a.end()));
            } else {
                sum += 0.5 * cv.start().cross(cv.end());
            }
        }
        return sum;
    }

    /**
     * Compensates one contour.
     *
     * @param c the contour in the direction it will be cut
     * @param s the offset distance (mm)
     * @param toolLeft true when the nozzle runs on the left of the contour
     */
    public static Result offset(Contour c, double s, boolean toolLeft) {
        List<Vec2> invalid = new ArrayList<>();
        double side = toolLeft ? s : -s;
        if (c.size() == 1 && c.get(0) instanceof Arc2 a && a.isFullCircle()) {
            double r2 = a.ccw() ? a.radius() - side : a.radius() + side;
            if (r2 <= 0) {
                invalid.add(a.center());
                return new Result(Optional.empty(), invalid);
            }
            return new Result(Optional.of(new Contour(List.of(Arc2.circle(a.center(), r2, a.ccw())))), invalid);
        }
        int n = c.size();
        Vec2[] corner = new Vec2[n];
        for (int i = 0; i < n; i++) {
            Curve2 prev = c.get((i + n - 1) % n);
            Curve2 next = c.get(i);
            Vec2 t1 = prev.endTangent();
            Vec2 t2 = next.startTangent();
            Vec2 it1 = next.start();
            Vec2 n1 = t1.leftNormal().times(side);
            Vec2 n2 = t2.leftNormal().times(side);
            double cross = t1.cross(t2);
            boolean tangent = Math.abs(cross) < 1e-9 && t1.dot(t2) > 0;
            if (tangent) {
                corner[i] = it1.plus(n2);
                continue;
            }
            boolean concave = toolLeft ? cross > 0 : cross < 0;
            if (concave) {
                invalid.add(it1);
            }
            List<Vec2> roots = carrierIntersections(prev, next, side);
            if (roots.isEmpty()) {
                invalid.add(it1);
                corner[i] = it1.plus(n2);
                continue;
            }
            Vec2 best = roots.get(0);
            for (Vec2 p : roots) {
                if (p.distance(it1) < best.distance(it1)) {
                    best = p;
                }
            }
            corner[i] = best;
        }
        List<Curve2> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Curve2 cv = c.get(i);
            Vec2 a = corner[i];
            Vec2 b = corner[(i + 1) % n];
            if (cv instanceof Segment2) {
                if (!a.equals(b)) {
                    out.add(new Segment2(a, b));
                }
            } else {
                Arc2 arc = (Arc2) cv;
                double r2 = arc.ccw() ? arc.radius() - side : arc.radius() + side;
                if (r2 <= 1e-6) {
                    invalid.add(arc.center());
                    if (!a.equals(b)) {
                        out.add(new Segment2(a, b));
                    }
                } else if (!a.equals(b)) {
                    // a corner that is not on the offset circle (an invalid vertex without a root):
                    // reach the circle along the radius so the arc itself stays a true arc
                    Vec2 a2 = onCircle(arc.center(), a, r2);
                    Vec2 b2 = onCircle(arc.center(), b, r2);
                    if (a2.distance(a) > 1e-9) {
                        out.add(new Segment2(a, a2));
                    }
                    if (!a2.equals(b2)) {
                        out.add(new Arc2(arc.center(), a2, b2, arc.ccw()));
                    }
                    if (b2.distance(b) > 1e-9) {
                        out.add(new Segment2(b2, b));
                    }
                }
            }
        }
        if (out.isEmpty()) {
            return new Result(Optional.empty(), invalid);
        }
        return new Result(Optional.of(new Contour(out)), invalid);
    }

    private static Vec2 onCircle(Vec2 c, Vec2 p, double r) {
        double d = p.distance(c);
        if (Math.abs(d - r) <= 1e-9 || d == 0) {
            return p;
        }
        return c.plus(p.minus(c).times(r / d));
    }

    private static List<Vec2> carrierIntersections(Curve2 a, Curve2 b, double side) {
        if (a instanceof Segment2 s && b instanceof Segment2 t) {
            Vec2 na = s.direction().normalized().leftNormal().times(side);
            Vec2 nb = t.direction().normalized().leftNormal().times(side);
            return Intersections.lineLine(
                    s.start().plus(na), s.direction(), t.start().plus(nb), t.direction(), TOL);
        }
        if (a instanceof Segment2 s && b instanceof Arc2 t) {
            Vec2 na = s.direction().normalized().leftNormal().times(side);
            return Intersections.lineCircle(s.start().plus(na), s.direction(), t.center(), radius(t, side), TOL);
        }
        if (a instanceof Arc2 s && b instanceof Segment2 t) {
            Vec2 nb = t.direction().normalized().leftNormal().times(side);
            return Intersections.lineCircle(t.start().plus(nb), t.direction(), s.center(), radius(s, side), TOL);
        }
        Arc2 s = (Arc2) a;
        Arc2 t = (Arc2) b;
        return Intersections.circleCircle(s.center(), radius(s, side), t.center(), radius(t, side), TOL);
    }

    private static double radius(Arc2 a, double side) {
        return Math.abs(a.ccw() ? a.radius() - side : a.radius() + side);
    }
}
