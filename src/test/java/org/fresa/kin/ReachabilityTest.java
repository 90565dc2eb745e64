package org.fresa.kin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.junit.jupiter.api.Test;

class ReachabilityTest {

    private static final Robot IRB140 = Robots.irb140().withTool(Transform3.translation(0, 0, 200));

    /** Targets made by the forward kinematics of random joints within the limits: all reachable. */
    private static List<ToolTarget> reachableTargets(Robot robot, int count) {
        SplittableRandom rnd = new SplittableRandom(7);
        List<ToolTarget> out = new ArrayList<>();
        while (out.size() < count) {
            double[] q = new double[robot.dof()];
            for (int i = 0; i < q.length; i++) {
                JointLimit l = robot.joints().get(i);
                q[i] = l.min() + (0.1 + 0.8 * rnd.nextDouble()) * (l.max() - l.min());
            }
            Transform3 t = robot.forward(q);
            out.add(new ToolTarget("ws", t.translationPart(), t.zAxis(), t.xAxis()));
        }
        return out;
    }

    @Test
    void everyTargetMadeByTheForwardKinematicsIsReachedWithinTheTolerances() {
        List<ToolTarget> targets = reachableTargets(IRB140, 300);
        TrajectorySolver.Result r = new Reachability(IkOptions.DEFAULT, new ToolTurns(false, 180))
                .check(targets, l -> IRB140, () -> false)
                .orElseThrow();
        assertEquals(0, r.unreachable());
        assertEquals(targets.size(), r.points().size());
        for (TrajectoryPoint p : r.points()) {
            assertTrue(p.posErrMm() <= 1e-7 && p.rotErrRad() <= 1e-9, p.toString());
            assertTrue(
                    IRB140.forward(p.q()).translationPart().distance(p.target().translationPart()) <= 1e-7);
        }
    }

    @Test
    void targetsBeyondTheArmsReachAreUnreachableAndTheOthersStillReached() {
        List<ToolTarget> targets = new ArrayList<>(reachableTargets(IRB140, 20));
        targets.add(10, ToolTarget.of("far", new Vec3(3000, 0, 500), new Vec3(0, 0, -1)));
        targets.add(ToolTarget.of("far", new Vec3(0, 4000, 0), new Vec3(0, 0, -1)));
        TrajectorySolver.Result r = new Reachability(IkOptions.DEFAULT, new ToolTurns(true, 180))
                .check(targets, l -> IRB140, () -> false)
                .orElseThrow();
        assertEquals(2, r.unreachable());
        assertEquals(TrajectoryPoint.Status.UNREACHABLE, r.points().get(10).status());
        assertEquals(TrajectoryPoint.Status.OK, r.points().get(11).status());
    }

    @Test
    void theTriceptWithoutAClosedFormIsCheckedByItsSolver() {
        Robot t = Robots.tricept806();
        List<ToolTarget> targets = reachableTargets(t, 30);
        TrajectorySolver.Result r = new Reachability(IkOptions.DEFAULT, new ToolTurns(false, 180))
                .check(targets, l -> t, () -> false)
                .orElseThrow();
        assertEquals(0, r.unreachable());
    }

    @Test
    void aStaleCheckGivesNoAnswer() {
        assertTrue(new Reachability(IkOptions.DEFAULT, new ToolTurns(true, 180))
                .check(reachableTargets(IRB140, 10), l -> IRB140, () -> true)
                .isEmpty());
    }
}
