package org.fresa.kin;

/**
 * An independent forward kinematics written straight from spec/robots.md with plain 4x4 matrices,
 * sharing no code with the main package: the oracle of the acceptance tests.
 */
final class SpecKinematics {
    private SpecKinematics() {}

    static double[][] dh(double thetaDeg, double d, double a, double alphaDeg) {
        double t = Math.toRadians(thetaDeg);
        double al = Math.toRadians(alphaDeg);
        double ct = Math.cos(t);
        double st = Math.sin(t);
        double ca = Math.cos(al);
        double sa = Math.sin(al);
        return new double[][] {
            {ct, -st * ca, st * sa, a * ct},
            {st, ct * ca, -ct * sa, a * st},
            {0, sa, ca, d},
            {0, 0, 0, 1}
        };
    }

    static double[][] mul(double[][] x, double[][] y) {
        double[][] r = new double[4][4];
        for (int i = 0; i < 4; i++) {
            for (int j = 0; j < 4; j++) {
                for (int k = 0; k < 4; k++) {
                    r[i][j] += x[i][k] * y[k][j];
                }
            }
        }
        return r;
    }

    /** IRB-140 flange pose, q in degrees, per the spec table. */
    static double[][] irb140(double[] q) {
        double[][] t = dh(q[0], 352, 70, -90);
        t = mul(t, dh(q[1] - 90, 0, 360, 0));
        t = mul(t, dh(q[2], 0, 0, -90));
        t = mul(t, dh(q[3], 380, 0, 90));
        t = mul(t, dh(q[4] + 180, 0, 0, 90));
        return mul(t, dh(q[5], 65, 0, 0));
    }

    /** Adept One tool pose: q1, q2, q4 in degrees, q3 in mm. */
    static double[][] adeptOne(double[] q) {
        double[][] t = dh(q[0], 1060.45, 424.942, 0);
        t = mul(t, dh(q[1], 0, 374.904, 180));
        t = mul(t, dh(0, q[2], 0, 0));
        return mul(t, dh(q[3], 183.642, 0, 0));
    }

    /** The legs of the spec's Tricept for a wrist centre w. */
    static double[] triceptLegs(double[] w) {
        double n = Math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        double[] u = {w[0] / n, w[1] / n, w[2] / n};
        double[] c = {u[0] * (n - 400), u[1] * (n - 400), u[2] * (n - 400)};
        double[] legs = new double[3];
        for (int k = 0; k < 3; k++) {
            double ang = Math.toRadians(90 + 120 * k);
            double[] a = {500 * Math.cos(ang), 500 * Math.sin(ang), 0};
            // B on the circle about C normal to u, in the plane of O, C, A: the direction of A's
            // projection on the platform plane
            double along = a[0] * u[0] + a[1] * u[1] + a[2] * u[2];
            double[] v = {a[0] - along * u[0], a[1] - along * u[1], a[2] - along * u[2]};
            double nv = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            double[] b = {c[0] + 200 * v[0] / nv, c[1] + 200 * v[1] / nv, c[2] + 200 * v[2] / nv};
            legs[k] = Math.sqrt(Math.pow(b[0] - a[0], 2) + Math.pow(b[1] - a[1], 2) + Math.pow(b[2] - a[2], 2));
        }
        return legs;
    }

    /** Tricept tool pose: legs in mm, wrist in degrees; W by damped Gauss-Newton from below. */
    static double[][] tricept(double[] q) {
        double[] w = {0, 0, -1800};
        for (int it = 0; it < 200; it++) {
            double[] l = triceptLegs(w);
            double[] f = {l[0] - q[0], l[1] - q[1], l[2] - q[2]};
            double[][] j = new double[3][3];
            for (int c = 0; c < 3; c++) {
                double[] wp = w.clone();
                wp[c] += 1e-5;
                double[] lp = triceptLegs(wp);
                for (int r = 0; r < 3; r++) {
                    j[r][c] = (lp[r] - l[r]) / 1e-5;
                }
            }
            double[] dw = solve3(j, f);
            for (int i = 0; i < 3; i++) {
                w[i] -= dw[i];
            }
        }
        double n = Math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        double[] z = {w[0] / n, w[1] / n, w[2] / n};
        double ang = Math.toRadians(90);
        double[] a1 = {500 * Math.cos(ang), 500 * Math.sin(ang), 0};
        double along = a1[0] * z[0] + a1[1] * z[1] + a1[2] * z[2];
        double[] x = {a1[0] - along * z[0], a1[1] - along * z[1], a1[2] - along * z[2]};
        double nx = Math.sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        x = new double[] {x[0] / nx, x[1] / nx, x[2] / nx};
        double[] y = {z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]};
        double[][] tw = {{x[0], y[0], z[0], w[0]}, {x[1], y[1], z[1], w[1]}, {x[2], y[2], z[2], w[2]}, {0, 0, 0, 1}};
        double[][] t = mul(tw, dh(q[3] + 90, 0, 0, -90));
        t = mul(t, dh(q[4] - 90, 0, 0, 90));
        return mul(t, dh(q[5] + 180, 250, 0, 0));
    }

    private static double[] solve3(double[][] m, double[] b) {
        double det = det3(m);
        double[] x = new double[3];
        for (int c = 0; c < 3; c++) {
            double[][] mc = {m[0].clone(), m[1].clone(), m[2].clone()};
            for (int r = 0; r < 3; r++) {
                mc[r][c] = b[r];
            }
            x[c] = det3(mc) / det;
        }
        return x;
    }

    private static double det3(double[][] m) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
                - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    }
}
