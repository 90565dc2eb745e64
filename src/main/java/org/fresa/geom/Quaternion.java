package org.fresa.geom;

/**
 * A unit quaternion w + xi + yj + zk for a rotation, scalar first (the ABB robtarget order
 * q1..q4). The sign is chosen with w >= 0 so that equal rotations give equal quaternions.
 */
public record Quaternion(double w, double x, double y, double z) {

    public Quaternion {
        Checks.finite(w, "w");
        Checks.finite(x, "x");
        Checks.finite(y, "y");
        Checks.finite(z, "z");
    }

    /** The rotation part of a transform, by Shepperd's method (stable for every rotation). */
    public static Quaternion of(Transform3 t) {
        double trace = t.r00() + t.r11() + t.r22();
        double w;
        double x;
        double y;
        double z;
        if (trace > 0) {
            double s = 2 * Math.sqrt(1 + trace);
            w = 0.25 * s;
            x = (t.r21() - t.r12()) / s;
            y = (t.r02() - t.r20()) / s;
            z = (t.r10() - t.r01()) / s;
        } else if (t.r00() > t.r11() && t.r00() > t.r22()) {
            double s = 2 * Math.sqrt(1 + t.r00() - t.r11() - t.r22());
            w = (t.r21() - t.r12()) / s;
            x = 0.25 * s;
            y = (t.r01() + t.r10()) / s;
            z = (t.r02() + t.r20()) / s;
        } else if (t.r11() > t.r22()) {
            double s = 2 * Math.sqrt(1 + t.r11() - t.r00() - t.r22());
            w = (t.r02() - t.r20()) / s;
            x = (t.r01() + t.r10()) / s;
            y = 0.25 * s;
            z = (t.r12() + t.r21()) / s;
        } else {
            double s = 2 * Math.sqrt(1 + t.r22() - t.r00() - t.r11());
            w = (t.r10() - t.r01()) / s;
            x = (t.r02() + t.r20()) / s;
            y = (t.r12() + t.r21()) / s;
            z = 0.25 * s;
        }
        double n = Math.sqrt(w * w + x * x + y * y + z * z);
        double sign = w < 0 ? -1 : 1;
        return new Quaternion(sign * w / n, sign * x / n, sign * y / n, sign * z / n);
    }

    /** The rotation as a transform without translation. */
    public Transform3 toTransform() {
        double ww = w * w;
        double xx = x * x;
        double yy = y * y;
        double zz = z * z;
        return new Transform3(
                ww + xx - yy - zz,
                2 * (x * y - w * z),
                2 * (x * z + w * y),
                2 * (x * y + w * z),
                ww - xx + yy - zz,
                2 * (y * z - w * x),
                2 * (x * z - w * y),
                2 * (y * z + w * x),
                ww - xx - yy + zz,
                0,
                0,
                0);
    }
}
