package org.fresa.pocket;

import java.util.List;
import java.util.Optional;
import org.fresa.geom.Vec2;

/**
 * Junctions of offset elements chosen by the thesis's S/L selectors: S takes the solution with
 * the smaller x, L the larger; when both share x, y decides. A line that misses a circle by less
 * than {@code 100·compar} counts as tangent and meets it at the foot of the perpendicular (the
 * thesis's snap; the arc's radius at that point then differs from its nominal radius by the gap).
 */
public final class ElementGeometry {
    private ElementGeometry() {}

    /** The one or two intersection points of the two elements' carriers at offset t, S first. */
    public static List<Vec2> candidates(PocketElement p, PocketElement q, double t, double compar) {
        if (!p.arc() && !q.arc()) {
            double a1 = p.a(), b1 = p.b(), d1 = p.at(t), a2 = q.a(), b2 = q.b(), d2 = q.at(t);
            double det = a1 * b2 - a2 * b1;
            if (Math.abs(det) <= 1e-12 * Math.hypot(a1, b1) * Math.hypot(a2, b2)) {
                return List.of();
            }
            return List.of(new Vec2((-b1 * d2 + d1 * b2) / det, (-d1 * a2 + a1 * d2) / det));
        }
        if (p.arc() && q.arc()) {
            double x1 = p.a(), y1 = p.b(), r1 = Math.max(0, p.at(t)), x2 = q.a(), y2 = q.b(), r2 = Math.max(0, q.at(t));
            if (Math.hypot(x2 - x1, y2 - y1) <= 1e-12) {
                return List.of();
            }
            double a = 2 * (x2 - x1), b = 2 * (y2 - y1);
            double d = -(x1 * x1 + y1 * y1 - r1 * r1 + r2 * r2 - x2 * x2 - y2 * y2);
            return lineCircle(a, b, d, x1, y1, r1, compar);
        }
        PocketElement line = p.arc() ? q : p;
        PocketElement circle = p.arc() ? p : q;
        return lineCircle(line.a(), line.b(), line.at(t), circle.a(), circle.b(), Math.max(0, circle.at(t)), compar);
    }

    private static List<Vec2> lineCircle(double a, double b, double d, double xc, double yc, double r, double compar) {
        double n = Math.hypot(a, b);
        double h = (a * xc + b * yc - d) / n;
        Vec2 foot = new Vec2(xc - a / n * h, yc - b / n * h);
        double gap = Math.abs(h) - r;
        if (gap > 0) {
            return gap < 100 * compar ? List.of(foot) : List.of();
        }
        double s = Math.sqrt(Math.max(0, r * r - h * h));
        Vec2 dir = new Vec2(-b / n, a / n);
        Vec2 u = foot.minus(dir.times(s));
        Vec2 v = foot.plus(dir.times(s));
        boolean sameX = Math.abs(u.x() - v.x()) <= 1e-9 * (1 + Math.abs(u.x()));
        boolean uFirst = sameX ? u.y() <= v.y() : u.x() <= v.x();
        return uFirst ? List.of(u, v) : List.of(v, u);
    }

    /** The junction of p (ending) and q (starting) at offset t, chosen by q's selector. */
    public static Optional<Vec2> junction(PocketElement p, PocketElement q, double t, double compar) {
        List<Vec2> c = candidates(p, q, t, compar);
        if (c.isEmpty()) {
            return Optional.empty();
        }
        return Optional.of(q.selector() == 'L' && c.size() > 1 ? c.get(1) : c.get(0));
    }

    /** The selector that picks, of the junctions of p and q at offset t, the one nearest to near. */
    public static char selectorNear(PocketElement p, PocketElement q, double t, Vec2 near, double compar) {
        List<Vec2> c = candidates(p, q, t, compar);
        if (c.size() < 2) {
            return 'S';
        }
        return c.get(1).distance(near) < c.get(0).distance(near) ? 'L' : 'S';
    }

    /** Interior angle (degrees) of a clockwise contour at the junction v of p (ending) and q (starting). */
    public static double interiorAngleDeg(PocketElement p, PocketElement q, Vec2 v) {
        Vec2 tin = p.tangentAt(v);
        Vec2 tout = q.tangentAt(v);
        if (tin.norm() == 0 || tout.norm() == 0) {
            return 180;
        }
        double turn = Math.atan2(tin.cross(tout), tin.dot(tout));
        return Math.toDegrees(Math.PI + turn);
    }
}
