package org.fresa.geom;

/**
 * A point or vector in space, in millimetres. Immutable.
 *
 * @param x in mm
 * @param y in mm
 * @param z in mm
 */
public record Vec3(double x, double y, double z) {

    public static final Vec3 ZERO = new Vec3(0, 0, 0);
    public static final Vec3 UNIT_X = new Vec3(1, 0, 0);
    public static final Vec3 UNIT_Y = new Vec3(0, 1, 0);
    public static final Vec3 UNIT_Z = new Vec3(0, 0, 1);

    public Vec3 {
        Checks.finite(x, "x");
        Checks.finite(y, "y");
        Checks.finite(z, "z");
    }

    public static Vec3 of(double x, double y, double z) {
        return new Vec3(x, y, z);
    }

    /** The point (p.x, p.y, z). */
    public static Vec3 of(Vec2 p, double z) {
        return new Vec3(p.x(), p.y(), z);
    }

    public Vec2 xy() {
        return new Vec2(x, y);
    }

    public Vec3 plus(Vec3 o) {
        return new Vec3(x + o.x, y + o.y, z + o.z);
    }

    public Vec3 minus(Vec3 o) {
        return new Vec3(x - o.x, y - o.y, z - o.z);
    }

    public Vec3 times(double s) {
        return new Vec3(x * s, y * s, z * s);
    }

    public Vec3 negated() {
        return new Vec3(-x, -y, -z);
    }

    public double dot(Vec3 o) {
        return x * o.x + y * o.y + z * o.z;
    }

    public Vec3 cross(Vec3 o) {
        return new Vec3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x);
    }

    public double norm() {
        return Math.sqrt(x * x + y * y + z * z);
    }

    public double distance(Vec3 o) {
        return minus(o).norm();
    }

    /**
     * This vector scaled to length 1.
     *
     * @throws IllegalArgumentException for the zero vector
     */
    public Vec3 normalized() {
        double n = norm();
        if (n == 0) {
            throw new IllegalArgumentException("cannot normalise the zero vector");
        }
        return new Vec3(x / n, y / n, z / n);
    }

    public Vec3 interpolate(Vec3 end, double t) {
        return new Vec3(x + (end.x - x) * t, y + (end.y - y) * t, z + (end.z - z) * t);
    }

    public boolean eq(Vec3 o, Tolerance tol) {
        return distance(o) <= tol.linear();
    }

    /**
     * The record's own equality (each component by {@link Double#compare}) and hash (the same
     * 31-polynomial), written out: the generated ones are bootstrapped through method handles,
     * which spins classes at start-up: with -XDstringConcat=inline (pom.xml) the classes spun by
     * {@code fresa robot} fell from 139 to 60 (docs/performance.md, "Fast paths").
     */
    @Override
    public boolean equals(Object other) {
        return other instanceof Vec3 o
                && Double.compare(x, o.x) == 0
                && Double.compare(y, o.y) == 0
                && Double.compare(z, o.z) == 0;
    }

    @Override
    public int hashCode() {
        int h = Double.hashCode(x);
        h = 31 * h + Double.hashCode(y);
        h = 31 * h + Double.hashCode(z);
        return h;
    }
}
