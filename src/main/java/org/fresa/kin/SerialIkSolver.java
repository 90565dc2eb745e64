package org.fresa.kin;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.fresa.geom.Transform3;

/**
 * Numerical inverse kinematics of a DH chain: Levenberg-Marquardt (default) or the thesis's
 * damped least squares, see {@link IkOptions.Method}. All work buffers are allocated once; the
 * iteration loop allocates nothing.
 */
final class SerialIkSolver implements IkSolver {

    /** Random extra starts for a cold solve, after the thesis's five and mid-range. */
    private static final int RANDOM_STARTS = 24;
    /** Two solutions closer than this (rad or mm, per joint) are the same. */
    private static final double SAME_SOLUTION = 1e-6;
    /** A closed-form joint value this far beyond a limit (rad or mm) is on it: rounding, not reach. */
    private static final double LIMIT_ROUNDING = 1e-9;

    private final DenavitHartenbergChain chain;
    private final IkOptions options;
    private final int n;
    /** Orientation rows are scaled by this length so that mm and rad weigh alike. */
    private final double rotWeight;

    private final double[][] starts;
    /** Closed-form start configurations for arms built like the IRB-140. */
    private final java.util.Optional<ClosedFormSeeds> closedForm;

    private final double[] target = new double[Pose.SIZE];
    private final double[] f;
    private final double[] e = new double[6];
    private final double[] et = new double[6];
    private final double[] j;
    private final double[] aMat;
    private final double[] lMat;
    private final double[] g;
    private final double[] dq;
    private final double[] q;
    private final double[] qt;
    private final Diagonal limitDamping = this::jointLimitDamping;
    private int lastIterations;
    private double lastPos;
    private double lastRot;

    SerialIkSolver(DenavitHartenbergChain chain, IkOptions options) {
        this.chain = chain;
        this.options = options;
        this.n = chain.n;
        double reach = 0;
        for (int i = 0; i < n; i++) {
            reach += Math.abs(chain.a[i]) + (chain.revolute[i] ? Math.abs(chain.d[i]) : 0);
        }
        rotWeight = options.method() == IkOptions.Method.THESIS_DLS ? 1 : Math.max(100, reach / 2);
        f = new double[chain.frameBufferSize()];
        j = new double[6 * n];
        aMat = new double[n * n];
        lMat = new double[n * n];
        g = new double[n];
        dq = new double[n];
        q = new double[n];
        qt = new double[n];
        starts = startConfigurations();
        closedForm = options.method() == IkOptions.Method.LEVENBERG_MARQUARDT
                ? ClosedFormSeeds.of(chain)
                : java.util.Optional.empty();
    }

    private double[][] startConfigurations() {
        List<double[]> s = new ArrayList<>();
        double[] max = new double[n];
        double[] min = new double[n];
        double[] mid = new double[n];
        double[] pos = new double[n];
        double[] neg = new double[n];
        for (int i = 0; i < n; i++) {
            max[i] = chain.qMax[i];
            min[i] = chain.qMin[i];
            mid[i] = (chain.qMax[i] + chain.qMin[i]) / 2;
            // "mid value of the positive part" and "of the negative part" of the range
            pos[i] = (Math.max(0, chain.qMin[i]) + chain.qMax[i]) / 2;
            neg[i] = (chain.qMin[i] + Math.min(0, chain.qMax[i])) / 2;
        }
        // the thesis's five, in its order
        s.add(max);
        s.add(min);
        s.add(mid);
        s.add(pos);
        s.add(neg);
        if (options.method() == IkOptions.Method.LEVENBERG_MARQUARDT) {
            SplittableRandom rnd = new SplittableRandom(20160229L);
            for (int k = 0; k < RANDOM_STARTS; k++) {
                double[] r = new double[n];
                for (int i = 0; i < n; i++) {
                    // inside the inner 90 % so that a start is not pinned at a limit
                    double lo = chain.qMin[i] + 0.05 * (chain.qMax[i] - chain.qMin[i]);
                    double hi = chain.qMax[i] - 0.05 * (chain.qMax[i] - chain.qMin[i]);
                    r[i] = lo + rnd.nextDouble() * (hi - lo);
                }
                s.add(r);
            }
        }
        return s.toArray(new double[0][]);
    }

    @Override
    public IkResult solve(Transform3 targetPose, double[] seed) {
        Pose.fromTransform(targetPose, target, 0);
        if (seed.length != n) {
            throw new IllegalArgumentException("expected " + n + " seed values, got " + seed.length);
        }
        for (int i = 0; i < n; i++) {
            q[i] = clamp(i, chain.revolute[i] ? Math.toRadians(seed[i]) : seed[i]);
        }
        boolean ok = run();
        if (!ok && options.method() == IkOptions.Method.THESIS_DLS) {
            // the thesis falls back to its five guesses when the previous solution fails
            int spent = lastIterations;
            IkResult r = solveCold(targetPose);
            return addIterations(r, spent);
        }
        return result(ok, lastIterations);
    }

    private static IkResult addIterations(IkResult r, int extra) {
        if (r instanceof IkResult.Converged c) {
            return new IkResult.Converged(c.q(), c.posErrMm(), c.rotErrRad(), c.iterations() + extra);
        }
        IkResult.Unreachable u = (IkResult.Unreachable) r;
        return new IkResult.Unreachable(u.reason(), u.posErrMm(), u.rotErrRad(), u.iterations() + extra);
    }

    private IkResult result(boolean ok, int iterations) {
        if (ok) {
            return new IkResult.Converged(chain.toUser(q), lastPos, lastRot, iterations);
        }
        return new IkResult.Unreachable(
                "did not converge within the joint limits from the start configuration", lastPos, lastRot, iterations);
    }

    /**
     * The closed form first, where the arm has one: its solutions within the joint limits are
     * polished (and so checked) and, when any converges, they are the answer; the generic starts
     * run only when the closed form finds nothing (a pose at the edge of the workspace, a chain
     * the closed form does not fit).
     */
    @Override
    public List<IkResult.Converged> solveAll(Transform3 targetPose) {
        if (closedForm.isPresent()) {
            SolutionSet found = closedFormSolutions(targetPose);
            if (!found.isEmpty()) {
                return found.sorted();
            }
        }
        return solveAllFromStarts(targetPose);
    }

    /**
     * The closed form's polished solutions only, where the arm has one: a pose the closed form
     * finds nothing for is taken as out of reach, without the generic starts (390 us of CPU for
     * such an IRB-140 pose, against a few us for the closed form).
     */
    @Override
    public List<IkResult.Converged> solveAllQuickly(Transform3 targetPose) {
        return closedForm.isPresent() ? closedFormSolutions(targetPose).sorted() : solveAll(targetPose);
    }

    private SolutionSet closedFormSolutions(Transform3 targetPose) {
        Pose.fromTransform(targetPose, target, 0);
        SolutionSet found = new SolutionSet(chain, SAME_SOLUTION);
        int spent = 0;
        for (double[] s : closedForm.get().seeds(target)) {
            if (!withinLimits(s)) {
                continue;
            }
            for (int i = 0; i < n; i++) {
                q[i] = clamp(i, s[i]);
            }
            boolean ok = run();
            spent += lastIterations;
            if (ok) {
                // the other whole turns of a joint give the same pose: no need to polish them again
                found.add(q, lastPos, lastRot, spent);
            }
        }
        return found;
    }

    /** Whether closed-form joint values (internal units) lie within the limits, up to rounding. */
    private boolean withinLimits(double[] s) {
        for (int i = 0; i < n; i++) {
            if (!(s[i] >= chain.qMin[i] - LIMIT_ROUNDING && s[i] <= chain.qMax[i] + LIMIT_ROUNDING)) {
                return false;
            }
        }
        return true;
    }

    /**
     * Every start: the closed form's solutions (clamped into the limits) and the generic starts,
     * which stop six after the closed form's once anything converged. The search {@link #solveAll}
     * did before it trusted the closed form; kept as the reference its tests compare against.
     */
    List<IkResult.Converged> solveAllFromStarts(Transform3 targetPose) {
        Pose.fromTransform(targetPose, target, 0);
        SolutionSet found = new SolutionSet(chain, SAME_SOLUTION);
        int spent = 0;
        List<double[]> seeds = new ArrayList<>();
        if (closedForm.isPresent()) {
            seeds.addAll(closedForm.get().seeds(target));
        }
        int closedFormSeeds = seeds.size();
        seeds.addAll(java.util.Arrays.asList(starts));
        for (int k = 0; k < seeds.size(); k++) {
            if (k == closedFormSeeds + 6 && !found.isEmpty() && closedFormSeeds > 0) {
                break; // the closed form found the branches: the random starts add nothing
            }
            double[] s = seeds.get(k);
            System.arraycopy(s, 0, q, 0, n);
            for (int i = 0; i < n; i++) {
                q[i] = clamp(i, q[i]);
            }
            boolean ok = run();
            spent += lastIterations;
            if (!ok) {
                continue;
            }
            if (options.method() == IkOptions.Method.THESIS_DLS) {
                found.addWithoutTurns(q, lastPos, lastRot, spent);
                break; // the thesis keeps the first guess that converges
            }
            found.add(q, lastPos, lastRot, spent);
        }
        return found.sorted();
    }

    private double clamp(int i, double v) {
        return Math.min(chain.qMax[i], Math.max(chain.qMin[i], v));
    }

    /** Iterates from q (internal units) in place; true when converged. */
    private boolean run() {
        return options.method() == IkOptions.Method.LEVENBERG_MARQUARDT ? levenbergMarquardt() : thesisDls();
    }

    private double evaluate(double[] qq, double[] err) {
        chain.frames(qq, f);
        Pose.error(target, 0, f, (n + 1) * Pose.SIZE, err);
        double p2 = err[0] * err[0] + err[1] * err[1] + err[2] * err[2];
        double r2 = err[3] * err[3] + err[4] * err[4] + err[5] * err[5];
        return 0.5 * (p2 + rotWeight * rotWeight * r2);
    }

    private boolean converged(double[] err) {
        lastPos = Math.sqrt(err[0] * err[0] + err[1] * err[1] + err[2] * err[2]);
        lastRot = Math.sqrt(err[3] * err[3] + err[4] * err[4] + err[5] * err[5]);
        return lastPos <= options.posTolMm() && lastRot <= options.rotTolRad();
    }

    private boolean levenbergMarquardt() {
        double energy = evaluate(q, e);
        double mu = 1e-12;
        int maxIt = options.maxIterations();
        double checkpoint = energy;
        for (int it = 0; it < maxIt; it++) {
            if (converged(e)) {
                lastIterations = it;
                return true;
            }
            if (it % 10 == 9) {
                // a local minimum away from the target (an unreachable pose): stop early
                if (energy > 0.9 * checkpoint) {
                    lastIterations = it;
                    return false;
                }
                checkpoint = energy;
            }
            chain.jacobian(f, j, rotWeight);
            normalEquations(e);
            double diagMax = 0;
            for (int i = 0; i < n; i++) {
                diagMax = Math.max(diagMax, aMat[i * n + i]);
            }
            boolean accepted = false;
            for (int retry = 0; retry < 12 && !accepted; retry++) {
                double lambda = energy + mu * diagMax;
                if (!solveDamped(lambda, null)) {
                    mu = Math.max(mu * 10, 1e-9);
                    continue;
                }
                for (int i = 0; i < n; i++) {
                    qt[i] = clamp(i, q[i] + dq[i]);
                }
                double et2 = evaluate(qt, et);
                if (et2 < energy) {
                    System.arraycopy(qt, 0, q, 0, n);
                    System.arraycopy(et, 0, e, 0, 6);
                    energy = et2;
                    mu = Math.max(mu * 0.1, 1e-15);
                    accepted = true;
                } else {
                    mu = Math.max(mu * 10, 1e-9);
                }
            }
            if (!accepted) {
                // no descent in any damping: a local minimum (or the floor of double precision)
                chain.frames(q, f);
                lastIterations = it + 1;
                return converged(e);
            }
        }
        lastIterations = maxIt;
        return converged(e);
    }

    private boolean thesisDls() {
        double sp = options.posTolMm();
        double sr = options.rotTolRad();
        int maxIt = options.maxIterations();
        for (int it = 0; it < maxIt; it++) {
            evaluate(q, e);
            if (converged(e)) {
                lastIterations = it;
                return true;
            }
            // eq. 26: halve a component that is above its threshold
            if (lastPos > sp) {
                e[0] *= 0.5;
                e[1] *= 0.5;
                e[2] *= 0.5;
            }
            if (lastRot > sr) {
                e[3] *= 0.5;
                e[4] *= 0.5;
                e[5] *= 0.5;
            }
            chain.jacobian(f, j, 1);
            normalEquations(e);
            if (!solveDamped(1e-12, limitDamping)) {
                lastIterations = it + 1;
                return false;
            }
            for (int i = 0; i < n; i++) {
                double v = q[i] + dq[i];
                // the 75 % rule, as the thesis states it (limits +-180, 181 -> -135)
                if (v > chain.qMax[i]) {
                    v = 0.75 * chain.qMin[i];
                } else if (v < chain.qMin[i]) {
                    v = 0.75 * chain.qMax[i];
                }
                q[i] = clamp(i, v);
            }
        }
        evaluate(q, e);
        lastIterations = maxIt;
        return converged(e);
    }

    /** Eq. 19 squared: lambda_i = c ((2 q - max - min) / (max - min))^p, c = 0.5, p = 8. */
    private double jointLimitDamping(int i) {
        double x = (2 * q[i] - chain.qMax[i] - chain.qMin[i]) / (chain.qMax[i] - chain.qMin[i]);
        double x2 = x * x;
        double x8 = x2 * x2 * x2 * x2;
        double l = 0.5 * x8;
        return l * l;
    }

    /** aMat = J^T J (lower triangle and diagonal), g = J^T e with the weighted orientation rows. */
    private void normalEquations(double[] err) {
        double w = rotWeight;
        for (int c = 0; c < n; c++) {
            double s = 0;
            for (int r = 0; r < 3; r++) {
                s += j[r * n + c] * err[r];
            }
            for (int r = 3; r < 6; r++) {
                s += j[r * n + c] * err[r] * w;
            }
            g[c] = s;
            for (int k = 0; k <= c; k++) {
                double t = 0;
                for (int r = 0; r < 6; r++) {
                    t += j[r * n + c] * j[r * n + k];
                }
                aMat[c * n + k] = t;
            }
        }
    }

    /** A per-joint diagonal term. */
    private interface Diagonal {
        double of(int i);
    }

    /** dq = (A + lambda I + D)^-1 g by Cholesky; false when not positive definite. */
    private boolean solveDamped(double lambda, Diagonal extra) {
        for (int c = 0; c < n; c++) {
            for (int k = 0; k <= c; k++) {
                double v = aMat[c * n + k];
                if (k == c) {
                    v += lambda + (extra == null ? 0 : extra.of(c));
                }
                for (int m = 0; m < k; m++) {
                    v -= lMat[c * n + m] * lMat[k * n + m];
                }
                if (k == c) {
                    if (!(v > 0)) {
                        return false;
                    }
                    lMat[c * n + c] = Math.sqrt(v);
                } else {
                    lMat[c * n + k] = v / lMat[k * n + k];
                }
            }
        }
        for (int c = 0; c < n; c++) {
            double v = g[c];
            for (int m = 0; m < c; m++) {
                v -= lMat[c * n + m] * dq[m];
            }
            dq[c] = v / lMat[c * n + c];
        }
        for (int c = n - 1; c >= 0; c--) {
            double v = dq[c];
            for (int m = c + 1; m < n; m++) {
                v -= lMat[m * n + c] * dq[m];
            }
            dq[c] = v / lMat[c * n + c];
        }
        return true;
    }
}
