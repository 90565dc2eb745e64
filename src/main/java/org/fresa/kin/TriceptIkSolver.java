package org.fresa.kin;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.fresa.geom.Transform3;

/**
 * Inverse kinematics of a {@link TriceptRobot}: the wrist centre from the target (eq. 27), the
 * legs in closed form (eqs. 31-40), the wrist as ZYZ Euler angles in closed form (both branches,
 * each angle moved by whole turns to the seed's side) or, with {@link IkOptions.Method#THESIS_DLS},
 * numerically as the thesis did. The result is checked with the forward kinematics (Newton on the
 * legs), so a converged result is never a wrong pose.
 */
final class TriceptIkSolver implements IkSolver {

    private static final double TWO_PI = 2 * Math.PI;
    /** Below this |sin theta5| the wrist is taken as singular and q4 kept at the seed. */
    private static final double SINGULAR = 1e-10;

    private final TriceptRobot robot;
    private final IkOptions options;
    private final TriceptGeometry geo;
    private final double[] min = new double[6];
    private final double[] max = new double[6];
    /** The flange target: the TCP target times the inverse tool frame. */
    private final double[] target = new double[Pose.SIZE];

    private final double[] tcpTarget = new double[Pose.SIZE];
    private final double[] tool = new double[Pose.SIZE];
    private final double[] toolInverse = new double[Pose.SIZE];
    private final double[] tcpPose = new double[Pose.SIZE];
    private final double[] w = new double[3];
    private final double[] wv = new double[3];
    private final double[] legs = new double[3];
    private final double[] pose = new double[Pose.SIZE];
    private final double[] err = new double[6];
    private final double[] seedI = new double[6];
    private final double[] best = new double[6];
    private final double[] cand = new double[6];
    private final double[] rwSaved = new double[9];
    private String failure = "";
    private double lastPos;
    private double lastRot;

    TriceptIkSolver(TriceptRobot robot, IkOptions options) {
        this.robot = robot;
        this.options = options;
        this.geo = new TriceptGeometry(robot);
        Pose.fromTransform(robot.tool(), tool, 0);
        Pose.fromTransform(robot.tool().inverse(), toolInverse, 0);
        List<JointLimit> js = robot.joints();
        for (int i = 0; i < 6; i++) {
            boolean rev = js.get(i).type() == JointType.REVOLUTE;
            min[i] = rev ? Math.toRadians(js.get(i).min()) : js.get(i).min();
            max[i] = rev ? Math.toRadians(js.get(i).max()) : js.get(i).max();
        }
    }

    @Override
    public IkResult solve(Transform3 targetPose, double[] seed) {
        if (seed.length != 6) {
            throw new IllegalArgumentException("expected 6 seed values, got " + seed.length);
        }
        for (int i = 0; i < 6; i++) {
            seedI[i] = i < 3 ? seed[i] : Math.toRadians(seed[i]);
        }
        setTarget(targetPose);
        if (!solveInternal(false)) {
            return new IkResult.Unreachable(failure, lastPos, lastRot, 1);
        }
        return converged(best);
    }

    @Override
    public List<IkResult.Converged> solveAll(Transform3 targetPose) {
        setTarget(targetPose);
        List<IkResult.Converged> out = new ArrayList<>();
        // the wrist's two branches, from the middle of its range
        for (int branch = 0; branch < 2; branch++) {
            for (int i = 0; i < 6; i++) {
                seedI[i] = (min[i] + max[i]) / 2;
            }
            seedI[4] = branch == 0 ? Math.abs(seedI[4]) + 1 : -Math.abs(seedI[4]) - 1;
            if (solveInternal(true)) {
                IkResult.Converged c = converged(best);
                boolean dup = false;
                for (IkResult.Converged o : out) {
                    double dmax = 0;
                    for (int i = 0; i < 6; i++) {
                        dmax = Math.max(dmax, Math.abs(o.q()[i] - c.q()[i]));
                    }
                    dup |= dmax < 1e-6;
                }
                if (!dup) {
                    out.add(c);
                }
            }
        }
        out.sort(Comparator.comparingDouble((IkResult.Converged c) -> -margin(c.q())));
        return out;
    }

    private void setTarget(Transform3 tcp) {
        Pose.fromTransform(tcp, tcpTarget, 0);
        Pose.mul(tcpTarget, 0, toolInverse, 0, target, 0);
    }

    private double margin(double[] qUser) {
        double m = Double.POSITIVE_INFINITY;
        List<JointLimit> js = robot.joints();
        for (int i = 0; i < 6; i++) {
            m = Math.min(m, js.get(i).margin(qUser[i]));
        }
        return m;
    }

    private IkResult.Converged converged(double[] qi) {
        double[] u = new double[6];
        for (int i = 0; i < 6; i++) {
            u[i] = i < 3 ? qi[i] : Math.toDegrees(qi[i]);
        }
        return new IkResult.Converged(u, lastPos, lastRot, 1);
    }

    /** The solution nearest the seed into best; false (with a reason) when there is none. */
    private boolean solveInternal(boolean branchFromSeed) {
        double zx = target[2];
        double zy = target[6];
        double zz = target[10];
        double effl = geo.effectorLength();
        w[0] = target[3] - effl * zx;
        w[1] = target[7] - effl * zy;
        w[2] = target[11] - effl * zz;
        lastPos = Double.NaN;
        lastRot = Double.NaN;
        if (!geo.legs(w, legs)) {
            failure = "wrist centre not below the platform";
            return false;
        }
        for (int k = 0; k < 3; k++) {
            if (legs[k] < min[k] || legs[k] > max[k]) {
                failure = String.format(
                        java.util.Locale.ROOT,
                        "leg %d would be %.3f mm, outside %.0f..%.0f mm",
                        k + 1,
                        legs[k],
                        min[k],
                        max[k]);
                return false;
            }
        }
        System.arraycopy(geo.rw, 0, rwSaved, 0, 9);
        boolean found =
                options.method() == IkOptions.Method.THESIS_DLS ? wristNumerical() : wristClosedForm(branchFromSeed);
        if (!found) {
            failure = "the wrist cannot reach the orientation within its limits";
            return false;
        }
        // check with the forward kinematics: W from the legs (Newton), then the wrist
        if (!geo.wristCentre(best[0], best[1], best[2], w, wv)) {
            failure = "forward kinematics of the legs does not assemble";
            return false;
        }
        geo.pose(wv, best[3], best[4], best[5], pose);
        // checked at the TCP, where the tolerance is asked
        Pose.mul(pose, 0, tool, 0, tcpPose, 0);
        Pose.error(tcpTarget, 0, tcpPose, 0, err);
        lastPos = Math.sqrt(err[0] * err[0] + err[1] * err[1] + err[2] * err[2]);
        lastRot = Math.sqrt(err[3] * err[3] + err[4] * err[4] + err[5] * err[5]);
        if (lastPos > options.posTolMm() || lastRot > options.rotTolRad()) {
            failure = "residual above tolerance";
            return false;
        }
        return true;
    }

    private boolean wristClosedForm(boolean unused) {
        // M = R_w^T R_target = Rz(t4) Ry(t5) Rz(t6)
        double[] r = rwSaved;
        double[] m = new double[9];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                m[3 * i + j] = r[i] * target[j] + r[3 + i] * target[4 + j] + r[6 + i] * target[8 + j];
            }
        }
        double sb = Math.sqrt(m[2] * m[2] + m[5] * m[5]);
        double cb = m[8];
        best[0] = legs[0];
        best[1] = legs[1];
        best[2] = legs[2];
        double bestCost = Double.POSITIVE_INFINITY;
        if (sb > SINGULAR) {
            double t5 = Math.atan2(sb, cb);
            double t4 = Math.atan2(m[5], m[2]);
            double t6 = Math.atan2(m[7], -m[6]);
            bestCost = Math.min(bestCost, candidate(t4, t5, t6, bestCost));
            bestCost = Math.min(bestCost, candidate(t4 + Math.PI, -t5, t6 + Math.PI, bestCost));
        } else {
            double t4 = seedI[3] + Math.PI / 2;
            if (cb > 0) {
                double sum = Math.atan2(m[3], m[0]);
                bestCost = Math.min(bestCost, candidate(t4, 0, sum - t4, bestCost));
            } else {
                double phi = Math.atan2(-m[3], -m[0]);
                bestCost = Math.min(bestCost, candidate(t4, Math.PI, t4 - phi, bestCost));
                bestCost = Math.min(bestCost, candidate(t4, -Math.PI, t4 - phi, bestCost));
            }
        }
        return bestCost < Double.POSITIVE_INFINITY;
    }

    /** Converts DH angles to q, moves each by whole turns towards the seed, keeps it if nearer. */
    private double candidate(double t4, double t5, double t6, double bestCost) {
        cand[3] = t4 - Math.PI / 2;
        cand[4] = t5 + Math.PI / 2;
        cand[5] = t6 - Math.PI;
        double cost = 0;
        for (int i = 3; i < 6; i++) {
            double v = cand[i] + TWO_PI * Math.rint((seedI[i] - cand[i]) / TWO_PI);
            // the nearest turn may be outside the limits while another is inside
            if (v > max[i]) {
                v -= TWO_PI;
            } else if (v < min[i]) {
                v += TWO_PI;
            }
            if (v < min[i] || v > max[i]) {
                return Double.POSITIVE_INFINITY;
            }
            cand[i] = v;
            cost += (v - seedI[i]) * (v - seedI[i]);
        }
        if (cost < bestCost) {
            System.arraycopy(cand, 3, best, 3, 3);
            return cost;
        }
        return bestCost;
    }

    private boolean wristNumerical() {
        Transform3 frame = new Transform3(
                rwSaved[0],
                rwSaved[1],
                rwSaved[2],
                rwSaved[3],
                rwSaved[4],
                rwSaved[5],
                rwSaved[6],
                rwSaved[7],
                rwSaved[8],
                w[0],
                w[1],
                w[2]);
        DenavitHartenbergChain wrist = robot.wristChain(frame);
        SerialIkSolver s = new SerialIkSolver(wrist, options);
        Transform3 t = Pose.toTransform(target, 0);
        IkResult r =
                s.solve(t, new double[] {Math.toDegrees(seedI[3]), Math.toDegrees(seedI[4]), Math.toDegrees(seedI[5])});
        if (!(r instanceof IkResult.Converged c)) {
            return false;
        }
        best[0] = legs[0];
        best[1] = legs[1];
        best[2] = legs[2];
        for (int i = 0; i < 3; i++) {
            best[3 + i] = Math.toRadians(c.q()[i]);
        }
        return true;
    }
}
