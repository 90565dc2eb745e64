package org.fresa.grading;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;

/**
 * Tangent-continuous circular arcs (biarcs) for an elliptic arc, so that NC programs and DXF
 * files keep G02/G03 arcs. Each piece of the ellipse is replaced by two arcs with the ellipse's
 * end points and end tangents (the equal-leg biarc); a piece is halved until every sample of the
 * ellipse lies within the tolerance of its biarc.
 *
 * <p>The check samples the ellipse at 32 interior parameters per piece; consecutive samples are
 * far closer than the curvature changes, so the true deviation exceeds the sampled one by a
 * negligible amount. The fit aims at 80 % of the tolerance to leave that margin.
 */
public final class Biarcs {

    private static final int SAMPLES = 32;
    private static final int MAX_DEPTH = 24;

    private Biarcs() {}

    /**
     * Arcs (and, where the ellipse is locally straight, segments) within toleranceMm of the
     * elliptic arc, from its exact start to its exact end, tangent-continuous inside.
     *
     * @param toleranceMm largest distance from the ellipse to the arcs, > 0
     */
    public static List<Curve2> of(EllipticArc e, double toleranceMm) {
        if (!(toleranceMm > 0)) {
            throw new IllegalArgumentException("tolerance must be > 0: " + toleranceMm);
        }
        int pieces = Math.max(1, (int) Math.ceil(Math.abs(e.sweepRad()) / (Math.PI / 4)));
        List<Curve2> out = new ArrayList<>();
        Vec2 p0 = e.start();
        for (int k = 0; k < pieces; k++) {
            double t0 = e.startRad() + e.sweepRad() * k / pieces;
            double t1 = e.startRad() + e.sweepRad() * (k + 1) / pieces;
            Vec2 p1 = k == pieces - 1 ? e.end() : e.at(t1);
            fit(e, t0, t1, p0, p1, 0.8 * toleranceMm, 0, out);
            p0 = p1;
        }
        return out;
    }

    private static void fit(
            EllipticArc e, double t0, double t1, Vec2 p0, Vec2 p1, double tol, int depth, List<Curve2> out) {
        List<Curve2> b = biarc(p0, e.tangent(t0), p1, e.tangent(t1));
        if (depth >= MAX_DEPTH || deviation(e, t0, t1, b) <= tol) {
            out.addAll(b);
            return;
        }
        double tm = (t0 + t1) / 2;
        Vec2 pm = e.at(tm);
        fit(e, t0, tm, p0, pm, tol, depth + 1, out);
        fit(e, tm, t1, pm, p1, tol, depth + 1, out);
    }

    /** The largest distance from ellipse samples in [t0, t1] to the curves. */
    static double deviation(EllipticArc e, double t0, double t1, List<Curve2> curves) {
        double worst = 0;
        for (int i = 1; i < SAMPLES; i++) {
            Vec2 p = e.at(t0 + (t1 - t0) * i / SAMPLES);
            double d = Double.POSITIVE_INFINITY;
            for (Curve2 c : curves) {
                d = Math.min(d, c.distanceTo(p));
            }
            worst = Math.max(worst, d);
        }
        return worst;
    }

    /**
     * The equal-leg biarc from p0 with unit tangent t0 to p1 with unit tangent t1: two arcs that
     * meet with a common tangent. Legs d satisfy |(p1 - d t1) - (p0 + d t0)| = 2 d.
     */
    static List<Curve2> biarc(Vec2 p0, Vec2 t0, Vec2 p1, Vec2 t1) {
        Vec2 v = p1.minus(p0);
        Vec2 t = t0.plus(t1);
        double a = t.dot(t) - 4;
        double b = -2 * v.dot(t);
        double c = v.dot(v);
        double d;
        if (Math.abs(a) < 1e-12) {
            double vt = v.dot(t);
            if (vt <= 0) {
                return List.of(new Segment2(p0, p1));
            }
            d = c / (2 * vt);
        } else {
            d = (-b - Math.sqrt(Math.max(0, b * b - 4 * a * c))) / (2 * a);
        }
        if (!(d > 0) || !Double.isFinite(d)) {
            return List.of(new Segment2(p0, p1));
        }
        Vec2 q0 = p0.plus(t0.times(d));
        Vec2 q1 = p1.minus(t1.times(d));
        Vec2 joint = q0.interpolate(q1, 0.5);
        List<Curve2> out = new ArrayList<>(2);
        out.add(arc(p0, t0, joint));
        out.add(arc(joint, q1.minus(q0).normalized(), p1));
        return out;
    }

    /** The arc leaving p with unit tangent t that reaches q (a segment when q lies ahead on t). */
    static Curve2 arc(Vec2 p, Vec2 t, Vec2 q) {
        Vec2 chord = q.minus(p);
        Vec2 n = t.leftNormal();
        double h = chord.dot(n);
        double len2 = chord.dot(chord);
        // a radius above 1e7 chord lengths is a line for any machine
        if (Math.abs(h) * 1e7 <= Math.sqrt(len2) || len2 == 0) {
            return new Segment2(p, q);
        }
        double r = len2 / (2 * h);
        Vec2 center = p.plus(n.times(r));
        return new Arc2(center, p, q, r > 0);
    }
}
