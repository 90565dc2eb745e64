package org.fresa.grading;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Vec2;

/**
 * An elliptic arc given as the affine image of a circular arc:
 * {@code p(t) = center + u cos t + v sin t} for t from startRad over sweepRad (CCW positive in
 * the base's sense). u and v are conjugate semi-diameters (the images of the base radius along x
 * and y), not necessarily the principal axes. The end points are stored exactly so that graded
 * elements meet where the base's met; the interior follows the formula.
 *
 * @param center the ellipse's centre (mm)
 * @param u semi-diameter at t = 0 (mm)
 * @param v semi-diameter at t = pi/2 (mm)
 * @param startRad parameter at the start
 * @param sweepRad signed parameter sweep; positive runs from u towards v
 * @param start exact start point
 * @param end exact end point
 */
public record EllipticArc(Vec2 center, Vec2 u, Vec2 v, double startRad, double sweepRad, Vec2 start, Vec2 end)
        implements GradedCurve {

    /** The image of a circular arc under the map. */
    public static EllipticArc of(Arc2 arc, PantographMap map) {
        double r = arc.radius();
        return new EllipticArc(
                map.apply(arc.center()),
                map.linear(new Vec2(r, 0)),
                map.linear(new Vec2(0, r)),
                arc.startAngleRad(),
                arc.sweepRad(),
                map.apply(arc.start()),
                map.apply(arc.end()));
    }

    /** The point at parameter t (radians). */
    public Vec2 at(double t) {
        return center.plus(u.times(Math.cos(t))).plus(v.times(Math.sin(t)));
    }

    /** The derivative dp/dt at t, which points along the direction of travel when sweep > 0. */
    public Vec2 derivative(double t) {
        return u.times(-Math.sin(t)).plus(v.times(Math.cos(t)));
    }

    /** The unit tangent in the direction of travel at t. */
    public Vec2 tangent(double t) {
        Vec2 d = derivative(t).normalized();
        return sweepRad >= 0 ? d : d.negated();
    }

    /** True when the ellipse is traversed counter-clockwise. */
    public boolean ccw() {
        return (u.cross(v) > 0) == (sweepRad > 0);
    }

    @Override
    public Vec2 pointAt(double f) {
        if (f == 0) {
            return start;
        }
        if (f == 1) {
            return end;
        }
        return at(startRad + f * sweepRad);
    }

    @Override
    public double[] extentAlong(Vec2 dir) {
        double a = u.dot(dir);
        double b = v.dot(dir);
        double lo = Math.min(start.dot(dir), end.dot(dir));
        double hi = Math.max(start.dot(dir), end.dot(dir));
        // f(t) = c + a cos t + b sin t is extreme where tan t = b / a
        double t0 = Math.atan2(b, a);
        for (double t : new double[] {t0, t0 + Math.PI}) {
            if (contains(t)) {
                double val = at(t).dot(dir);
                lo = Math.min(lo, val);
                hi = Math.max(hi, val);
            }
        }
        return new double[] {lo, hi};
    }

    /** True when parameter t lies within the swept range. */
    public boolean contains(double t) {
        double twoPi = 2 * Math.PI;
        if (Math.abs(sweepRad) >= twoPi) {
            return true;
        }
        double d = sweepRad >= 0 ? t - startRad : startRad - t;
        d = ((d % twoPi) + twoPi) % twoPi;
        return d <= Math.abs(sweepRad);
    }

    @Override
    public EllipticArc mapped(PantographMap map) {
        return new EllipticArc(
                map.apply(center), map.linear(u), map.linear(v), startRad, sweepRad, map.apply(start), map.apply(end));
    }

    /** The largest semi-axis length (mm). */
    public double majorRadius() {
        double[] ax = semiAxes();
        return ax[0];
    }

    /** The principal semi-axes {a, b}, a >= b, from the conjugate semi-diameters. */
    public double[] semiAxes() {
        // singular values of the 2x2 matrix [u v]
        double p = u.dot(u) + v.dot(v);
        double q = Math.abs(u.cross(v));
        double s = Math.sqrt(Math.max(0, p * p / 4 - q * q));
        double a2 = p / 2 + s;
        double b2 = Math.max(0, p / 2 - s);
        return new double[] {Math.sqrt(a2), Math.sqrt(b2)};
    }

    @Override
    public List<Vec2> sample(double chordMm) {
        // the deviation of a chord over parameter step dt is at most max|p''| dt^2 / 8, and
        // |p''(t)| = |p(t) - center| <= the major semi-axis
        double a = Math.max(majorRadius(), 1e-9);
        double dt = Math.sqrt(8 * chordMm / a);
        int n = Math.max(2, (int) Math.ceil(Math.abs(sweepRad) / dt));
        List<Vec2> out = new ArrayList<>(n);
        out.add(start);
        for (int k = 1; k < n; k++) {
            out.add(at(startRad + sweepRad * k / n));
        }
        return out;
    }
}
