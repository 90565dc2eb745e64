package org.fresa.geom;

/**
 * A rigid transform of space: a rotation followed by a translation, p' = R p + t. Lengths in mm.
 *
 * <p>Angles enter in degrees through the factories and follow the right-hand rule about the
 * named axis. {@link #ofXyzRpyDeg} builds R = Rz(rz) Ry(ry) Rx(rx), the convention of the
 * command-line placements and of the 2016 thesis's eq. 1.
 */
public record Transform3(
        double r00,
        double r01,
        double r02,
        double r10,
        double r11,
        double r12,
        double r20,
        double r21,
        double r22,
        double tx,
        double ty,
        double tz) {

    public static final Transform3 IDENTITY = new Transform3(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0);

    public Transform3 {
        double[] all = {r00, r01, r02, r10, r11, r12, r20, r21, r22, tx, ty, tz};
        for (double v : all) {
            Checks.finite(v, "transform entry");
        }
    }

    public static Transform3 translation(double x, double y, double z) {
        return new Transform3(1, 0, 0, 0, 1, 0, 0, 0, 1, x, y, z);
    }

    public static Transform3 rotX(double angleDeg) {
        double c = cosDeg(angleDeg);
        double s = sinDeg(angleDeg);
        return new Transform3(1, 0, 0, 0, c, -s, 0, s, c, 0, 0, 0);
    }

    public static Transform3 rotY(double angleDeg) {
        double c = cosDeg(angleDeg);
        double s = sinDeg(angleDeg);
        return new Transform3(c, 0, s, 0, 1, 0, -s, 0, c, 0, 0, 0);
    }

    public static Transform3 rotZ(double angleDeg) {
        double c = cosDeg(angleDeg);
        double s = sinDeg(angleDeg);
        return new Transform3(c, -s, 0, s, c, 0, 0, 0, 1, 0, 0, 0);
    }

    /** Translation (x, y, z) after the rotation Rz(rz) Ry(ry) Rx(rx); angles in degrees. */
    public static Transform3 ofXyzRpyDeg(double x, double y, double z, double rxDeg, double ryDeg, double rzDeg) {
        Transform3 r = rotZ(rzDeg).times(rotY(ryDeg)).times(rotX(rxDeg));
        return new Transform3(r.r00, r.r01, r.r02, r.r10, r.r11, r.r12, r.r20, r.r21, r.r22, x, y, z);
    }

    /**
     * A frame from its origin, its z axis and a reference direction for x (the ISO 10303
     * AXIS2_PLACEMENT_3D rule: x is the reference direction made normal to z).
     *
     * @throws IllegalArgumentException when the axis is zero or parallel to the reference
     */
    public static Transform3 ofFrame(Vec3 origin, Vec3 axis, Vec3 refDirection) {
        Vec3 z = axis.normalized();
        Vec3 xr = refDirection.minus(z.times(refDirection.dot(z)));
        if (xr.norm() < 1e-12) {
            throw new IllegalArgumentException("reference direction parallel to the axis");
        }
        Vec3 x = xr.normalized();
        Vec3 y = z.cross(x);
        return new Transform3(
                x.x(), y.x(), z.x(), x.y(), y.y(), z.y(), x.z(), y.z(), z.z(), origin.x(), origin.y(), origin.z());
    }

    // exact values at multiples of 90 degrees keep placements like RX = -90 free of 6e-17 noise
    private static double cosDeg(double a) {
        double m = ((a % 360) + 360) % 360;
        if (m == 0) {
            return 1;
        }
        if (m == 90 || m == 270) {
            return 0;
        }
        if (m == 180) {
            return -1;
        }
        return Math.cos(Math.toRadians(a));
    }

    private static double sinDeg(double a) {
        double m = ((a % 360) + 360) % 360;
        if (m == 0 || m == 180) {
            return 0;
        }
        if (m == 90) {
            return 1;
        }
        if (m == 270) {
            return -1;
        }
        return Math.sin(Math.toRadians(a));
    }

    /** This transform after the other: (this * o)(p) = this(o(p)). */
    public Transform3 times(Transform3 o) {
        return new Transform3(
                r00 * o.r00 + r01 * o.r10 + r02 * o.r20,
                r00 * o.r01 + r01 * o.r11 + r02 * o.r21,
                r00 * o.r02 + r01 * o.r12 + r02 * o.r22,
                r10 * o.r00 + r11 * o.r10 + r12 * o.r20,
                r10 * o.r01 + r11 * o.r11 + r12 * o.r21,
                r10 * o.r02 + r11 * o.r12 + r12 * o.r22,
                r20 * o.r00 + r21 * o.r10 + r22 * o.r20,
                r20 * o.r01 + r21 * o.r11 + r22 * o.r21,
                r20 * o.r02 + r21 * o.r12 + r22 * o.r22,
                r00 * o.tx + r01 * o.ty + r02 * o.tz + tx,
                r10 * o.tx + r11 * o.ty + r12 * o.tz + ty,
                r20 * o.tx + r21 * o.ty + r22 * o.tz + tz);
    }

    public Vec3 applyToPoint(Vec3 p) {
        return new Vec3(
                r00 * p.x() + r01 * p.y() + r02 * p.z() + tx,
                r10 * p.x() + r11 * p.y() + r12 * p.z() + ty,
                r20 * p.x() + r21 * p.y() + r22 * p.z() + tz);
    }

    public Vec3 applyToDirection(Vec3 v) {
        return new Vec3(
                r00 * v.x() + r01 * v.y() + r02 * v.z(),
                r10 * v.x() + r11 * v.y() + r12 * v.z(),
                r20 * v.x() + r21 * v.y() + r22 * v.z());
    }

    public Transform3 inverse() {
        // R^T and -R^T t
        return new Transform3(
                r00,
                r10,
                r20,
                r01,
                r11,
                r21,
                r02,
                r12,
                r22,
                -(r00 * tx + r10 * ty + r20 * tz),
                -(r01 * tx + r11 * ty + r21 * tz),
                -(r02 * tx + r12 * ty + r22 * tz));
    }

    public Vec3 translationPart() {
        return new Vec3(tx, ty, tz);
    }

    public Vec3 xAxis() {
        return new Vec3(r00, r10, r20);
    }

    public Vec3 yAxis() {
        return new Vec3(r01, r11, r21);
    }

    public Vec3 zAxis() {
        return new Vec3(r02, r12, r22);
    }

    /**
     * The angle in radians of the rotation R_this^T R_other: how far apart two orientations are.
     * Computed with atan2 of the skew and symmetric parts, so it stays exact near zero (where
     * acos of the trace would lose half the digits).
     */
    public double rotationAngleTo(Transform3 o) {
        Transform3 a = new Transform3(r00, r10, r20, r01, r11, r21, r02, r12, r22, 0, 0, 0)
                .times(new Transform3(o.r00, o.r01, o.r02, o.r10, o.r11, o.r12, o.r20, o.r21, o.r22, 0, 0, 0));
        double sx = a.r21 - a.r12;
        double sy = a.r02 - a.r20;
        double sz = a.r10 - a.r01;
        double twoSin = Math.sqrt(sx * sx + sy * sy + sz * sz);
        double twoCos = a.r00 + a.r11 + a.r22 - 1;
        return Math.atan2(twoSin, twoCos);
    }

    /**
     * The rotation as Z-Y-X Euler angles in degrees, R = Rz(a) Ry(b) Rx(c), returned as
     * (a, b, c): roll, pitch, yaw of trajectory.csv and KUKA's A, B, C. b is in [-90, 90]; at
     * b = +-90 (gimbal lock) c is set to 0 and a carries the whole turn about z.
     */
    public Vec3 zyxAnglesDeg() {
        double b = Math.atan2(-r20, Math.hypot(r00, r10));
        double a;
        double c;
        if (Math.hypot(r00, r10) < 1e-12) {
            c = 0;
            a = Math.atan2(-r01, r11);
        } else {
            a = Math.atan2(r10, r00);
            c = Math.atan2(r21, r22);
        }
        return new Vec3(Math.toDegrees(a), Math.toDegrees(b), Math.toDegrees(c));
    }

    public boolean eq(Transform3 o, Tolerance tol) {
        return translationPart().eq(o.translationPart(), tol) && rotationAngleTo(o) <= tol.angularRad();
    }

    /**
     * The record's own equality (each component by {@link Double#compare}) and hash (the same
     * 31-polynomial), written out: the generated ones are bootstrapped through method handles,
     * which spins classes at start-up (as {@link Vec3}'s: docs/performance.md, "Fast paths").
     */
    @Override
    public boolean equals(Object other) {
        return other instanceof Transform3 o
                && Double.compare(r00, o.r00) == 0
                && Double.compare(r01, o.r01) == 0
                && Double.compare(r02, o.r02) == 0
                && Double.compare(r10, o.r10) == 0
                && Double.compare(r11, o.r11) == 0
                && Double.compare(r12, o.r12) == 0
                && Double.compare(r20, o.r20) == 0
                && Double.compare(r21, o.r21) == 0
                && Double.compare(r22, o.r22) == 0
                && Double.compare(tx, o.tx) == 0
                && Double.compare(ty, o.ty) == 0
                && Double.compare(tz, o.tz) == 0;
    }

    @Override
    public int hashCode() {
        int h = Double.hashCode(r00);
        h = 31 * h + Double.hashCode(r01);
        h = 31 * h + Double.hashCode(r02);
        h = 31 * h + Double.hashCode(r10);
        h = 31 * h + Double.hashCode(r11);
        h = 31 * h + Double.hashCode(r12);
        h = 31 * h + Double.hashCode(r20);
        h = 31 * h + Double.hashCode(r21);
        h = 31 * h + Double.hashCode(r22);
        h = 31 * h + Double.hashCode(tx);
        h = 31 * h + Double.hashCode(ty);
        h = 31 * h + Double.hashCode(tz);
        return h;
    }
}
