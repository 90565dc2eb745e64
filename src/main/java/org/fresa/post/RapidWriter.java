package org.fresa.post;

import java.io.IOException;
import java.io.Writer;
import java.util.Locale;
import org.fresa.geom.Quaternion;
import org.fresa.geom.Transform3;
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
public final class RapidWriter extends RobotLanguageWriter {

    /** The digital output that starts the spindle drive. */
    public static final String SPINDLE_ON = "doFresaSpindleOn";
    /** The analog output of the spindle speed, rpm. */
    public static final String SPINDLE_RPM = "aoFresaSpindleRpm";
    /** The time the spindle is given to reach its speed before the first motion, s. */
    public static final double SPINDLE_RUN_UP_S = 2;

    /**
     * @param arm how to tell rear and lower-arm configurations from the joints of this robot
     */
    public RapidWriter(ArmGeometry arm) {
        super("rapid", "mod", arm);
    }

    /** What cfx needs to know of the arm, from its kinematics. */
    public interface ArmGeometry {
        /** True when the wrist centre lies behind axis 1 (negative x in axis 1's rotated frame). */
        boolean rear(RobotProgram.Motion m);

        /** True when the elbow is below the shoulder-wrist line (ABB's "lower arm" case). */
        boolean lowerArm(RobotProgram.Motion m);
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
            sb.append("  PERS tooldata ").append(toolName(t)).append(" := [TRUE,[");
            pose(sb, t.tcp()).append("],[1,[0,0,1],[1,0,0,0],0,0,0]];\n");
        }
        sb.append("  PERS wobjdata wFresa := [FALSE,TRUE,\"\",[[0,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];\n");
        sb.append("  ! the joints and poses are in the robot base frame (wFresa is the identity); each tooldata\n");
        sb.append("  ! is a tool's TCP in the flange frame (spindle and tool length), as Fresa solved it\n");
        sb.append('\n');
        sb.append("  PROC main()\n");
        sb.append("    ConfJ \\On;\n");
        sb.append("    ConfL \\On;\n");
        walk(new Lines(p, sb));
        sb.append("  ENDPROC\n");
        sb.append("ENDMODULE\n");
        out.write(sb.toString());
    }

    /** The lines of the program's motions inside {@code PROC main()}. */
    private final class Lines extends Steps {

        Lines(RobotProgram p, StringBuilder sb) {
            super(p, sb);
        }

        @Override
        void workingstep(String ws) {
            sb.append("    ! workingstep ").append(ws.replace('\n', ' ')).append('\n');
        }

        /**
         * Starts the spindle at the speed and waits for it to run up, or stops it: the spindle drive is
         * wired to the controller's signals {@value #SPINDLE_ON} (start) and {@value #SPINDLE_RPM}
         * (speed in rpm), which the cell's I/O configuration must define.
         */
        @Override
        void spindle(double rpm) {
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

        @Override
        void motion(RobotProgram.Motion m) {
            if (m.type() == RobotProgram.MotionType.JOINT || m.jointValues().size() != 6) {
                sb.append("    MoveAbsJ [[");
                for (int i = 0; i < 6; i++) {
                    if (i > 0) {
                        sb.append(',');
                    }
                    sb.append(i < m.jointValues().size() ? f(m.joint(i), 6) : "0");
                }
                sb.append(extaxSpeedZoneTool(m));
            } else {
                sb.append("    MoveL [");
                pose(sb, m.target()).append(",[").append(confdata(m, arm)).append(extaxSpeedZoneTool(m));
                // the joints the trajectory found for this robtarget, so a reader can check them
                RobotProgramWriter.appendJoints(sb, " !", m, 6);
            }
            sb.append(" ! ").append(m.index()).append('\n');
        }

        /**
         * What follows a target's axes: no external axes, then the motion's speed and zone, and
         * the tool of its workingstep in the work object.
         */
        private String extaxSpeedZoneTool(RobotProgram.Motion m) {
            return "],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]]," + speed(m.speedMmPerS()) + "," + zone(m.zoneMm()) + ","
                    + toolName(program.toolOf(m.workingstep())) + "\\WObj:=wFresa;";
        }

        @Override
        void dwell(double seconds) {
            sb.append("    WaitTime \\InPos, ").append(f(seconds, 3)).append(";\n");
        }
    }

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
    private static StringBuilder pose(StringBuilder sb, Transform3 pose) {
        Vec3 at = pose.translationPart();
        Quaternion q = Quaternion.of(pose);
        return sb.append('[')
                .append(list(3, at.x(), at.y(), at.z()))
                .append("],[")
                .append(list(8, q.w(), q.x(), q.y(), q.z()))
                .append(']');
    }

    /** Numbers separated by commas, each with the decimals given. */
    private static String list(int decimals, double... values) {
        StringBuilder sb = new StringBuilder();
        for (double v : values) {
            sb.append(sb.length() > 0 ? "," : "").append(f(v, decimals));
        }
        return sb.toString();
    }

    static String f(double v, int decimals) {
        String s = String.format(Locale.ROOT, "%." + decimals + "f", v);
        return s.startsWith("-") && Double.parseDouble(s) == 0 ? s.substring(1) : s;
    }
}
