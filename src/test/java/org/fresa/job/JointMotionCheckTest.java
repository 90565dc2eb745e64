package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fresa.check.Failure;
import org.fresa.check.Limits;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.kin.Robot;
import org.fresa.kin.Robots;
import org.fresa.post.RobotProgram;
import org.junit.jupiter.api.Test;

/**
 * A robot's joint motion is judged where the robot takes the tool, not along the straight line
 * between its ends: the IRB-140 folding its elbow while it lifts its shoulder dips the tip between
 * two points at one height.
 */
class JointMotionCheckTest {

    static final Robot IRB140 = Robots.byName("irb140").orElseThrow();

    private static RobotProgram program(double[] q0, double[] q1) {
        List<RobotProgram.Joint> joints = IRB140.joints().stream()
                .map(j -> new RobotProgram.Joint(
                        j.name(), RobotProgram.JointType.valueOf(j.type().name()), j.min(), j.max()))
                .toList();
        return new RobotProgram("dip", "irb140", joints, List.of(motion(0, q0), motion(1, q1)));
    }

    private static RobotProgram.Motion motion(int index, double[] q) {
        return new RobotProgram.Motion(
                index,
                "WS",
                RobotProgram.MotionType.JOINT,
                RobotProgram.PointRole.PART,
                java.util.Arrays.stream(q).boxed().toList(),
                IRB140.forward(q),
                250,
                0,
                0,
                1000);
    }

    private static Optional<Failure> check(double[] q0, double[] q1, Limits.Stock stock) {
        return ProgramChecks.jointMotions(
                program(q0, q1),
                label -> IRB140,
                Transform3.IDENTITY,
                Limits.milling().withStock(stock),
                Map.of());
    }

    @Test
    void aJointMotionThatDipsBelowItsEndsIntoTheStockIsRefused() {
        // the elbow swings through 80 degrees with the shoulder leaning forward: the tip passes below both ends
        double[] up = {0, 80, -40, 0, 60, 0};
        double[] down = {0, 80, 40, 0, 60, 0};
        Vec3 a = IRB140.forward(up).translationPart();
        Vec3 b = IRB140.forward(down).translationPart();
        double lowest = Double.POSITIVE_INFINITY;
        Vec3 at = null;
        for (int k = 1; k < 60; k++) {
            double t = k / 60.0;
            double[] q = new double[6];
            for (int j = 0; j < 6; j++) {
                q[j] = up[j] + t * (down[j] - up[j]);
            }
            Vec3 p = IRB140.forward(q).translationPart();
            if (p.z() < lowest) {
                lowest = p.z();
                at = p;
            }
        }
        double ends = Math.min(a.z(), b.z());
        assertTrue(lowest < ends - 20, "the motion dips " + (ends - lowest) + " mm");
        // a block whose top is just above the ends, under the lowest point
        Limits.Stock block = new Limits.Stock(at.x() - 30, at.y() - 30, -1000, at.x() + 30, at.y() + 30, ends + 1);
        Failure f = check(up, down, block).orElseThrow();
        assertEquals("rapid", f.rule().name());
        assertEquals("motion 1", f.where());
        assertTrue(f.reason().contains("mm below the motion's ends"), f.reason());
        // the same motion over a block whose top is below the dip passes
        Limits.Stock lower = new Limits.Stock(at.x() - 30, at.y() - 30, -1000, at.x() + 30, at.y() + 30, lowest - 1);
        assertTrue(check(up, down, lower).isEmpty());
        // and a linear motion between the same ends is the toolpath check's, not this rule's
        assertTrue(ProgramChecks.jointMotions(
                        new RobotProgram(
                                "line",
                                "irb140",
                                program(up, down).joints(),
                                List.of(
                                        motion(0, up),
                                        new RobotProgram.Motion(
                                                1,
                                                "WS",
                                                RobotProgram.MotionType.LINEAR,
                                                RobotProgram.PointRole.PART,
                                                java.util.Arrays.stream(down)
                                                        .boxed()
                                                        .toList(),
                                                IRB140.forward(down),
                                                10,
                                                0,
                                                0,
                                                1000))),
                        label -> IRB140,
                        Transform3.IDENTITY,
                        Limits.milling().withStock(block),
                        Map.of())
                .isEmpty());
    }
}
