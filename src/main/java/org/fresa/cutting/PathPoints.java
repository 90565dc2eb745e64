package org.fresa.cutting;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;

/**
 * Points anywhere on a closed cut path (not only at its vertices): the point nearest a position,
 * and the point where a cut pierced and left at the same place shortens the rapids to and from it
 * most. Used to choose where a cut without leads starts.
 */
final class PathPoints {

    /** Shorter pieces than this (mm) are not split off an element: the start moves to its end. */
    private static final double MIN_PIECE_MM = 1e-4;

    private static final double GOLDEN = (Math.sqrt(5) - 1) / 2;

    private PathPoints() {}

    /** A point on a path: the element, the fraction along it, the point, and what it costs. */
    record OnPath(int index, double fraction, Vec2 point, double cost) {}

    /** The fraction along c of the point of c nearest p. */
    static double nearestFraction(Curve2 c, Vec2 p) {
        if (c instanceof Segment2 s) {
            Vec2 d = s.end().minus(s.start());
            double l2 = d.dot(d);
            return l2 == 0 ? 0 : Math.max(0, Math.min(1, p.minus(s.start()).dot(d) / l2));
        }
        Arc2 a = (Arc2) c;
        Vec2 d = p.minus(a.center());
        if (d.norm() > 0 && a.radius() > 0 && a.containsAngle(d.angleRad())) {
            double sweep = a.sweepRad();
            double off =
                    sweep > 0 ? mod2pi(d.angleRad() - a.startAngleRad()) : mod2pi(a.startAngleRad() - d.angleRad());
            return Math.max(0, Math.min(1, off / Math.abs(sweep)));
        }
        return p.distance(a.start()) <= p.distance(a.end()) ? 0 : 1;
    }

    private static double mod2pi(double a) {
        double r = a % (2 * Math.PI);
        return r < 0 ? r + 2 * Math.PI : r;
    }

    /** The point of the path nearest p; cost is its distance. */
    static OnPath nearest(Contour path, Vec2 p) {
        OnPath best = null;
        for (int i = 0; i < path.size(); i++) {
            Curve2 c = path.get(i);
            if (best != null && boxDistance(c.bounds(), p) >= best.cost()) {
                continue;
            }
            double f = nearestFraction(c, p);
            Vec2 q = c.pointAt(f);
            double d = q.distance(p);
            if (best == null || d < best.cost()) {
                best = new OnPath(i, f, q, d);
            }
        }
        return best;
    }

    /**
     * The point q of the path where |from - q| + |q - to| is least (to null: |from - q| alone):
     * the start of a cut pierced and left at q between the exit before it and the pierce after it.
     */
    static OnPath bestLink(Contour path, Vec2 from, Vec2 to) {
        if (to == null) {
            return nearest(path, from);
        }
        OnPath best = null;
        for (int i = 0; i < path.size(); i++) {
            Curve2 c = path.get(i);
            Box2 b = c.bounds();
            if (best != null && boxDistance(b, from) + boxDistance(b, to) >= best.cost()) {
                continue;
            }
            OnPath o = c instanceof Segment2 ? onSegment(c, i, from, to, 0, 1) : onArc(c, i, from, to);
            if (best == null || o.cost() < best.cost()) {
                best = o;
            }
        }
        return best;
    }

    private static double cost(Curve2 c, double f, Vec2 from, Vec2 to) {
        Vec2 q = c.pointAt(f);
        return q.distance(from) + q.distance(to);
    }

    /** Golden-section search of the fraction on [lo, hi]: exact on a line, where the cost is convex. */
    private static OnPath onSegment(Curve2 c, int i, Vec2 from, Vec2 to, double lo, double hi) {
        double a = lo;
        double b = hi;
        double x1 = b - GOLDEN * (b - a);
        double x2 = a + GOLDEN * (b - a);
        double f1 = cost(c, x1, from, to);
        double f2 = cost(c, x2, from, to);
        for (int k = 0; k < 48 && (b - a) * c.length() > 1e-7; k++) {
            if (f1 <= f2) {
                b = x2;
                x2 = x1;
                f2 = f1;
                x1 = b - GOLDEN * (b - a);
                f1 = cost(c, x1, from, to);
            } else {
                a = x1;
                x1 = x2;
                f1 = f2;
                x2 = a + GOLDEN * (b - a);
                f2 = cost(c, x2, from, to);
            }
        }
        double best = f1 <= f2 ? x1 : x2;
        // the ends themselves, which the search only approaches
        for (double e : new double[] {lo, hi}) {
            if (cost(c, e, from, to) < cost(c, best, from, to)) {
                best = e;
            }
        }
        return new OnPath(i, best, c.pointAt(best), cost(c, best, from, to));
    }

    /** On an arc the cost is not convex: sampled, then refined around the best sample. */
    private static OnPath onArc(Curve2 c, int i, Vec2 from, Vec2 to) {
        Arc2 a = (Arc2) c;
        int n = Math.max(8, (int) Math.ceil(Math.abs(a.sweepRad()) / (Math.PI / 16)));
        int bestK = 0;
        double bestCost = Double.POSITIVE_INFINITY;
        for (int k = 0; k <= n; k++) {
            double v = cost(c, (double) k / n, from, to);
            if (v < bestCost) {
                bestCost = v;
                bestK = k;
            }
        }
        return onSegment(c, i, from, to, Math.max(0, bestK - 1) / (double) n, Math.min(n, bestK + 1) / (double) n);
    }

    private static double boxDistance(Box2 b, Vec2 p) {
        double dx = Math.max(0, Math.max(b.minX() - p.x(), p.x() - b.maxX()));
        double dy = Math.max(0, Math.max(b.minY() - p.y(), p.y() - b.maxY()));
        return Math.hypot(dx, dy);
    }

    /**
     * The closed path started at the given point. The element the path started in the middle of
     * (split into its last and first pieces) is joined again first, so re-starting does not add
     * elements.
     */
    static Contour restart(Contour path, OnPath at) {
        Contour whole = joinEnds(path);
        int i = at.index();
        double f = at.fraction();
        if (whole != path) {
            // indices shift: the first piece is gone and the last one is the joined element
            int n = whole.size();
            if (i == 0 || i == path.size() - 1) {
                i = n - 1;
                f = nearestFraction(whole.get(i), at.point());
            } else {
                i = i - 1;
            }
        }
        Curve2 c = whole.get(i);
        double len = c.length();
        if (f * len < MIN_PIECE_MM) {
            return CutPlanner.startAt(whole, i, 0);
        }
        if ((1 - f) * len < MIN_PIECE_MM) {
            return CutPlanner.startAt(whole, (i + 1) % whole.size(), 0);
        }
        return CutPlanner.startAt(whole, i, f);
    }

    /** The path with its last and first elements joined when they are two pieces of one line or arc. */
    static Contour joinEnds(Contour path) {
        int n = path.size();
        if (n < 3) {
            return path;
        }
        Curve2 last = path.get(n - 1);
        Curve2 first = path.get(0);
        Curve2 joined = null;
        if (last instanceof Segment2 l && first instanceof Segment2 f && l.length() > 0 && f.length() > 0) {
            Vec2 dl = l.end().minus(l.start()).normalized();
            Vec2 df = f.end().minus(f.start()).normalized();
            if (Math.abs(dl.cross(df)) < 1e-9 && dl.dot(df) > 0) {
                joined = new Segment2(l.start(), f.end());
            }
        } else if (last instanceof Arc2 l
                && first instanceof Arc2 f
                && l.ccw() == f.ccw()
                && l.center().distance(f.center()) < 1e-9
                && Math.abs(l.radius() - f.radius()) < 1e-9
                && Math.abs(l.sweepRad()) + Math.abs(f.sweepRad()) < 2 * Math.PI - 1e-6) {
            joined = new Arc2(l.center(), l.start(), f.end(), l.ccw());
        }
        if (joined == null) {
            return path;
        }
        List<Curve2> l = new ArrayList<>(path.curves().subList(1, n - 1));
        l.add(joined);
        return new Contour(l);
    }
}
