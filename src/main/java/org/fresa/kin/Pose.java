package org.fresa.kin;

import org.fresa.geom.Transform3;

/**
 * Kernels on poses stored as 12 doubles, the rows of [R | t] (row-major 3x4), the hot-loop form
 * of {@link Transform3}. Package-private: the public API speaks Transform3.
 */
final class Pose {
    private Pose() {}

    static final int SIZE = 12;

    static void identity(double[] m, int o) {
        java.util.Arrays.fill(m, o, o + SIZE, 0);
        m[o] = 1;
        m[o + 5] = 1;
        m[o + 10] = 1;
    }

    static void fromTransform(Transform3 t, double[] m, int o) {
        m[o] = t.r00();
        m[o + 1] = t.r01();
        m[o + 2] = t.r02();
        m[o + 3] = t.tx();
        m[o + 4] = t.r10();
        m[o + 5] = t.r11();
        m[o + 6] = t.r12();
        m[o + 7] = t.ty();
        m[o + 8] = t.r20();
        m[o + 9] = t.r21();
        m[o + 10] = t.r22();
        m[o + 11] = t.tz();
    }

    static Transform3 toTransform(double[] m, int o) {
        return new Transform3(
                m[o], m[o + 1], m[o + 2], m[o + 4], m[o + 5], m[o + 6], m[o + 8], m[o + 9], m[o + 10], m[o + 3],
                m[o + 7], m[o + 11]);
    }

    /** c = a * b; c may not alias a or b. */
    static void mul(double[] a, int ao, double[] b, int bo, double[] c, int co) {
        for (int i = 0; i < 3; i++) {
            double x0 = a[ao + 4 * i];
            double x1 = a[ao + 4 * i + 1];
            double x2 = a[ao + 4 * i + 2];
            c[co + 4 * i] = x0 * b[bo] + x1 * b[bo + 4] + x2 * b[bo + 8];
            c[co + 4 * i + 1] = x0 * b[bo + 1] + x1 * b[bo + 5] + x2 * b[bo + 9];
            c[co + 4 * i + 2] = x0 * b[bo + 2] + x1 * b[bo + 6] + x2 * b[bo + 10];
            c[co + 4 * i + 3] = x0 * b[bo + 3] + x1 * b[bo + 7] + x2 * b[bo + 11] + a[ao + 4 * i + 3];
        }
    }

    /**
     * The pose error of current c against desired d: out[0..2] = p_d - p_c (mm), out[3..5] = the
     * rotation vector (axis times angle, rad, in the base frame) of R_d R_c^T. Exact for every
     * angle up to pi (the log map, with the pi case taken from the symmetric part).
     */
    static void error(double[] d, int dO, double[] c, int cO, double[] out) {
        out[0] = d[dO + 3] - c[cO + 3];
        out[1] = d[dO + 7] - c[cO + 7];
        out[2] = d[dO + 11] - c[cO + 11];
        // E = R_d R_c^T
        double e00 = 0;
        double e01 = 0;
        double e02 = 0;
        double e10 = 0;
        double e11 = 0;
        double e12 = 0;
        double e20 = 0;
        double e21 = 0;
        double e22 = 0;
        for (int k = 0; k < 3; k++) {
            double d0 = d[dO + k];
            double d1 = d[dO + 4 + k];
            double d2 = d[dO + 8 + k];
            double c0 = c[cO + k];
            double c1 = c[cO + 4 + k];
            double c2 = c[cO + 8 + k];
            e00 += d0 * c0;
            e01 += d0 * c1;
            e02 += d0 * c2;
            e10 += d1 * c0;
            e11 += d1 * c1;
            e12 += d1 * c2;
            e20 += d2 * c0;
            e21 += d2 * c1;
            e22 += d2 * c2;
        }
        double sx = e21 - e12;
        double sy = e02 - e20;
        double sz = e10 - e01;
        double s = Math.sqrt(sx * sx + sy * sy + sz * sz);
        double tr = e00 + e11 + e22 - 1;
        double angle = Math.atan2(s, tr);
        if (s > 1e-6) {
            double k = angle / s;
            out[3] = sx * k;
            out[4] = sy * k;
            out[5] = sz * k;
        } else if (tr > 0) {
            // small angle: angle/s -> 1/2
            out[3] = 0.5 * sx;
            out[4] = 0.5 * sy;
            out[5] = 0.5 * sz;
        } else {
            // angle near pi: axis from the diagonal of (E + I)/2 = u u^T
            double ux = Math.sqrt(Math.max(0, (e00 + 1) / 2));
            double uy = Math.sqrt(Math.max(0, (e11 + 1) / 2));
            double uz = Math.sqrt(Math.max(0, (e22 + 1) / 2));
            if (ux >= uy && ux >= uz) {
                uy = Math.copySign(uy, e01 + e10);
                uz = Math.copySign(uz, e02 + e20);
            } else if (uy >= uz) {
                ux = Math.copySign(ux, e01 + e10);
                uz = Math.copySign(uz, e12 + e21);
            } else {
                ux = Math.copySign(ux, e02 + e20);
                uy = Math.copySign(uy, e12 + e21);
            }
            double n = Math.sqrt(ux * ux + uy * uy + uz * uz);
            out[3] = ux / n * angle;
            out[4] = uy / n * angle;
            out[5] = uz / n * angle;
        }
    }
}
