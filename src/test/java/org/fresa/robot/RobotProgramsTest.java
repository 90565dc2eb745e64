package org.fresa.robot;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fresa.geom.Transform3;
import org.fresa.kin.Robots;
import org.fresa.post.RapidWriter;
import org.fresa.post.RobotProgram;
import org.junit.jupiter.api.Test;

class RobotProgramsTest {

    static RobotProgram.Motion at(double... q) {
        return new RobotProgram.Motion(
                0,
                "ws",
                RobotProgram.MotionType.LINEAR,
                RobotProgram.PointRole.PART,
                java.util.Arrays.stream(q).boxed().toList(),
                Transform3.IDENTITY,
                1,
                0,
                0,
                0);
    }

    @Test
    void irb140HomeIsFrontAndUpperArm() {
        RapidWriter.ArmGeometry arm = RobotPrograms.armGeometry(Robots.irb140());
        RobotProgram.Motion home = at(0, 0, 0, 0, 0, 0);
        assertAll(() -> assertFalse(arm.rear(home)), () -> assertFalse(arm.lowerArm(home)));
    }

    @Test
    void irb140ReachingOverItsBaseIsRear() {
        RapidWriter.ArmGeometry arm = RobotPrograms.armGeometry(Robots.irb140());
        // shoulder tilted back 80 deg with the forearm folded up and back: wrist behind axis 1
        assertTrue(arm.rear(at(0, -80, -60, 0, 0, 0)));
        // the same pose turned half a revolution about axis 1 is still rear in axis 1's own frame
        assertTrue(arm.rear(at(180, -80, -60, 0, 0, 0)));
    }

    @Test
    void irb140ElbowFoldedPastTheShoulderLineIsLowerArm() {
        RapidWriter.ArmGeometry arm = RobotPrograms.armGeometry(Robots.irb140());
        assertTrue(arm.lowerArm(at(0, 0, -200, 0, 0, 0)));
        assertFalse(arm.lowerArm(at(0, 30, 40, 0, 0, 0)));
    }

    @Test
    void scaraHasNeitherRearNorLowerArm() {
        RapidWriter.ArmGeometry arm = RobotPrograms.armGeometry(Robots.adeptOne());
        RobotProgram.Motion m = at(100, -120, 50, 0);
        assertAll(() -> assertFalse(arm.rear(m)), () -> assertFalse(arm.lowerArm(m)));
    }

    @Test
    void relinksAndWorkingstepStartsAreJointMotions() {
        var irb = Robots.irb140();
        Transform3 pose = irb.forward(0, 10, 20, 0, 30, 0);
        List<org.fresa.kin.TrajectoryPoint> points = List.of(
                new org.fresa.kin.TrajectoryPoint(
                        "A",
                        pose,
                        org.fresa.kin.TrajectoryPoint.Status.OK,
                        new double[] {0, 10, 20, 0, 30, 0},
                        java.util.Optional.of(pose),
                        0,
                        0,
                        0,
                        false),
                new org.fresa.kin.TrajectoryPoint(
                        "A",
                        pose,
                        org.fresa.kin.TrajectoryPoint.Status.OK,
                        new double[] {0, 10, 20, 0, 30, 0},
                        java.util.Optional.of(pose),
                        0,
                        0,
                        0,
                        false),
                new org.fresa.kin.TrajectoryPoint(
                        "A",
                        pose,
                        org.fresa.kin.TrajectoryPoint.Status.UNREACHABLE,
                        new double[0],
                        java.util.Optional.empty(),
                        Double.NaN,
                        Double.NaN,
                        0,
                        false),
                new org.fresa.kin.TrajectoryPoint(
                        "A",
                        pose,
                        org.fresa.kin.TrajectoryPoint.Status.RELINK,
                        new double[] {0, 10, 20, 0, 30, 0},
                        java.util.Optional.of(pose),
                        0,
                        0,
                        0,
                        true));
        RobotProgram p = RobotPrograms.of("t", irb, new org.fresa.model.Toolpath(List.of()), points);
        assertEquals(
                List.of(RobotProgram.MotionType.JOINT, RobotProgram.MotionType.LINEAR, RobotProgram.MotionType.JOINT),
                p.motions().stream().map(RobotProgram.Motion::type).toList());
        assertEquals(
                List.of(0, 1, 3),
                p.motions().stream().map(RobotProgram.Motion::index).toList());
    }
}
