package org.fresa.kin;

import java.util.ArrayList;
import java.util.List;

/**
 * Closed-form inverse kinematics of SCARA arms built like the Adept One (RRPR; alpha = 0, 180, 0,
 * 0; a3 = a4 = 0): the flange stays vertical, its height gives the prismatic joint, the two arm
 * links a triangle (two elbows), and the turn of the flange about the vertical the last joint.
 * Up to 2 solutions before whole turns.
 *
 * <p>Without it a cold solve of the Adept One ran 29 numerical starts, 300 us of CPU per pose,
 * which made the placement search spend 11 of its 12 s on a 54-point part.
 */
final class ScaraSeeds implements ClosedFormSeeds {

    private static final double TWO_PI = 2 * Math.PI;

    private final DenavitHartenbergChain chain;
    private final double[] toolInverse = new double[Pose.SIZE];
    private final double[] fl = new double[Pose.SIZE];

    private ScaraSeeds(DenavitHartenbergChain c) {
        chain = c;
        Pose.fromTransform(c.tool().inverse(), toolInverse, 0);
    }

    /** The seeds for this chain, when it has the structure. */
    static java.util.Optional<ScaraSeeds> of(DenavitHartenbergChain c) {
        if (c.n != 4
                || !c.base().equals(org.fresa.geom.Transform3.IDENTITY)
                || !c.revolute[0]
                || !c.revolute[1]
                || c.revolute[2]
                || !c.revolute[3]) {
            return java.util.Optional.empty();
        }
        double[] alphaCos = {1, -1, 1, 1};
        for (int i = 0; i < 4; i++) {
            if (Math.abs(c.sa[i]) > 1e-15 || Math.abs(c.ca[i] - alphaCos[i]) > 1e-15) {
                return java.util.Optional.empty();
            }
        }
        if (c.a[2] != 0 || c.a[3] != 0 || !(c.a[0] > 0) || !(c.a[1] > 0)) {
            return java.util.Optional.empty();
        }
        return java.util.Optional.of(new ScaraSeeds(c));
    }

    @Override
    public List<double[]> seeds(double[] target) {
        Pose.mul(target, 0, toolInverse, 0, fl, 0);
        double x = fl[3];
        double y = fl[7];
        double z = fl[11];
        // flange x axis = (cos psi, sin psi, 0) with psi = t1 + t2 - t3 - t4 (the 180 deg twist of link 2)
        double psi = Math.atan2(fl[4], fl[0]);
        double a1 = chain.a[0];
        double a2 = chain.a[1];
        double c2 = (x * x + y * y - a1 * a1 - a2 * a2) / (2 * a1 * a2);
        List<double[]> out = new ArrayList<>(2);
        if (!(Math.abs(c2) <= 1)) {
            return out;
        }
        double d3 = chain.d[0] + chain.d[1] - chain.d[3] - z;
        for (int elbow = 0; elbow < 2; elbow++) {
            double t2 = elbow == 0 ? Math.acos(c2) : -Math.acos(c2);
            double t1 = Math.atan2(y, x) - Math.atan2(a2 * Math.sin(t2), a1 + a2 * Math.cos(t2));
            double t4 = t1 + t2 - chain.theta[2] - psi;
            double[] q = new double[4];
            q[0] = intoLimits(0, t1 - chain.theta[0]);
            q[1] = intoLimits(1, t2 - chain.theta[1]);
            q[2] = d3 - chain.d[2];
            q[3] = intoLimits(3, t4 - chain.theta[3]);
            out.add(q);
            if (c2 == 1 || c2 == -1) {
                break; // one elbow at the edge of the reach (or folded back)
            }
        }
        return out;
    }

    /** The whole-turn shift of v nearest mid-range that lies within the limits (or v itself). */
    private double intoLimits(int i, double v) {
        double mid = (chain.qMin[i] + chain.qMax[i]) / 2;
        double w = v + TWO_PI * Math.rint((mid - v) / TWO_PI);
        for (int k = -2; k <= 2; k++) {
            double t = w + k * TWO_PI;
            if (t >= chain.qMin[i] && t <= chain.qMax[i]) {
                return t;
            }
        }
        return w;
    }
}
