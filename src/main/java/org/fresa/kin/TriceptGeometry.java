package org.fresa.kin;

/**
 * The Tricept's parallel part and wrist on primitive buffers: leg lengths from the wrist centre
 * (closed form, eqs. 31-40), the wrist centre from leg lengths (Newton), the wrist frame and the
 * tool pose. One instance per thread.
 */
final class TriceptGeometry {

    private static final double HALF_PI = Math.PI / 2;

    private final double rp;
    private final double deff;
    private final double effl;
    private final double[] ax = new double[3];
    private final double[] ay = new double[3];
    /** The wrist frame from the last {@link #legs} call: rows of R_w (x, y, z columns). */
    final double[] rw = new double[9];

    private final double[] lt = new double[3];
    private final double[] wt = new double[3];
    private final double[] jm = new double[9];

    TriceptGeometry(TriceptRobot r) {
        rp = r.platformRadiusMm();
        deff = r.centreOffsetMm();
        effl = r.effectorLengthMm();
        for (int k = 0; k < 3; k++) {
            ax[k] = r.legBase(k).x();
            ay[k] = r.legBase(k).y();
        }
    }

    double effectorLength() {
        return effl;
    }

    /**
     * Leg lengths for wrist centre w into legs, and the wrist frame into {@link #rw}; false when
     * W is not below the platform offset (|OW| <= d_eff) or a leg plane is degenerate.
     */
    boolean legs(double[] w, double[] legs) {
        double nw = Math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        if (!(nw > deff)) {
            return false;
        }
        double ux = w[0] / nw;
        double uy = w[1] / nw;
        double uz = w[2] / nw;
        double cs = nw - deff;
        double cx = cs * ux;
        double cy = cs * uy;
        double cz = cs * uz;
        for (int k = 0; k < 3; k++) {
            // the part of OA_k normal to OC: B_k lies on A_k's side of the line OC
            double dot = ax[k] * ux + ay[k] * uy;
            double vx = ax[k] - dot * ux;
            double vy = ay[k] - dot * uy;
            double vz = -dot * uz;
            double nv = Math.sqrt(vx * vx + vy * vy + vz * vz);
            if (!(nv > 1e-9)) {
                return false;
            }
            vx /= nv;
            vy /= nv;
            vz /= nv;
            double bx = cx + rp * vx - ax[k];
            double by = cy + rp * vy - ay[k];
            double bz = cz + rp * vz;
            legs[k] = Math.sqrt(bx * bx + by * by + bz * bz);
            if (k == 0) {
                // wrist frame: x = v_1, z = u, y = z x x (stored row-major)
                rw[0] = vx;
                rw[3] = vy;
                rw[6] = vz;
                rw[2] = ux;
                rw[5] = uy;
                rw[8] = uz;
                rw[1] = uy * vz - uz * vy;
                rw[4] = uz * vx - ux * vz;
                rw[7] = ux * vy - uy * vx;
            }
        }
        return true;
    }

    /**
     * Solves legs(W) = (l1, l2, l3) for W by Newton's method with a finite-difference Jacobian,
     * from guess (or below the base when null). False when it does not converge to 1e-11 mm.
     */
    boolean wristCentre(double l1, double l2, double l3, double[] guess, double[] w) {
        if (guess != null) {
            System.arraycopy(guess, 0, w, 0, 3);
        } else {
            double lm = (l1 + l2 + l3) / 3;
            double rb = Math.hypot(ax[0], ay[0]);
            double dr = rb - rp;
            w[0] = 0;
            w[1] = 0;
            w[2] = -(Math.sqrt(Math.max(lm * lm - dr * dr, 1)) + deff);
        }
        double[] target = {l1, l2, l3};
        for (int it = 0; it < 50; it++) {
            if (!legs(w, lt)) {
                return false;
            }
            double f0 = lt[0] - target[0];
            double f1 = lt[1] - target[1];
            double f2 = lt[2] - target[2];
            double res = Math.max(Math.abs(f0), Math.max(Math.abs(f1), Math.abs(f2)));
            if (res <= 1e-11) {
                legs(w, lt); // leaves rw for w
                return true;
            }
            double h = 1e-4;
            for (int c = 0; c < 3; c++) {
                System.arraycopy(w, 0, wt, 0, 3);
                wt[c] += h;
                double[] lp = new double[3];
                if (!legs(wt, lp)) {
                    return false;
                }
                wt[c] -= 2 * h;
                double[] lmn = new double[3];
                if (!legs(wt, lmn)) {
                    return false;
                }
                for (int r = 0; r < 3; r++) {
                    jm[r * 3 + c] = (lp[r] - lmn[r]) / (2 * h);
                }
            }
            // w -= J^-1 f (Cramer)
            double det = jm[0] * (jm[4] * jm[8] - jm[5] * jm[7])
                    - jm[1] * (jm[3] * jm[8] - jm[5] * jm[6])
                    + jm[2] * (jm[3] * jm[7] - jm[4] * jm[6]);
            if (Math.abs(det) < 1e-12) {
                return false;
            }
            double[] fv = {f0, f1, f2};
            for (int c = 0; c < 3; c++) {
                double[] m = jm.clone();
                for (int r = 0; r < 3; r++) {
                    m[r * 3 + c] = fv[r];
                }
                double dc = m[0] * (m[4] * m[8] - m[5] * m[7])
                        - m[1] * (m[3] * m[8] - m[5] * m[6])
                        + m[2] * (m[3] * m[7] - m[4] * m[6]);
                wt[c] = dc / det;
            }
            w[0] -= wt[0];
            w[1] -= wt[1];
            w[2] -= wt[2];
        }
        return false;
    }

    /**
     * The tool pose for wrist centre w (with {@link #rw} set for it) and wrist joints q4..q6 in
     * radians (the robot's convention, offsets added here).
     */
    void pose(double[] w, double q4, double q5, double q6, double[] out) {
        legs(w, lt);
        double t4 = q4 + HALF_PI;
        double t5 = q5 - HALF_PI;
        double t6 = q6 + Math.PI;
        double c4 = Math.cos(t4);
        double s4 = Math.sin(t4);
        double c5 = Math.cos(t5);
        double s5 = Math.sin(t5);
        double c6 = Math.cos(t6);
        double s6 = Math.sin(t6);
        // M = Rz(t4) Ry(t5) Rz(t6)
        double m00 = c4 * c5 * c6 - s4 * s6;
        double m01 = -c4 * c5 * s6 - s4 * c6;
        double m02 = c4 * s5;
        double m10 = s4 * c5 * c6 + c4 * s6;
        double m11 = -s4 * c5 * s6 + c4 * c6;
        double m12 = s4 * s5;
        double m20 = -s5 * c6;
        double m21 = s5 * s6;
        double m22 = c5;
        double[] m = {m00, m01, m02, m10, m11, m12, m20, m21, m22};
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                out[4 * r + c] = rw[3 * r] * m[c] + rw[3 * r + 1] * m[3 + c] + rw[3 * r + 2] * m[6 + c];
            }
            out[4 * r + 3] = w[r] + effl * out[4 * r + 2];
        }
    }
}
