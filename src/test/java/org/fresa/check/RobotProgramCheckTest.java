package org.fresa.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fresa.geom.Transform3;
import org.fresa.post.RobotProgram;
import org.junit.jupiter.api.Test;

/** The check of robot programs: the spindle before every linear motion on the part, joints and speeds in range. */
class RobotProgramCheckTest {

    private static final List<RobotProgram.Joint> JOINTS =
            List.of(new RobotProgram.Joint("A1", RobotProgram.JointType.REVOLUTE, -180, 180));

    /** A tool pointing down (its z axis, into the material, is -Z of the base). */
    private static RobotProgram.Motion motion(
            int i, RobotProgram.MotionType type, double x, double z, double q, double rpm) {
        Transform3 pose = Transform3.translation(x, 0, z).times(Transform3.rotX(180));
        return new RobotProgram.Motion(i, "ws", type, RobotProgram.PointRole.PART, List.of(q), pose, 5, 0, 0, rpm);
    }

    private static RobotProgram program(double rpm, double q, double lastZ) {
        return new RobotProgram(
                "p",
                "r",
                JOINTS,
                List.of(
                        motion(0, RobotProgram.MotionType.JOINT, 0, 10, 0, rpm),
                        motion(1, RobotProgram.MotionType.LINEAR, 100, 10 - 2, q, rpm),
                        motion(2, RobotProgram.MotionType.LINEAR, 200, lastZ, 0, rpm)));
    }

    @Test
    void aRampOfOneDegreeWithTheSpindleOnPasses() {
        ProgramCheck.Verdict v = ProgramCheck.of(program(3000, 10, 8), Limits.milling());
        assertTrue(v.ok(), () -> v.failure().get().message());
    }

    @Test
    void aLinearMotionWithTheSpindleStoppedIsRefused() {
        Failure f =
                ProgramCheck.of(program(0, 10, 8), Limits.milling()).failure().orElseThrow();
        assertEquals("spindle", f.rule().name());
        assertEquals("motion 1", f.where());
    }

    @Test
    void aJointOutsideItsLimitsIsRefused() {
        Failure f = ProgramCheck.of(program(3000, 190, 8), Limits.milling())
                .failure()
                .orElseThrow();
        assertEquals("words", f.rule().name());
        assertTrue(f.reason().contains("outside its limits"), f.reason());
    }

    @Test
    void aPlungeAlongTheToolAxisIsRefusedUnlessTheToolMayPlunge() {
        RobotProgram p = new RobotProgram(
                "p",
                "r",
                JOINTS,
                List.of(
                        motion(0, RobotProgram.MotionType.JOINT, 0, 10, 0, 3000),
                        motion(1, RobotProgram.MotionType.LINEAR, 0, 0, 0, 3000)));
        Failure f = ProgramCheck.of(p, Limits.milling()).failure().orElseThrow();
        assertEquals("entry angle", f.rule().name());
        assertTrue(ProgramCheck.of(p, Limits.milling().withTool(4, ToolLimits.drill()), java.util.Map.of("ws", 4))
                .ok());
    }
}
