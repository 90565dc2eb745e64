package org.fresa.dxf;

import java.util.List;
import java.util.function.DoubleFunction;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;

/**
 * Replaces a smooth parametric curve (an ellipse, a spline span, a non-uniformly scaled arc) by
 * arcs and lines that stay within a distance tolerance of it: each piece is the arc through the
 * piece's start, middle and end, accepted when the curve's points in between are within the
 * tolerance of it, otherwise the piece is halved. Pieces join exactly, end to start.
 */
final class DxfArcFitter {
    private static final int MAX_DEPTH = 18;

    private DxfArcFitter() {
    }

    static void fit(DoubleFunction<Vec2> f, double u0, double u1, double tolMm, List<Curve2> out) {
        fit(f, u0, f.apply(u0), u1, f.apply(u1), tolMm, out, 0);
    }

    private static void fit(DoubleFunction<Vec2> f, double u0, Vec2 p0, double u1, Vec2 p1, double tol,
            List<Curve2> out, int depth) {
        double um = 0.5 * (u0 + u1);
        Vec2 pm = f.apply(um);
        Curve2 piece = through(p0, pm, p1, tol);
        boolean ok = depth >= MAX_DEPTH;
        if (!ok && piece != null) {
            ok = true;
            for (int k = 1; k < 8 && ok; k++) {
                if (k == 4) {
                    continue;
                }
                Vec2 q = f.apply(u0 + (u1 - u0) * k / 8.0);
                ok = piece.distanceTo(q) <= tol;
            }
        }
        if (ok && piece != null) {
            if (piece.length() > 0) {
                out.add(piece);
            }
            return;
        }
        if (ok) { // depth exhausted on a degenerate piece
            if (!p0.equals(p1)) {
                out.add(new Segment2(p0, p1));
            }
            return;
        }
        fit(f, u0, p0, um, pm, tol, out, depth + 1);
        fit(f, um, pm, u1, p1, tol, out, depth + 1);
    }

    /** The arc (or line when nearly straight) from a through m to b; null when a == b. */
    static Curve2 through(Vec2 a, Vec2 m, Vec2 b, double tol) {
        if (a.distance(b) == 0) {
            return null;
        }
        Vec2 ab = b.minus(a);
        double cross = ab.cross(m.minus(a));
        double sagitta = Math.abs(cross) / ab.norm();
        if (sagitta <= tol * 0.25 && m.minus(a).dot(ab) > 0 && m.minus(b).dot(ab) < 0) {
            return new Segment2(a, b);
        }
        if (cross == 0) {
            return null;
        }
        // circumcentre
        double d = 2 * (a.x() * (m.y() - b.y()) + m.x() * (b.y() - a.y()) + b.x() * (a.y() - m.y()));
        double a2 = a.dot(a);
        double m2 = m.dot(m);
        double b2 = b.dot(b);
        double cx = (a2 * (m.y() - b.y()) + m2 * (b.y() - a.y()) + b2 * (a.y() - m.y())) / d;
        double cy = (a2 * (b.x() - m.x()) + m2 * (a.x() - b.x()) + b2 * (m.x() - a.x())) / d;
        Vec2 c = new Vec2(cx, cy);
        // m left of a->b means the arc turns right (clockwise)
        boolean ccw = cross < 0;
        // keep both ends at exactly one radius: move the end onto the start's circle only in direction
        return new Arc2(c, a, b, ccw);
    }
}
