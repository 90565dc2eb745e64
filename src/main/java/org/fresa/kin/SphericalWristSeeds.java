package org.fresa.kin;

import java.util.ArrayList;
import java.util.List;

/**
 * Closed-form inverse kinematics of 6R arms built like the IRB-140 (alpha = -90, 0, -90, 90, 90, 0;
 * a3..a6 = 0; d2 = d3 = d5 = 0; any offsets): the wrist centre from the flange pose, q1 from its
 * direction (two ways), q3 from the law of cosines (two elbows), q2 by atan2, the wrist as ZYZ
 * Euler angles (two flips). Up to 8 solutions, each angle moved by whole turns into the limits
 * where it can be. Used as start configurations that the numerical solver polishes (and so checks).
 */
final class SphericalWristSeeds implements ClosedFormSeeds {

    private static final double TWO_PI = 2 * Math.PI;

    private final DenavitHartenbergChain chain;
    private final double a1;
    private final double d1;
    private final double a2;
    private final double d4;
    private final double d6;
    private final double[] toolInverse = new double[Pose.SIZE];

    private SphericalWristSeeds(DenavitHartenbergChain c) {
        chain = c;
        a1 = c.a[0];
        d1 = c.d[0];
        a2 = c.a[1];
        d4 = c.d[3];
        d6 = c.d[5];
        Pose.fromTransform(c.tool().inverse(), toolInverse, 0);
    }

    /** The seeds for this chain, when it has the structure. */
    static java.util.Optional<SphericalWristSeeds> of(DenavitHartenbergChain c) {
        if (c.n != 6 || !c.base().equals(org.fresa.geom.Transform3.IDENTITY)) {
            return java.util.Optional.empty();
        }
        double[] alphaSin = {-1, 0, -1, 1, 1, 0};
        for (int i = 0; i < 6; i++) {
            if (!c.revolute[i] || Math.abs(c.sa[i] - alphaSin[i]) > 1e-15 || (alphaSin[i] == 0 && c.ca[i] != 1)) {
                return java.util.Optional.empty();
            }
        }
        if (c.a[2] != 0
                || c.a[3] != 0
                || c.a[4] != 0
                || c.a[5] != 0
                || c.d[1] != 0
                || c.d[2] != 0
                || c.d[4] != 0
                || !(c.a[1] > 0)
                || !(c.d[3] > 0)) {
            return java.util.Optional.empty();
        }
        return java.util.Optional.of(new SphericalWristSeeds(c));
    }

    @Override
    public List<double[]> seeds(double[] target) {
        return solutions(target, false);
    }

    /** Joint values (internal units) of the closed-form solutions for a TCP pose (12 doubles). */
    List<double[]> solutions(double[] target) {
        return solutions(target, true);
    }

    /**
     * The closed-form solutions, each joint moved into its limits by whole turns where it can be,
     * with every other whole-turn variant within the limits too when {@code allTurns}.
     */
    List<double[]> solutions(double[] target, boolean allTurns) {
        return solutions(target, allTurns, Double.NaN);
    }

    /**
     * The closed-form solutions, each joint moved into its limits by whole turns where it can be,
     * that then lie within the limits up to {@code rounding} (rad or mm): those of {@link
     * #solutions(double[], boolean) solutions(target, false)} within the limits, in its order. The
     * wrist of a shoulder and elbow already out of their limits is not worked out.
     */
    List<double[]> solutionsWithinLimits(double[] target, double rounding) {
        return solutions(target, false, rounding);
    }

    /** As above; a NaN rounding keeps the solutions out of the limits too. */
    private List<double[]> solutions(double[] target, boolean allTurns, double rounding) {
        boolean within = !Double.isNaN(rounding);
        double[] fl = new double[Pose.SIZE];
        Pose.mul(target, 0, toolInverse, 0, fl, 0);
        double wx = fl[3] - d6 * fl[2];
        double wy = fl[7] - d6 * fl[6];
        double wz = fl[11] - d6 * fl[10];
        double rho = Math.hypot(wx, wy);
        List<double[]> out = new ArrayList<>();
        double[] f = new double[chain.frameBufferSize()];
        for (int shoulder = 0; shoulder < 2; shoulder++) {
            double t1 = Math.atan2(wy, wx) + (shoulder == 0 ? 0 : Math.PI);
            double u = (shoulder == 0 ? rho : -rho) - a1;
            double v = d1 - wz;
            double s3 = (a2 * a2 + d4 * d4 - u * u - v * v) / (2 * a2 * d4);
            if (Math.abs(s3) > 1) {
                continue;
            }
            for (int elbow = 0; elbow < 2; elbow++) {
                double t3 = elbow == 0 ? Math.asin(s3) : Math.PI - Math.asin(s3);
                double aa = a2 - d4 * Math.sin(t3);
                double bb = d4 * Math.cos(t3);
                double t2 = Math.atan2(v, u) - Math.atan2(bb, aa);
                double[] q = new double[6];
                q[0] = t1 - chain.theta[0];
                q[1] = t2 - chain.theta[1];
                q[2] = t3 - chain.theta[2];
                if (within && !armWithinLimits(q, rounding)) {
                    continue;
                }
                chain.frames(q, f, 3);
                // N = R3^T R_flange diag(1, -1, -1) = Rz(t4) Ry(-t5) Rz(-t6)
                int o = 3 * Pose.SIZE;
                double[] n = new double[9];
                for (int i = 0; i < 3; i++) {
                    for (int j = 0; j < 3; j++) {
                        double m = f[o + i] * fl[j] + f[o + 4 + i] * fl[4 + j] + f[o + 8 + i] * fl[8 + j];
                        n[3 * i + j] = j == 0 ? m : -m;
                    }
                }
                double sb = Math.hypot(n[2], n[5]);
                double b = Math.atan2(sb, n[8]);
                double a = sb > 1e-12 ? Math.atan2(n[5], n[2]) : 0;
                double c = sb > 1e-12 ? Math.atan2(n[7], -n[6]) : Math.atan2(n[3], n[0]) - a;
                for (int flip = 0; flip < 2; flip++) {
                    double[] s = q.clone();
                    double t4 = flip == 0 ? a : a + Math.PI;
                    double t5 = flip == 0 ? -b : b;
                    double t6 = flip == 0 ? -c : -c + Math.PI;
                    s[3] = t4 - chain.theta[3];
                    s[4] = t5 - chain.theta[4];
                    s[5] = t6 - chain.theta[5];
                    for (int i = 0; i < 6; i++) {
                        s[i] = intoLimits(i, s[i]);
                    }
                    if (allTurns) {
                        addTurns(s, 0, out);
                    } else if (!within || withinLimits(s, rounding)) {
                        out.add(s);
                    }
                }
            }
        }
        return out;
    }

    /**
     * Whether the first three joints of q, each moved into its limits as {@link #solutions} moves
     * it, lie within their limits up to rounding.
     */
    private boolean armWithinLimits(double[] q, double rounding) {
        for (int i = 0; i < 3; i++) {
            if (!within(i, intoLimits(i, q[i]), rounding)) {
                return false;
            }
        }
        return true;
    }

    private boolean withinLimits(double[] s, double rounding) {
        for (int i = 0; i < s.length; i++) {
            if (!within(i, s[i], rounding)) {
                return false;
            }
        }
        return true;
    }

    private boolean within(int i, double v, double rounding) {
        return v >= chain.qMin[i] - rounding && v <= chain.qMax[i] + rounding;
    }

    /** s and its whole-turn variants from joint {@code from} on, into out. */
    private void addTurns(double[] s, int from, List<double[]> out) {
        if (from == 6) {
            out.add(s);
            return;
        }
        addTurns(s, from + 1, out);
        for (int k = -2; k <= 2; k++) {
            double v = s[from] + k * TWO_PI;
            if (k != 0 && v >= chain.qMin[from] && v <= chain.qMax[from]) {
                double[] t = s.clone();
                t[from] = v;
                addTurns(t, from + 1, out);
            }
        }
    }

    /** The whole-turn shift of v nearest mid-range that lies within the limits (or v itself). */
    private double intoLimits(int i, double v) {
        double mid = (chain.qMin[i] + chain.qMax[i]) / 2;
        double w = v + TWO_PI * Math.rint((mid - v) / TWO_PI);
        for (int k = -2; k <= 2; k++) {
            double x = w + k * TWO_PI;
            if (x >= chain.qMin[i] && x <= chain.qMax[i]) {
                return x;
            }
        }
        return w;
    }
}
