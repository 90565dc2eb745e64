package org.fresa.testing;

/**
 * Forward kinematics written from spec/robots.md alone, with plain 4x4 matrices, so that tests
 * check Fresa's kinematics against the contract and not against itself. Standard DH:
 * A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i); joints in deg (revolute) and mm.
 */
public final class SpecKinematics {

    private SpecKinematics() {}

    /** The IRB-140's flange pose (4x4, mm) for joints q1..q6 in deg, from the spec's table. */
    public static double[][] irb140(double... q) {
        double[][] rows = {
            // a, d, alpha, theta
            {70, 352, -90, q[0]},
            {360, 0, 0, q[1] - 90},
            {0, 0, -90, q[2]},
            {0, 380, 90, q[3]},
            {0, 0, 90, q[4] + 180},
            {0, 65, 0, q[5]},
        };
        double[][] t = identity();
        for (double[] r : rows) {
            t = times(t, dh(r[0], r[1], r[2], r[3]));
        }
        return t;
    }

    /** A_i = Rz(theta) Tz(d) Tx(a) Rx(alpha). */
    public static double[][] dh(double aMm, double dMm, double alphaDeg, double thetaDeg) {
        double ct = Math.cos(Math.toRadians(thetaDeg));
        double st = Math.sin(Math.toRadians(thetaDeg));
        double ca = Math.cos(Math.toRadians(alphaDeg));
        double sa = Math.sin(Math.toRadians(alphaDeg));
        return new double[][] {
            {ct, -st * ca, st * sa, aMm * ct},
            {st, ct * ca, -ct * sa, aMm * st},
            {0, sa, ca, dMm},
            {0, 0, 0, 1},
        };
    }

    /** A translation along z. */
    public static double[][] tz(double mm) {
        double[][] t = identity();
        t[2][3] = mm;
        return t;
    }

    /** R = Rz(roll) Ry(pitch) Rx(yaw), degrees (spec/cli.md, thesis eq. 1), at a position. */
    public static double[][] pose(double x, double y, double z, double rollDeg, double pitchDeg, double yawDeg) {
        double a = Math.toRadians(rollDeg);
        double b = Math.toRadians(pitchDeg);
        double g = Math.toRadians(yawDeg);
        double[][] rz = {{Math.cos(a), -Math.sin(a), 0, 0}, {Math.sin(a), Math.cos(a), 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}
        };
        double[][] ry = {{Math.cos(b), 0, Math.sin(b), 0}, {0, 1, 0, 0}, {-Math.sin(b), 0, Math.cos(b), 0}, {0, 0, 0, 1}
        };
        double[][] rx = {{1, 0, 0, 0}, {0, Math.cos(g), -Math.sin(g), 0}, {0, Math.sin(g), Math.cos(g), 0}, {0, 0, 0, 1}
        };
        double[][] t = times(rz, times(ry, rx));
        t[0][3] = x;
        t[1][3] = y;
        t[2][3] = z;
        return t;
    }

    /** Distance of the positions of two poses (mm). */
    public static double positionError(double[][] a, double[][] b) {
        return Math.sqrt(
                Math.pow(a[0][3] - b[0][3], 2) + Math.pow(a[1][3] - b[1][3], 2) + Math.pow(a[2][3] - b[2][3], 2));
    }

    /** The angle of R_a^T R_b (rad), from the trace and the skew part. */
    public static double rotationError(double[][] a, double[][] b) {
        double[][] m = new double[3][3];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                for (int k = 0; k < 3; k++) {
                    m[i][j] += a[k][i] * b[k][j];
                }
            }
        }
        double s = Math.hypot(Math.hypot(m[2][1] - m[1][2], m[0][2] - m[2][0]), m[1][0] - m[0][1]);
        return Math.atan2(s, m[0][0] + m[1][1] + m[2][2] - 1);
    }

    public static double[][] times(double[][] a, double[][] b) {
        double[][] c = new double[4][4];
        for (int i = 0; i < 4; i++) {
            for (int j = 0; j < 4; j++) {
                for (int k = 0; k < 4; k++) {
                    c[i][j] += a[i][k] * b[k][j];
                }
            }
        }
        return c;
    }

    public static double[][] identity() {
        double[][] t = new double[4][4];
        for (int i = 0; i < 4; i++) {
            t[i][i] = 1;
        }
        return t;
    }
}
