package org.fresa.geom;

import java.util.ArrayList;
import java.util.List;

/**
 * Intersections of lines and circles, exactly as doubles allow. The curve versions keep only
 * points that lie on both curves' extents (within the tolerance); the carrier versions work on the
 * infinite line and the full circle.
 *
 * <p>Tangency: when two carriers are tangent within tol.linear(), one point (the tangent point)
 * is returned, not two nearly equal ones and not none. Parallel or coincident lines, and
 * concentric circles, give no point.
 */
public final class Intersections {
    private Intersections() {}

    /** The intersection of the lines through (p, p + u) and (q, q + v), empty when parallel. */
    public static List<Vec2> lineLine(Vec2 p, Vec2 u, Vec2 q, Vec2 v, Tolerance tol) {
        double den = u.cross(v);
        double scale = u.norm() * v.norm();
        if (scale == 0 || Math.abs(den) <= tol.angularRad() * scale) {
            return List.of();
        }
        double t = q.minus(p).cross(v) / den;
        return List.of(p.plus(u.times(t)));
    }

    /** The intersections of the line through (p, p + u) with the circle (c, r). */
    public static List<Vec2> lineCircle(Vec2 p, Vec2 u, Vec2 c, double r, Tolerance tol) {
        double len = u.norm();
        if (len == 0) {
            return List.of();
        }
        Vec2 d = u.times(1 / len);
        Vec2 foot = p.plus(d.times(c.minus(p).dot(d)));
        double h = foot.distance(c);
        if (h > r + tol.linear()) {
            return List.of();
        }
        if (Math.abs(h - r) <= tol.linear()) {
            return List.of(foot);
        }
        double s = Math.sqrt(Math.max(0, r * r - h * h));
        return List.of(foot.minus(d.times(s)), foot.plus(d.times(s)));
    }

    /** The intersections of the circles (c1, r1) and (c2, r2). */
    public static List<Vec2> circleCircle(Vec2 c1, double r1, Vec2 c2, double r2, Tolerance tol) {
        double d = c1.distance(c2);
        if (d <= tol.linear()) {
            return List.of();
        }
        if (d > r1 + r2 + tol.linear() || d < Math.abs(r1 - r2) - tol.linear()) {
            return List.of();
        }
        double a = (r1 * r1 - r2 * r2 + d * d) / (2 * d);
        Vec2 dir = c2.minus(c1).times(1 / d);
        Vec2 mid = c1.plus(dir.times(a));
        double h2 = r1 * r1 - a * a;
        if (Math.abs(d - (r1 + r2)) <= tol.linear() || Math.abs(d - Math.abs(r1 - r2)) <= tol.linear() || h2 <= 0) {
            return List.of(mid);
        }
        double h = Math.sqrt(h2);
        Vec2 n = dir.leftNormal();
        return List.of(mid.plus(n.times(h)), mid.minus(n.times(h)));
    }

    /** The points where two curves (segments or arcs) meet, within their extents. */
    public static List<Vec2> of(Curve2 a, Curve2 b, Tolerance tol) {
        List<Vec2> raw;
        if (a instanceof Segment2 s && b instanceof Segment2 t) {
            raw = lineLine(s.start(), s.direction(), t.start(), t.direction(), tol);
        } else if (a instanceof Segment2 s && b instanceof Arc2 t) {
            raw = lineCircle(s.start(), s.direction(), t.center(), t.radius(), tol);
        } else if (a instanceof Arc2 s && b instanceof Segment2 t) {
            raw = lineCircle(t.start(), t.direction(), s.center(), s.radius(), tol);
        } else {
            Arc2 s = (Arc2) a;
            Arc2 t = (Arc2) b;
            raw = circleCircle(s.center(), s.radius(), t.center(), t.radius(), tol);
        }
        List<Vec2> out = new ArrayList<>(raw.size());
        for (Vec2 p : raw) {
            if (a.distanceTo(p) <= tol.linear() && b.distanceTo(p) <= tol.linear()) {
                out.add(p);
            }
        }
        return out;
    }
}
