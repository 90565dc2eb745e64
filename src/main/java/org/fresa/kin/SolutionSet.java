package org.fresa.kin;

import java.util.ArrayList;
import java.util.List;

/**
 * The distinct solutions of one cold solve, best joint-limit margin first. Each converged
 * configuration comes with its whole-turn variants within the limits (a revolute range wider than
 * a turn, as the IRB-140's axes 4 (+-200 deg) and 6 (+-400 deg), holds the same pose more than
 * once: the variants are different configurations for the controller, its cf4 and cf6, and the
 * trajectory needs the one nearest the previous point), so that the closed form and the search
 * from every start give the same set.
 *
 * <p>The cold solve's fast path: the margin of each solution is computed once (the sort compared
 * by recomputing it, 40 % of a cold pose's CPU time) and the variants of one configuration are
 * not compared with each other (a duplicate test of every pair was 20 %). Together they take the
 * cold IRB-140 pose of {@code fresa bench} from 5.2 to 3.6 us of CPU (median of 9 rounds, two
 * shared cores).
 */
final class SolutionSet {

    private static final double TWO_PI = 2 * Math.PI;

    private final DenavitHartenbergChain chain;
    private final double sameSolution;
    private final List<double[]> internal = new ArrayList<>();
    private final List<IkResult.Converged> found = new ArrayList<>();
    private double[] margins = new double[16];
    /** Where the variants of the configuration being added begin: they differ from each other by turns. */
    private int variantsFrom;

    /** @param sameSolution two solutions closer than this (rad or mm, per joint) are the same */
    SolutionSet(DenavitHartenbergChain chain, double sameSolution) {
        this.chain = chain;
        this.sameSolution = sameSolution;
    }

    boolean isEmpty() {
        return found.isEmpty();
    }

    /**
     * Adds q (internal units, within the limits) and its whole-turn variants within the limits,
     * those not already in the set.
     */
    void add(double[] q, double posErrMm, double rotErrRad, int iterations) {
        variantsFrom = internal.size();
        addTurns(q.clone(), 0, posErrMm, rotErrRad, iterations);
    }

    /** Adds q alone (the thesis's method keeps the one configuration it converged to). */
    void addWithoutTurns(double[] q, double posErrMm, double rotErrRad, int iterations) {
        variantsFrom = internal.size();
        addOne(q.clone(), posErrMm, rotErrRad, iterations);
    }

    private void addTurns(double[] s, int from, double pos, double rot, int iterations) {
        if (from == chain.n) {
            addOne(s, pos, rot, iterations);
            return;
        }
        addTurns(s, from + 1, pos, rot, iterations);
        if (!chain.revolute[from] || chain.qMax[from] - chain.qMin[from] < TWO_PI) {
            return;
        }
        for (int k = -2; k <= 2; k++) {
            double v = s[from] + k * TWO_PI;
            if (k != 0 && v >= chain.qMin[from] && v <= chain.qMax[from]) {
                double[] t = s.clone();
                t[from] = v;
                addTurns(t, from + 1, pos, rot, iterations);
            }
        }
    }

    private void addOne(double[] q, double pos, double rot, int iterations) {
        // the variants of one configuration differ by whole turns: only the earlier ones can be the same
        for (int k = 0; k < variantsFrom; k++) {
            if (same(internal.get(k), q)) {
                return;
            }
        }
        internal.add(q);
        IkResult.Converged c = new IkResult.Converged(chain.toUser(q), pos, rot, iterations);
        if (found.size() == margins.length) {
            margins = java.util.Arrays.copyOf(margins, 2 * margins.length);
        }
        margins[found.size()] = margin(c.q());
        found.add(c);
    }

    private boolean same(double[] a, double[] b) {
        for (int i = 0; i < a.length; i++) {
            if (!(Math.abs(a[i] - b[i]) < sameSolution)) {
                return false;
            }
        }
        return true;
    }

    /** The smallest distance to a limit over the joints, as a fraction of each joint's range. */
    private double margin(double[] qUser) {
        double m = Double.POSITIVE_INFINITY;
        List<DhJoint> js = chain.joints();
        for (int i = 0; i < qUser.length; i++) {
            DhJoint jt = js.get(i);
            m = Math.min(m, Math.min(qUser[i] - jt.qMin(), jt.qMax() - qUser[i]) / (jt.qMax() - jt.qMin()));
        }
        return m;
    }

    /** The solutions, largest margin first (the order of finding among equal margins). */
    List<IkResult.Converged> sorted() {
        int k = found.size();
        int[] order = new int[k];
        for (int i = 0; i < k; i++) {
            // insertion sort: stable, and a few dozen entries at most
            int j = i;
            while (j > 0 && margins[order[j - 1]] < margins[i]) {
                order[j] = order[j - 1];
                j--;
            }
            order[j] = i;
        }
        List<IkResult.Converged> out = new ArrayList<>(k);
        for (int i : order) {
            out.add(found.get(i));
        }
        return out;
    }
}
