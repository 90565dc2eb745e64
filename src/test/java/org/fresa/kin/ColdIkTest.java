package org.fresa.kin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.fresa.geom.Transform3;
import org.junit.jupiter.api.Test;

/** The cold solve that trusts the closed form finds the same solutions as the search from every start. */
class ColdIkTest {

    static final double SAME_DEG = 1e-5;

    static List<Transform3> randomPoses(SerialRobot r, int count, long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        List<JointLimit> js = r.joints();
        List<Transform3> out = new ArrayList<>();
        for (int k = 0; k < count; k++) {
            double[] q = new double[6];
            for (int i = 0; i < 6; i++) {
                q[i] = js.get(i).min()
                        + rnd.nextDouble() * (js.get(i).max() - js.get(i).min());
            }
            out.add(r.forward(q));
        }
        return out;
    }

    static boolean contains(List<IkResult.Converged> set, double[] q) {
        for (IkResult.Converged c : set) {
            double d = 0;
            for (int i = 0; i < q.length; i++) {
                d = Math.max(d, Math.abs(c.q()[i] - q[i]));
            }
            if (d < SAME_DEG) {
                return true;
            }
        }
        return false;
    }

    @Test
    void theClosedFormFindsExactlyTheSolutionsTheSearchFromEveryStartFinds() {
        // both give every whole-turn variant within the limits (axes 4 and 6 of the IRB-140):
        // the same sets, best margin first, each solution within the limits and on the pose
        SerialRobot irb = Robots.irb140();
        SerialIkSolver solver = (SerialIkSolver) irb.newSolver(IkOptions.DEFAULT);
        int solutions = 0;
        for (Transform3 t : randomPoses(irb, 400, 20261202L)) {
            List<IkResult.Converged> fast = solver.solveAll(t);
            List<IkResult.Converged> every = solver.solveAllFromStarts(t);
            assertTrue(!fast.isEmpty());
            assertEquals(every.size(), fast.size(), () -> "for " + t);
            for (IkResult.Converged c : every) {
                assertTrue(contains(fast, c.q()), () -> "missing " + java.util.Arrays.toString(c.q()) + " for " + t);
            }
            for (IkResult.Converged c : fast) {
                assertTrue(contains(every, c.q()), () -> "extra " + java.util.Arrays.toString(c.q()) + " for " + t);
                Transform3 reached = irb.forward(c.q());
                assertTrue(reached.translationPart().distance(t.translationPart()) <= 1e-7, c::toString);
                assertTrue(t.rotationAngleTo(reached) <= 1e-9, c::toString);
                for (int i = 0; i < 6; i++) {
                    JointLimit l = irb.joints().get(i);
                    assertTrue(c.q()[i] >= l.min() && c.q()[i] <= l.max(), c::toString);
                }
            }
            for (int k = 1; k < fast.size(); k++) {
                assertTrue(
                        margin(irb, fast.get(k - 1).q())
                                >= margin(irb, fast.get(k).q()),
                        "best margin first");
            }
            solutions += fast.size();
        }
        // axes 4 and 6 turn more than a full turn: most poses have several variants of a branch
        assertTrue(solutions > 4 * 400, solutions + " solutions");
    }

    @Test
    void theScarasClosedFormFindsExactlyTheSolutionsOfTheSearchFromEveryStart() {
        SerialRobot adept = Robots.adeptOne();
        SerialIkSolver solver = (SerialIkSolver) adept.newSolver(IkOptions.DEFAULT);
        SplittableRandom rnd = new SplittableRandom(4L);
        int solutions = 0;
        for (int k = 0; k < 300; k++) {
            double[] q = new double[4];
            for (int i = 0; i < 4; i++) {
                JointLimit l = adept.joints().get(i);
                q[i] = l.min() + rnd.nextDouble() * (l.max() - l.min());
            }
            Transform3 t = adept.forward(q);
            List<IkResult.Converged> fast = solver.solveAll(t);
            List<IkResult.Converged> every = solver.solveAllFromStarts(t);
            assertTrue(contains(fast, q), () -> "the pose's own joints are missing for " + t);
            assertEquals(every.size(), fast.size(), () -> "for " + t);
            for (IkResult.Converged c : every) {
                assertTrue(contains(fast, c.q()), () -> "missing " + java.util.Arrays.toString(c.q()));
            }
            solutions += fast.size();
        }
        assertTrue(solutions > 300, solutions + " solutions");
    }

    @Test
    void theQuickSolveIsTheClosedFormsSetAndNothingOutOfReach() {
        SerialRobot irb = Robots.irb140();
        IkSolver solver = irb.newSolver(IkOptions.DEFAULT);
        for (Transform3 t : randomPoses(irb, 100, 7L)) {
            assertEquals(solver.solveAll(t).size(), solver.solveAllQuickly(t).size());
        }
        assertEquals(
                0, solver.solveAllQuickly(Transform3.translation(2000, 0, 0)).size());
    }

    static double margin(SerialRobot r, double[] q) {
        double m = Double.POSITIVE_INFINITY;
        for (int i = 0; i < q.length; i++) {
            m = Math.min(m, r.joints().get(i).margin(q[i]));
        }
        return m;
    }

    @Test
    void aPoseOutOfReachFindsNothing() {
        SerialIkSolver solver = (SerialIkSolver) Robots.irb140().newSolver(IkOptions.DEFAULT);
        assertEquals(0, solver.solveAll(Transform3.translation(2000, 0, 0)).size());
    }
}
