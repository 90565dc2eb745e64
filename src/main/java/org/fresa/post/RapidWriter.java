package org.fresa.post;

import java.io.IOException;
import java.io.Writer;
import java.util.Locale;
import org.fresa.geom.Quaternion;
import org.fresa.geom.Vec3;

/**
 * ABB RAPID ({@code program.mod}): a MODULE with tooldata and wobjdata declarations and one
 * procedure; {@code MoveAbsJ} for joint motions (approach, relinks), {@code MoveL} with a
 * robtarget for each linear motion on the part. Robtargets carry the quaternion (q1 scalar) and
 * the confdata [cf1, cf4, cf6, cfx] computed from the joints, so the controller keeps the
 * trajectory's configuration (ConfL\On).
 *
 * <p>cf1, cf4, cf6 are the quarter revolutions of axes 1, 4 and 6 (floor(q/90): 0..89.999 deg is
 * 0, -90..-0.001 is -1; within {@link #CONFIGURATION_TOLERANCE_DEG} of a boundary, the boundary's).
 * Zones: {@code fine} at the motion's stop points, RobotWare's named zone ({@code z1}, {@code z5})
 * for a radius that has one, else a zonedata of that radius. A dwell is {@code WaitTime \InPos}. cfx follows RobotWare 6 for a 6R arm with a spherical wrist:
 * 4 * rear + 2 * lowerArm + flip, where flip is q5 < 0, lowerArm is q3 below the
 * straight-arm angle (the elbow below the line from shoulder to wrist) and rear is the wrist centre
 * behind axis 1. The joints are in Fresa's convention for the robot (spec/robots.md), which for the
 * IRB-140 is ABB's.
 */
public final class RapidWriter implements RobotProgramWriter {

    private final ArmGeometry arm;

    /**
     * @param arm how to tell rear and lower-arm configurations from the joints of this robot
     */
    public RapidWriter(ArmGeometry arm) {
        this.arm = arm;
    }

    /** What cfx needs to know of the arm, from its kinematics. */
    public interface ArmGeometry {
        /** True when the wrist centre lies behind axis 1 (negative x in axis 1's rotated frame). */
        boolean rear(RobotProgram.Motion m);

        /** True when the elbow is below the shoulder-wrist line (ABB's "lower arm" case). */
        boolean lowerArm(RobotProgram.Motion m);
    }

    @Override
    public String format() {
        return "rapid";
    }

    @Override
    public String fileName() {
        return "program.mod";
    }

    @Override
    public void write(RobotProgram p, Writer out) throws IOException {
        String module = RobotProgramWriter.identifier(p.programName(), 32);
        StringBuilder sb = new StringBuilder(64 * (p.motions().size() + 20));
        sb.append("MODULE ").append(module).append('\n');
        sb.append("  ! Fresa robot program for ")
                .append(p.robotName())
                .append(": ")
                .append(p.motions().size())
                .append(" motions\n");
        for (RobotProgram.ToolFrame t : p.tools()) {
            Vec3 at = t.tcp().translationPart();
            Quaternion q = Quaternion.of(t.tcp());
            sb.append("  PERS tooldata ").append(toolName(t)).append(" := [TRUE,[");
            pose(sb, at, q).append("],[1,[0,0,1],[1,0,0,0],0,0,0]];\n");
        }
        sb.append("  PERS wobjdata wFresa := [FALSE,TRUE,\"\",[[0,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];\n");
        sb.append("  ! the joints and poses are in the robot base frame (wFresa is the identity); each tooldata\n");
        sb.append("  ! is a tool's TCP in the flange frame (spindle and tool length), as Fresa solved it\n");
        sb.append('\n');
        sb.append("  PROC main()\n");
        sb.append("    ConfJ \\On;\n");
        sb.append("    ConfL \\On;\n");
        String ws = null;
        double rpm = 0;
        for (RobotProgram.Motion m : p.motions()) {
            if (!m.workingstep().equals(ws)) {
                ws = m.workingstep();
                sb.append("    ! workingstep ").append(ws.replace('\n', ' ')).append('\n');
            }
            if (m.spindleRpm() != rpm) {
                spindle(sb, m.spindleRpm());
                rpm = m.spindleRpm();
            }
            String speed = speed(m.speedMmPerS());
            String zone = zone(m.zoneMm());
            if (m.type() == RobotProgram.MotionType.JOINT || m.jointValues().size() != 6) {
                sb.append("    MoveAbsJ [[");
                for (int i = 0; i < 6; i++) {
                    if (i > 0) {
                        sb.append(',');
                    }
                    sb.append(i < m.jointValues().size() ? f(m.joint(i), 6) : "0");
                }
                sb.append("],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]],")
                        .append(speed)
                        .append(',')
                        .append(zone)
                        .append(',')
                        .append(toolName(p.toolOf(m.workingstep())))
                        .append("\\WObj:=wFresa;");
            } else {
                Vec3 pos = m.target().translationPart();
                Quaternion q = Quaternion.of(m.target());
                sb.append("    MoveL [");
                pose(sb, pos, q)
                        .append(",[")
                        .append(confdata(m, arm))
                        .append("],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]],")
                        .append(speed)
                        .append(',')
                        .append(zone)
                        .append(',')
                        .append(toolName(p.toolOf(m.workingstep())))
                        .append("\\WObj:=wFresa;");
                // the joints the trajectory found for this robtarget, so a reader can check them
                RobotProgramWriter.appendJoints(sb, " !", m, 6);
            }
            sb.append(" ! ").append(m.index()).append('\n');
            if (m.dwellS() > 0) {
                sb.append("    WaitTime \\InPos, ").append(f(m.dwellS(), 3)).append(";\n");
            }
        }
        if (rpm != 0) {
            spindle(sb, 0);
        }
        sb.append("  ENDPROC\n");
        sb.append("ENDMODULE\n");
        out.write(sb.toString());
    }

    /**
     * Starts the spindle at the speed and waits for it to run up, or stops it: the spindle drive is
     * wired to the controller's signals {@value #SPINDLE_ON} (start) and {@value #SPINDLE_RPM}
     * (speed in rpm), which the cell's I/O configuration must define.
     */
    private static void spindle(StringBuilder sb, double rpm) {
        if (rpm > 0) {
            sb.append("    ! spindle on at ").append(f(rpm, 0)).append(" rpm before the tool cuts\n");
            sb.append("    SetAO ")
                    .append(SPINDLE_RPM)
                    .append(", ")
                    .append(f(rpm, 0))
                    .append(";\n");
            sb.append("    SetDO ").append(SPINDLE_ON).append(", 1;\n");
            sb.append("    WaitTime ").append(f(SPINDLE_RUN_UP_S, 1)).append(";\n");
        } else {
            sb.append("    SetDO ").append(SPINDLE_ON).append(", 0;\n");
        }
    }

    /** The digital output that starts the spindle drive. */
    public static final String SPINDLE_ON = "doFresaSpindleOn";
    /** The analog output of the spindle speed, rpm. */
    public static final String SPINDLE_RPM = "aoFresaSpindleRpm";
    /** The time the spindle is given to reach its speed before the first motion, s. */
    public static final double SPINDLE_RUN_UP_S = 2;

    /** The tooldata's name of a tool. */
    static String toolName(RobotProgram.ToolFrame t) {
        return "tFresa" + t.number();
    }

    /**
     * Joint angles this close to a quadrant boundary or to 0 (deg) count as on it: a joint the
     * solver leaves at -1e-16 instead of 0 must not change the configuration a controller is
     * asked for between two neighbouring points.
     */
    public static final double CONFIGURATION_TOLERANCE_DEG = 1e-9;

    /** The quarter revolution of a joint angle in degrees, as confdata counts it. */
    static int quarter(double angleDeg) {
        double k = Math.rint(angleDeg / 90.0);
        if (Math.abs(angleDeg - 90.0 * k) <= CONFIGURATION_TOLERANCE_DEG) {
            return (int) k;
        }
        return (int) Math.floor(angleDeg / 90.0);
    }

    /** Whether a joint angle is below 0 by more than {@link #CONFIGURATION_TOLERANCE_DEG}. */
    public static boolean negative(double angleDeg) {
        return angleDeg < -CONFIGURATION_TOLERANCE_DEG;
    }

    /** ABB confdata of a six-joint motion: quarter turns of axes 1, 4 and 6, and cfx. */
    public record Confdata(int cf1, int cf4, int cf6, int cfx) {
        @Override
        public String toString() {
            return cf1 + "," + cf4 + "," + cf6 + "," + cfx;
        }
    }

    /** The confdata of a motion of a six-joint arm (see the class comment). */
    public static Confdata confdata(RobotProgram.Motion m, ArmGeometry arm) {
        int flip = negative(m.joint(4)) ? 1 : 0;
        int cfx = 4 * (arm.rear(m) ? 1 : 0) + 2 * (arm.lowerArm(m) ? 1 : 0) + flip;
        return new Confdata(quarter(m.joint(0)), quarter(m.joint(3)), quarter(m.joint(5)), cfx);
    }

    /** speeddata [v_tcp mm/s, v_ori deg/s, v_leax, v_reax]. */
    static String speed(double mmPerS) {
        return "[" + f(mmPerS, 3) + ",500,5000,1000]";
    }

    /** RobotWare's predefined zones by their TCP radius (mm). */
    private static final double[] NAMED_ZONES_MM = {0.3, 1, 5, 10, 15, 20, 30, 40, 50, 60, 80, 100, 150, 200};

    static String zone(double mm) {
        if (mm <= 0) {
            return "fine";
        }
        for (double z : NAMED_ZONES_MM) {
            if (z == mm) {
                return z == 0.3 ? "z0" : "z" + (int) z;
            }
        }
        return "[FALSE," + f(mm, 3) + "," + f(1.5 * mm, 3) + "," + f(1.5 * mm, 3) + ",0.15," + f(1.5 * mm, 3)
                + ",0.15]";
    }

    /** A pose as RAPID writes it: {@code [x,y,z],[q1,q2,q3,q4]}, mm and the unit quaternion. */
    private static StringBuilder pose(StringBuilder sb, Vec3 at, Quaternion q) {
        return sb.append('[')
                .append(f(at.x(), 3))
                .append(',')
                .append(f(at.y(), 3))
                .append(',')
                .append(f(at.z(), 3))
                .append("],[")
                .append(f(q.w(), 8))
                .append(',')
                .append(f(q.x(), 8))
                .append(',')
                .append(f(q.y(), 8))
                .append(',')
                .append(f(q.z(), 8))
                .append(']');
    }

    static String f(double v, int decimals) {
        String s = String.format(Locale.ROOT, "%." + decimals + "f", v);
        return s.startsWith("-") && Double.parseDouble(s) == 0 ? s.substring(1) : s;
    }
}
