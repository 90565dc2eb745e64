package org.fresa.dxf;

import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleFunction;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;

/**
 * Replaces a smooth parametric curve (an ellipse, a spline, a non-uniformly scaled arc) by
 * tangent-continuous biarcs that stay within a distance tolerance of it.
 *
 * <p>A biarc joins two points with given unit tangents by two arcs that meet with a common
 * tangent; the "equal distance" biarc is used: the joint is the middle of Q1 = P0 + d T0 and
 * Q2 = P1 - d T1 with |Q2 - Q1| = 2 d, that is
 * <pre>
 *   d = (-(v.t) + sqrt((v.t)^2 + (4 - t.t) v.v)) / (4 - t.t),   v = P1 - P0, t = T0 + T1
 * </pre>
 * A piece is accepted when the curve's points at 15 interior parameters, and the farthest point
 * found by a golden-section search around the worst of them, are within the tolerance of the
 * biarc, and the biarc's points at its quarters are within the tolerance of the curve;
 * otherwise it is halved at the middle parameter, the tangent there being shared by both halves.
 *
 * <p>The curve is given as consecutive pieces (knot spans, ellipse quadrants), each a function
 * over its own parameter range. Where two pieces meet with tangents less than
 * {@link #SMOOTH_RAD} apart the shared tangent is their mean, so the output is G1 across pieces
 * too; a real kink (a knot of full multiplicity) is kept. End points are exact: the output starts
 * at the first piece's first point and ends at the last piece's last point (the first point again
 * when {@code closed}); each curve starts exactly where the previous one ends. Tangents are
 * central differences of the piece's own function.
 */
final class DxfArcFitter {
    private static final int MAX_DEPTH = 18;
    /** Tangents closer than this at a joint between pieces are treated as one (radians). */
    static final double SMOOTH_RAD = 1e-4;

    /** One piece of a curve: the point at each parameter in [u0, u1]. */
    record Piece(DoubleFunction<Vec2> f, double u0, double u1) {}

    private DxfArcFitter() {}

    /** Fits one piece (see {@link #fit(List, boolean, double, List)}). */
    static void fit(DoubleFunction<Vec2> f, double u0, double u1, double tolMm, List<Curve2> out) {
        fit(List.of(new Piece(f, u0, u1)), false, tolMm, out);
    }

    /**
     * Fits consecutive pieces.
     *
     * @param closed the last piece ends where the first starts: its end is snapped there and the
     *     tangent there is shared when smooth
     */
    static void fit(List<Piece> pieces, boolean closed, double tolMm, List<Curve2> out) {
        int n = pieces.size();
        if (n == 0) {
            return;
        }
        Vec2[] start = new Vec2[n];
        Vec2[] t0 = new Vec2[n];
        Vec2[] t1 = new Vec2[n];
        for (int i = 0; i < n; i++) {
            Piece p = pieces.get(i);
            start[i] = p.f.apply(p.u0);
            t0[i] = tangent(p, p.u0);
            t1[i] = tangent(p, p.u1);
        }
        for (int i = 0; i < n; i++) {
            int j = i + 1;
            if (j == n) {
                if (!closed) {
                    break;
                }
                j = 0;
            }
            Vec2 a = t1[i];
            Vec2 b = t0[j];
            if (a != null && b != null && Math.abs(Math.atan2(a.cross(b), a.dot(b))) < SMOOTH_RAD) {
                Vec2 m = a.plus(b).normalized();
                t1[i] = m;
                t0[j] = m;
            }
        }
        for (int i = 0; i < n; i++) {
            Piece p = pieces.get(i);
            Vec2 end = i + 1 < n ? start[i + 1] : closed ? start[0] : p.f.apply(p.u1);
            fit(p, p.u0, start[i], t0[i], p.u1, end, t1[i], tolMm, out, 0);
        }
    }

    /** The unit tangent of the piece at u (a central difference), or null where it vanishes. */
    static Vec2 tangent(Piece p, double u) {
        double span = Math.abs(p.u1 - p.u0);
        double h = Math.max(span, 1e-300) * 1e-5;
        Vec2 d = p.f.apply(u + h).minus(p.f.apply(u - h));
        if (d.norm() <= 1e-14 * Math.max(1, p.f.apply(u).norm())) {
            // a cusp or a degenerate parametrisation: the direction into the piece
            double dir = u <= p.u0 ? 1 : -1;
            d = p.f.apply(u + dir * span * 1e-3).minus(p.f.apply(u)).times(dir);
            if (d.norm() == 0) {
                return null;
            }
        }
        return d.normalized();
    }

    private static void fit(
            Piece p,
            double ua,
            Vec2 pa,
            Vec2 ta,
            double ub,
            Vec2 pb,
            Vec2 tb,
            double tol,
            List<Curve2> out,
            int depth) {
        if (pa.equals(pb)) {
            // a closed piece is split; a vanishing one is left out
            if (depth >= MAX_DEPTH || ua == ub || p.f.apply(0.5 * (ua + ub)).distance(pa) <= tol * 1e-3) {
                return;
            }
        } else if (ta != null && tb != null) {
            List<Curve2> biarc = biarc(pa, ta, pb, tb);
            if (biarc != null && (depth >= MAX_DEPTH || within(p, ua, ub, biarc, tol))) {
                out.addAll(biarc);
                return;
            }
        }
        if (depth >= MAX_DEPTH) {
            out.add(new Segment2(pa, pb));
            return;
        }
        double um = 0.5 * (ua + ub);
        Vec2 pm = p.f.apply(um);
        Vec2 tm = tangent(p, um);
        fit(p, ua, pa, ta, um, pm, tm, tol, out, depth + 1);
        fit(p, um, pm, tm, ub, pb, tb, tol, out, depth + 1);
    }

    /**
     * The equal-distance biarc from a (unit tangent ta) to b (unit tangent tb): one or two curves,
     * the second starting exactly where the first ends; null when it degenerates (a half-turn or
     * more, a joint at an end).
     */
    static List<Curve2> biarc(Vec2 a, Vec2 ta, Vec2 b, Vec2 tb) {
        Vec2 v = b.minus(a);
        Vec2 t = ta.plus(tb);
        double vt = v.dot(t);
        double k = 4 - t.dot(t);
        double d;
        if (k < 1e-12) {
            double vtb = v.dot(tb);
            if (Math.abs(vtb) <= 1e-12 * v.norm()) {
                return null;
            }
            d = v.dot(v) / (4 * vtb);
        } else {
            d = (-vt + Math.sqrt(vt * vt + k * v.dot(v))) / k;
        }
        if (!(d > 0) || !Double.isFinite(d)) {
            return null;
        }
        Vec2 q1 = a.plus(ta.times(d));
        Vec2 q2 = b.minus(tb.times(d));
        Vec2 tm = q2.minus(q1);
        if (tm.norm() <= 1e-15 * Math.max(1, v.norm())) {
            // the tangents already meet at one point: a single arc or line through it
            Curve2 one = arc(a, ta, b);
            return one == null ? null : List.of(one);
        }
        Vec2 m = q1.interpolate(q2, 0.5);
        Curve2 c1 = arc(a, ta, m);
        Curve2 c2 = arc(m, tm.normalized(), b);
        if (c1 == null || c2 == null) {
            return null;
        }
        return List.of(c1, c2);
    }

    /** The arc (or line) leaving a with unit tangent t and ending at b; null for a half-turn or more. */
    static Curve2 arc(Vec2 a, Vec2 t, Vec2 b) {
        Vec2 w = b.minus(a);
        double len = w.norm();
        if (len == 0) {
            return null;
        }
        Vec2 n = t.leftNormal();
        double nw = n.dot(w);
        // sagitta-like measure: a line when the arc would bulge less than 1e-12 of its chord
        if (Math.abs(nw) <= 1e-12 * len) {
            return t.dot(w) > 0 ? new Segment2(a, b) : null;
        }
        if (t.dot(w) <= 0) {
            return null; // the arc would sweep half a turn or more
        }
        double r = w.dot(w) / (2 * nw);
        Vec2 c = a.plus(n.times(r));
        return new Arc2(c, a, b, r > 0);
    }

    /** True when the curve over [ua, ub] and the biarc are within tol of each other, both ways. */
    private static boolean within(Piece p, double ua, double ub, List<Curve2> biarc, double tol) {
        int samples = 16;
        double[] us = new double[samples + 1];
        Vec2[] pts = new Vec2[samples + 1];
        for (int k = 0; k <= samples; k++) {
            us[k] = ua + (ub - ua) * k / samples;
            pts[k] = p.f.apply(us[k]);
        }
        int worst = 1;
        double worstD = 0;
        for (int k = 1; k < samples; k++) {
            double d = distance(biarc, pts[k]);
            if (d > tol) {
                return false;
            }
            if (d > worstD) {
                worstD = d;
                worst = k;
            }
        }
        // the largest deviation lies near the worst sample: search the parameter around it
        double lo = us[worst - 1];
        double hi = us[worst + 1];
        double g = (Math.sqrt(5) - 1) / 2;
        double x1 = hi - g * (hi - lo);
        double x2 = lo + g * (hi - lo);
        double f1 = distance(biarc, p.f.apply(x1));
        double f2 = distance(biarc, p.f.apply(x2));
        for (int it = 0; it < 30; it++) {
            if (f1 > f2) {
                hi = x2;
                x2 = x1;
                f2 = f1;
                x1 = hi - g * (hi - lo);
                f1 = distance(biarc, p.f.apply(x1));
            } else {
                lo = x1;
                x1 = x2;
                f1 = f2;
                x2 = lo + g * (hi - lo);
                f2 = distance(biarc, p.f.apply(x2));
            }
        }
        if (Math.max(f1, f2) > tol) {
            return false;
        }
        for (Curve2 c : biarc) {
            for (double f : new double[] {0.25, 0.5, 0.75}) {
                if (distanceToCurve(p, us, pts, c.pointAt(f)) > tol) {
                    return false;
                }
            }
        }
        return true;
    }

    private static double distance(List<Curve2> curves, Vec2 q) {
        double best = Double.POSITIVE_INFINITY;
        for (Curve2 c : curves) {
            best = Math.min(best, c.distanceTo(q));
        }
        return best;
    }

    /** The distance from q to the curve: the nearest sample, then a golden-section search around it. */
    static double distanceToCurve(Piece p, double[] us, Vec2[] pts, Vec2 q) {
        int best = 0;
        for (int k = 1; k < pts.length; k++) {
            if (pts[k].distance(q) < pts[best].distance(q)) {
                best = k;
            }
        }
        double lo = us[Math.max(0, best - 1)];
        double hi = us[Math.min(us.length - 1, best + 1)];
        double g = (Math.sqrt(5) - 1) / 2;
        double x1 = hi - g * (hi - lo);
        double x2 = lo + g * (hi - lo);
        double f1 = p.f.apply(x1).distance(q);
        double f2 = p.f.apply(x2).distance(q);
        for (int it = 0; it < 40; it++) {
            if (f1 < f2) {
                hi = x2;
                x2 = x1;
                f2 = f1;
                x1 = hi - g * (hi - lo);
                f1 = p.f.apply(x1).distance(q);
            } else {
                lo = x1;
                x1 = x2;
                f1 = f2;
                x2 = lo + g * (hi - lo);
                f2 = p.f.apply(x2).distance(q);
            }
        }
        return Math.min(Math.min(f1, f2), pts[best].distance(q));
    }

    /** Convenience for callers with a list to fill. */
    static List<Curve2> fit(List<Piece> pieces, boolean closed, double tolMm) {
        List<Curve2> out = new ArrayList<>();
        fit(pieces, closed, tolMm, out);
        return out;
    }
}
