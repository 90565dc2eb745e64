package org.fresa.geom;

import java.util.Objects;

/**
 * A directed circular arc with exact end points, centre and sense. The radius and the angles
 * are derived, never stored: the end points are the truth, so chained arcs meet exactly.
 *
 * <p>When start equals end the arc is a full circle. A radius of zero is allowed: it is the
 * rounding arc that an exact offset puts at a reflex corner before the offset distance grows.
 *
 * @param center centre (mm)
 * @param start first point (mm)
 * @param end last point (mm), at the same distance from the centre as start (the factories check
 *     this within a tolerance)
 * @param ccw true for counter-clockwise travel (G03), false for clockwise (G02)
 */
public record Arc2(Vec2 center, Vec2 start, Vec2 end, boolean ccw) implements Curve2 {

    public Arc2 {
        Objects.requireNonNull(center, "center");
        Objects.requireNonNull(start, "start");
        Objects.requireNonNull(end, "end");
    }

    /**
     * A counter-clockwise arc.
     *
     * @throws IllegalArgumentException when start and end are not at the same radius within tol
     */
    public static Arc2 ccw(Vec2 center, Vec2 start, Vec2 end, Tolerance tol) {
        return of(center, start, end, true, tol);
    }

    /** A clockwise arc; see {@link #ccw}. */
    public static Arc2 cw(Vec2 center, Vec2 start, Vec2 end, Tolerance tol) {
        return of(center, start, end, false, tol);
    }

    /**
     * An arc with the given sense.
     *
     * @throws IllegalArgumentException when start and end are not at the same radius within tol
     */
    public static Arc2 of(Vec2 center, Vec2 start, Vec2 end, boolean ccw, Tolerance tol) {
        double r1 = center.distance(start);
        double r2 = center.distance(end);
        if (!tol.eq(r1, r2)) {
            throw new IllegalArgumentException("arc end radii differ: " + r1 + " and " + r2);
        }
        return new Arc2(center, start, end, ccw);
    }

    /** A full circle starting and ending at angle 0 (the point centre + (radius, 0)). */
    public static Arc2 circle(Vec2 center, double radius, boolean ccw) {
        if (!(radius > 0)) {
            throw new IllegalArgumentException("circle radius must be > 0: " + radius);
        }
        Vec2 p = center.plus(new Vec2(radius, 0));
        return new Arc2(center, p, p, ccw);
    }

    /** An arc from its centre, radius, start angle and signed sweep (radians, CCW positive). */
    public static Arc2 ofAngles(Vec2 center, double radius, double startAngleRad, double sweepRad) {
        Vec2 s = center.plus(Vec2.ofAngle(startAngleRad).times(radius));
        Vec2 e = center.plus(Vec2.ofAngle(startAngleRad + sweepRad).times(radius));
        return new Arc2(center, s, e, sweepRad >= 0);
    }

    /** Radius in mm, measured at the start point. */
    public double radius() {
        return center.distance(start);
    }

    public boolean isFullCircle() {
        return start.equals(end);
    }

    public double startAngleRad() {
        return start.minus(center).angleRad();
    }

    public double endAngleRad() {
        return end.minus(center).angleRad();
    }

    /** The signed sweep in radians: in (0, 2 pi] for CCW, in [-2 pi, 0) for CW. */
    public double sweepRad() {
        if (isFullCircle()) {
            return ccw ? 2 * Math.PI : -2 * Math.PI;
        }
        double d = endAngleRad() - startAngleRad();
        if (ccw) {
            while (d <= 0) {
                d += 2 * Math.PI;
            }
        } else {
            while (d >= 0) {
                d -= 2 * Math.PI;
            }
        }
        return d;
    }

    @Override
    public double length() {
        return radius() * Math.abs(sweepRad());
    }

    @Override
    public Arc2 reversed() {
        return new Arc2(center, end, start, !ccw);
    }

    @Override
    public Vec2 pointAt(double fraction) {
        if (fraction == 0) {
            return start;
        }
        if (fraction == 1) {
            return end;
        }
        return center.plus(Vec2.ofAngle(startAngleRad() + sweepRad() * fraction).times(radius()));
    }

    /** @throws IllegalArgumentException for a zero-radius arc, whose tangent is undefined */
    @Override
    public Vec2 startTangent() {
        Vec2 n = start.minus(center).normalized();
        return ccw ? n.leftNormal() : n.leftNormal().negated();
    }

    /** @throws IllegalArgumentException for a zero-radius arc, whose tangent is undefined */
    @Override
    public Vec2 endTangent() {
        Vec2 n = end.minus(center).normalized();
        return ccw ? n.leftNormal() : n.leftNormal().negated();
    }

    /** True when the direction from the centre at the given angle lies within the swept range. */
    public boolean containsAngle(double angleRad) {
        if (isFullCircle()) {
            return true;
        }
        double sweep = sweepRad();
        double d = angleRad - startAngleRad();
        if (sweep > 0) {
            d = mod2pi(d);
            return d <= sweep;
        }
        d = mod2pi(-d);
        return d <= -sweep;
    }

    private static double mod2pi(double a) {
        double r = a % (2 * Math.PI);
        return r < 0 ? r + 2 * Math.PI : r;
    }

    @Override
    public double areaContribution() {
        // chord triangle with the origin plus the circular segment between chord and arc
        double r = radius();
        double sweep = sweepRad();
        double segment = 0.5 * r * r * (sweep - Math.sin(sweep));
        return 0.5 * start.cross(end) + segment;
    }

    @Override
    public Box2 bounds() {
        Box2 b = Box2.of(start, end);
        double r = radius();
        for (int k = 0; k < 4; k++) {
            double a = k * Math.PI / 2;
            if (containsAngle(a)) {
                b = b.including(center.plus(Vec2.ofAngle(a).times(r)));
            }
        }
        return b;
    }

    @Override
    public Arc2 translated(Vec2 by) {
        return new Arc2(center.plus(by), start.plus(by), end.plus(by), ccw);
    }

    @Override
    public double distanceTo(Vec2 p) {
        Vec2 d = p.minus(center);
        if (d.norm() > 0 && containsAngle(d.angleRad())) {
            return Math.abs(d.norm() - radius());
        }
        return Math.min(p.distance(start), p.distance(end));
    }
}
