package org.fresa.sole;

import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Intersections;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;

/**
 * EXAPT-style travel along circles: where a {@code GO/ON,YPAR,x,ON,circle} start-up lands, where
 * a {@code GOLFT/GORGT/GOFWD/GOBACK} along a circle stops at its check surface (the first crossing
 * ahead of the tool), and which way the tool turns onto the next circle.
 */
final class CircleWalk {
    private CircleWalk() {}

    /** The angle travelled from a to b about c in the given sense, in (0, 2 pi]. */
    static double sweep(Vec2 c, Vec2 a, Vec2 b, boolean ccw) {
        double d = b.minus(c).angleRad() - a.minus(c).angleRad();
        if (!ccw) {
            d = -d;
        }
        d %= 2 * Math.PI;
        if (d < 0) {
            d += 2 * Math.PI;
        }
        return d < 1e-12 ? 2 * Math.PI : d;
    }

    /** The unit tangent of travel at p on the circle about c. */
    static Vec2 tangent(Vec2 c, Vec2 p, boolean ccw) {
        Vec2 n = p.minus(c).normalized().leftNormal();
        return ccw ? n : n.negated();
    }

    /** The candidate first reached travelling from start about c in the sense. */
    static Vec2 firstHit(Vec2 c, Vec2 start, boolean ccw, List<Vec2> candidates, String what) {
        Vec2 best = null;
        double bestSweep = Double.POSITIVE_INFINITY;
        for (Vec2 p : candidates) {
            double s = sweep(c, start, p, ccw);
            if (s < bestSweep) {
                bestSweep = s;
                best = p;
            }
        }
        if (best == null) {
            throw new IllegalArgumentException(what);
        }
        return best;
    }

    /** Where the vertical line x = xMm meets the circle (one point when tangent). */
    static List<Vec2> atX(Vec2 c, double r, double xMm, Tolerance tol) {
        return Intersections.lineCircle(Vec2.of(xMm, 0), Vec2.UNIT_Y, c, r, tol);
    }

    /**
     * The start-up point on the circle at x = fromX: of the (one or two) points, the one where
     * travel in the sense heads towards x = toX.
     */
    static Vec2 startAtX(Vec2 c, double r, double fromX, double toX, boolean ccw, Tolerance tol, String macro) {
        List<Vec2> pts = atX(c, r, fromX, tol);
        if (pts.isEmpty()) {
            throw new IllegalArgumentException(macro + ": the line x = " + fromX + " misses the circle");
        }
        for (Vec2 p : pts) {
            if (tangent(c, p, ccw).x() * (toX - fromX) > 0) {
                return p;
            }
        }
        return pts.get(0);
    }

    /** The arc from start about c in the sense to the first crossing of x = toX. */
    static Arc2 toX(Vec2 c, double r, Vec2 start, boolean ccw, double toX, Tolerance tol, String macro) {
        List<Vec2> pts = atX(c, r, toX, tol);
        Vec2 end = firstHit(c, start, ccw, pts, macro + ": the line x = " + toX + " misses the circle");
        return arc(c, start, end, ccw);
    }

    /** The arc from start about c (through start) in the sense to the first crossing of circle (c2, r2). */
    static Arc2 toCircle(Vec2 c, Vec2 start, boolean ccw, Vec2 c2, double r2, Tolerance tol, String macro) {
        List<Vec2> pts = Intersections.circleCircle(c, c.distance(start), c2, r2, Tolerance.ofLinear(1e-6));
        Vec2 end = firstHit(c, start, ccw, pts, macro + ": consecutive circles do not meet");
        return arc(c, start, end, ccw);
    }

    /**
     * The sense on the next circle (centre c2) at p: GOFWD keeps the heading (the tangent closest to
     * it), GOBACK reverses it.
     */
    static boolean nextSense(Vec2 heading, Vec2 c2, Vec2 p, boolean forward) {
        double dot = tangent(c2, p, true).dot(heading);
        return forward ? dot >= 0 : dot < 0;
    }

    static Arc2 arc(Vec2 c, Vec2 start, Vec2 end, boolean ccw) {
        return new Arc2(c, start, end, ccw);
    }
}
