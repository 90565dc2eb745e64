package org.fresa.kin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import java.util.SplittableRandom;
import org.fresa.geom.Transform3;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

class InverseKinematicsTest {

    static double[] tenDegreesAway(double[] q, List<JointLimit> limits) {
        double[] s = q.clone();
        for (int i = 0; i < s.length; i++) {
            double step = limits.get(i).type() == JointType.REVOLUTE ? 10 : 10;
            s[i] = q[i] + step <= limits.get(i).max() ? q[i] + step : q[i] - step;
        }
        return s;
    }

    @ParameterizedTest
    @EnumSource(IkOptions.Method.class)
    void theReferencePosesAreSolvedBackToTheirJointsFromTenDegreesAway(IkOptions.Method method) throws IOException {
        SerialRobot robot = Robots.irb140();
        IkOptions opts = method == IkOptions.Method.THESIS_DLS ? IkOptions.THESIS : IkOptions.DEFAULT;
        IkSolver solver = robot.newSolver(opts);
        for (double[] r : ForwardKinematicsTest.referenceRows()) {
            double[] q = {r[0], r[1], r[2], r[3], r[4], r[5]};
            Transform3 target = robot.forward(q);
            IkResult res = solver.solve(target, tenDegreesAway(q, robot.joints()));
            IkResult.Converged c =
                    assertInstanceOf(IkResult.Converged.class, res, () -> "pose " + java.util.Arrays.toString(q));
            assertTrue(c.posErrMm() <= 1e-7 && c.rotErrRad() <= 1e-9, c::toString);
            // at q5 = 0 the wrist is singular and only q4 + q6 is defined
            boolean singular = Math.abs(q[4]) < 1e-9;
            // q3 = -90 stretches the arm: the elbow-up and elbow-down twins meet, and from 10 deg
            // away the solver may land on the twin 0.01 deg off, an equally exact solution
            double jointTol = Math.abs(q[2] + 90) < 0.1 ? 0.05 : 1e-6;
            if (method == IkOptions.Method.LEVENBERG_MARQUARDT) {
                if (singular) {
                    assertEquals(q[3] + q[5], c.q()[3] + c.q()[5], 1e-6);
                }
                for (int i = 0; i < 6; i++) {
                    if (singular && (i == 3 || i == 5)) {
                        continue;
                    }
                    assertEquals(q[i], c.q()[i], jointTol, "joint " + (i + 1) + " of " + java.util.Arrays.toString(q));
                }
            }
            double[][] m = SpecKinematics.irb140(c.q());
            assertEquals(target.tx(), m[0][3], 1e-6);
            assertEquals(target.ty(), m[1][3], 1e-6);
            assertEquals(target.tz(), m[2][3], 1e-6);
        }
    }

    @Test
    void aColdSolveFindsRandomReachablePosesOfTheIrb140() {
        SerialRobot robot = Robots.irb140();
        IkSolver solver = robot.newSolver(IkOptions.DEFAULT);
        SplittableRandom rnd = new SplittableRandom(7);
        int solved = 0;
        for (int k = 0; k < 50; k++) {
            double[] q = new double[6];
            for (int i = 0; i < 6; i++) {
                JointLimit l = robot.joints().get(i);
                q[i] = l.min() + 0.05 * (l.max() - l.min()) + rnd.nextDouble() * 0.9 * (l.max() - l.min());
            }
            IkResult r = solver.solveCold(robot.forward(q));
            if (r instanceof IkResult.Converged c) {
                solved++;
                Transform3 t = robot.forward(c.q());
                assertTrue(t.translationPart().distance(robot.forward(q).translationPart()) < 1e-6);
            }
        }
        assertEquals(50, solved);
    }

    @Test
    void theTriceptIsSolvedInClosedFormAndCheckedByItsForwardKinematics() {
        TriceptRobot robot = Robots.tricept806();
        IkSolver solver = robot.newSolver(IkOptions.DEFAULT);
        IkSolver thesis = robot.newSolver(IkOptions.THESIS);
        SplittableRandom rnd = new SplittableRandom(11);
        for (int k = 0; k < 100; k++) {
            double[] q = {
                1300 + rnd.nextDouble() * 300,
                1300 + rnd.nextDouble() * 300,
                1300 + rnd.nextDouble() * 300,
                -150 + rnd.nextDouble() * 300,
                -100 + rnd.nextDouble() * 200,
                -300 + rnd.nextDouble() * 600
            };
            Transform3 target = robot.forward(q);
            double[] seed = q.clone();
            for (int i = 3; i < 6; i++) {
                seed[i] += 10;
            }
            IkResult.Converged c = assertInstanceOf(IkResult.Converged.class, solver.solve(target, seed));
            for (int i = 0; i < 6; i++) {
                assertEquals(q[i], c.q()[i], 1e-6);
            }
            ForwardKinematicsTest.assertSame(SpecKinematics.tricept(c.q()), target, 1e-6);
            IkResult.Converged t = assertInstanceOf(IkResult.Converged.class, thesis.solve(target, seed));
            ForwardKinematicsTest.assertSame(SpecKinematics.tricept(t.q()), target, 1e-6, 1e-8);
        }
    }

    @Test
    void theAdeptOneReachesAVerticalToolAndNotAHorizontalOne() {
        SerialRobot robot = Robots.adeptOne();
        IkSolver solver = robot.newSolver(IkOptions.DEFAULT);
        // tool axis down, x along +x: R = diag(1, -1, -1)
        Transform3 down = new Transform3(1, 0, 0, 0, -1, 0, 0, 0, -1, 400, 310, 800);
        IkResult.Converged c = assertInstanceOf(IkResult.Converged.class, solver.solveCold(down));
        ForwardKinematicsTest.assertSame(SpecKinematics.adeptOne(c.q()), down, 1e-6);
        Transform3 sideways = Transform3.ofFrame(
                new org.fresa.geom.Vec3(400, 310, 800), org.fresa.geom.Vec3.UNIT_Y, org.fresa.geom.Vec3.UNIT_X);
        assertInstanceOf(IkResult.Unreachable.class, solver.solveCold(sideways));
    }

    @Test
    void aTargetBeyondTheReachIsReportedUnreachable() {
        IkSolver solver = Robots.irb140().newSolver(IkOptions.DEFAULT);
        Transform3 far = Transform3.translation(2000, 0, 500);
        assertInstanceOf(IkResult.Unreachable.class, solver.solveCold(far));
        assertInstanceOf(IkResult.Unreachable.class, solver.solve(far, new double[6]));
        IkSolver tricept = Robots.tricept806().newSolver(IkOptions.DEFAULT);
        assertInstanceOf(IkResult.Unreachable.class, tricept.solveCold(Transform3.translation(0, 0, -3500)));
    }
}
