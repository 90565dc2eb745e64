package org.fresa.geom;

/**
 * A point or vector in the plane, in millimetres. Immutable; every operation returns a new value.
 *
 * @param x abscissa in mm
 * @param y ordinate in mm
 */
public record Vec2(double x, double y) {

    public static final Vec2 ZERO = new Vec2(0, 0);
    public static final Vec2 UNIT_X = new Vec2(1, 0);
    public static final Vec2 UNIT_Y = new Vec2(0, 1);

    public Vec2 {
        Checks.finite(x, "x");
        Checks.finite(y, "y");
    }

    public static Vec2 of(double x, double y) {
        return new Vec2(x, y);
    }

    /** The unit vector at the given angle from the x axis (radians, counter-clockwise positive). */
    public static Vec2 ofAngle(double angleRad) {
        return new Vec2(Math.cos(angleRad), Math.sin(angleRad));
    }

    public Vec2 plus(Vec2 o) {
        return new Vec2(x + o.x, y + o.y);
    }

    public Vec2 minus(Vec2 o) {
        return new Vec2(x - o.x, y - o.y);
    }

    public Vec2 times(double s) {
        return new Vec2(x * s, y * s);
    }

    public Vec2 negated() {
        return new Vec2(-x, -y);
    }

    public double dot(Vec2 o) {
        return x * o.x + y * o.y;
    }

    /** The z component of the cross product: positive when o is counter-clockwise from this. */
    public double cross(Vec2 o) {
        return x * o.y - y * o.x;
    }

    public double norm() {
        return Math.hypot(x, y);
    }

    public double distance(Vec2 o) {
        return Math.hypot(x - o.x, y - o.y);
    }

    /** The angle from the x axis in radians, in (-pi, pi]. */
    public double angleRad() {
        return Math.atan2(y, x);
    }

    /**
     * This vector scaled to length 1.
     *
     * @throws IllegalArgumentException for the zero vector
     */
    public Vec2 normalized() {
        double n = norm();
        if (n == 0) {
            throw new IllegalArgumentException("cannot normalise the zero vector");
        }
        return new Vec2(x / n, y / n);
    }

    /** This vector turned 90 degrees counter-clockwise: the left normal of a direction. */
    public Vec2 leftNormal() {
        return new Vec2(-y, x);
    }

    /** This vector rotated counter-clockwise by the angle (radians) about the origin. */
    public Vec2 rotated(double angleRad) {
        double c = Math.cos(angleRad);
        double s = Math.sin(angleRad);
        return new Vec2(c * x - s * y, s * x + c * y);
    }

    /** The point a fraction t of the way from this to end (t = 0 gives this, 1 gives end). */
    public Vec2 interpolate(Vec2 end, double t) {
        return new Vec2(x + (end.x - x) * t, y + (end.y - y) * t);
    }

    /** True when the two points are within tol.linear() of each other. */
    public boolean eq(Vec2 o, Tolerance tol) {
        return distance(o) <= tol.linear();
    }

    /**
     * The record's own equality (each component by {@link Double#compare}) and hash (the same
     * 31-polynomial), written out: the generated ones are bootstrapped through method handles,
     * which spins classes at start-up (as {@link Vec3}'s: docs/performance.md, "Fast paths").
     */
    @Override
    public boolean equals(Object other) {
        return other instanceof Vec2 o && Double.compare(x, o.x) == 0 && Double.compare(y, o.y) == 0;
    }

    @Override
    public int hashCode() {
        int h = Double.hashCode(x);
        h = 31 * h + Double.hashCode(y);
        return h;
    }
}
