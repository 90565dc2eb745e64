package org.fresa.post;

import java.util.List;
import org.fresa.geom.Transform3;

/** A small IRB-140-like program: an approach, three linear moves on a face, a relink. */
public final class RobotProgramsForTest {
    private RobotProgramsForTest() {}

    public static final RapidWriter.ArmGeometry FRONT_UPPER = new RapidWriter.ArmGeometry() {
        @Override
        public boolean rear(RobotProgram.Motion m) {
            return false;
        }

        @Override
        public boolean lowerArm(RobotProgram.Motion m) {
            return false;
        }
    };

    public static RobotProgram sample() {
        List<RobotProgram.Joint> joints = List.of(
                new RobotProgram.Joint("J1", RobotProgram.JointType.REVOLUTE, -180, 180),
                new RobotProgram.Joint("J2", RobotProgram.JointType.REVOLUTE, -90, 110),
                new RobotProgram.Joint("J3", RobotProgram.JointType.REVOLUTE, -230, 50),
                new RobotProgram.Joint("J4", RobotProgram.JointType.REVOLUTE, -200, 200),
                new RobotProgram.Joint("J5", RobotProgram.JointType.REVOLUTE, -120, 120),
                new RobotProgram.Joint("J6", RobotProgram.JointType.REVOLUTE, -400, 400));
        Transform3 down = Transform3.rotY(180);
        return new RobotProgram(
                "example 2",
                "irb140",
                joints,
                List.of(
                        motion(
                                0,
                                "approach",
                                RobotProgram.MotionType.JOINT,
                                RobotProgram.PointRole.RELINK,
                                List.of(0.0, 10.0, -20.0, 0.0, 55.5, 0.0),
                                at(down, 500, 0, 400),
                                250,
                                0),
                        motion(
                                1,
                                "WS 1",
                                RobotProgram.MotionType.LINEAR,
                                RobotProgram.PointRole.PART,
                                List.of(-1.25, 12.5, -22.123456789, 181.0, -35.25, -91.0),
                                at(down, 500, 10, 350),
                                5,
                                0),
                        motion(
                                2,
                                "WS 1",
                                RobotProgram.MotionType.LINEAR,
                                RobotProgram.PointRole.PART,
                                List.of(2.5, 13.0, -21.0, 0.0, 30.0, 0.1),
                                at(down.times(Transform3.rotZ(30)), 520, 10, 350),
                                5,
                                0.5),
                        motion(
                                3,
                                "WS 2",
                                RobotProgram.MotionType.LINEAR,
                                RobotProgram.PointRole.PART,
                                List.of(3.0, 13.5, -20.5, -0.5, 31.0, 359.9),
                                at(down, 540, 10.25, 350),
                                8.5,
                                0.5)));
    }

    static RobotProgram.Motion motion(
            int i,
            String ws,
            RobotProgram.MotionType type,
            RobotProgram.PointRole role,
            List<Double> q,
            Transform3 target,
            double speed,
            double zone) {
        return new RobotProgram.Motion(i, ws, type, role, q, target, speed, zone, 0, 0);
    }

    static Transform3 at(Transform3 r, double x, double y, double z) {
        return new Transform3(r.r00(), r.r01(), r.r02(), r.r10(), r.r11(), r.r12(), r.r20(), r.r21(), r.r22(), x, y, z);
    }
}
