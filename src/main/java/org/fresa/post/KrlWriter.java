package org.fresa.post;

import java.io.IOException;
import java.io.Writer;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;

/**
 * KUKA KRL ({@code program.src}, KSS 8): {@code PTP} with the axis values for joint motions,
 * {@code LIN} with X Y Z A B C and the Status and Turn bits for linear motions on the part,
 * {@code $VEL.CP} (m/s) from the feed. Everything is inline, so no {@code .dat} file is needed.
 *
 * <p>A, B, C are Z-Y-X Euler angles (A about z, B about y, C about x). Status: bit 0 the wrist
 * centre behind axis 1 (overhead area), bit 1 axis 3 beyond the straight arm, bit 2 axis 5 <= 0.
 * Turn: bit i set when axis i + 1 is negative. A joint within
 * {@link RapidWriter#CONFIGURATION_TOLERANCE_DEG} of 0 counts as 0. {@code $APO.CDIS} is the
 * program's path tolerance, {@code C_DIS} on every point that is not a stop point; a dwell is
 * {@code WAIT SEC}. The axes are the robot's joints in Fresa's
 * convention (spec/robots.md), named A1..A6.
 */
public final class KrlWriter extends RobotLanguageWriter {

    /** The output that starts the spindle drive. */
    public static final String SPINDLE_ON = "$OUT[1]";
    /** The analog output of the spindle speed. */
    public static final String SPINDLE_SPEED = "$ANOUT[1]";
    /** The speed at full scale of {@link #SPINDLE_SPEED}, rpm. */
    public static final double SPINDLE_FULL_SCALE_RPM = 100_000;

    public KrlWriter(RapidWriter.ArmGeometry arm) {
        super("krl", "src", arm);
    }

    @Override
    public void write(RobotProgram p, Writer out) throws IOException {
        String name = RobotProgramWriter.identifier(p.programName(), 24);
        StringBuilder sb = new StringBuilder(96 * (p.motions().size() + 20));
        sb.append("&ACCESS RVP\n&REL 1\n&PARAM TEMPLATE = C:\\KRC\\Roboter\\Template\\vorgabe\n&PARAM EDITMASK = *\n");
        sb.append("DEF ").append(name).append("( )\n");
        sb.append(";FOLD INI\n  BAS (#INITMOV,0 )\n;ENDFOLD (INI)\n");
        sb.append("; Fresa robot program for ")
                .append(p.robotName())
                .append(": ")
                .append(p.motions().size())
                .append(" motions, base frame 0 (the robot base frame), TOOL_DATA[n] the TCP of tool n in the flange"
                        + " frame\n");
        sb.append("$BASE = {FRAME: X 0,Y 0,Z 0,A 0,B 0,C 0}\n");
        for (RobotProgram.ToolFrame t : p.tools()) {
            sb.append("TOOL_DATA[").append(t.number()).append("] = {");
            frame(sb, t.tcp()).append("}\n");
        }
        double apo = 0;
        for (RobotProgram.Motion m : p.motions()) {
            apo = Math.max(apo, m.zoneMm());
        }
        // the approximation distance of the C_DIS points: the program's path tolerance
        sb.append("$APO.CDIS = ").append(f(apo > 0 ? apo : 0.5, 3)).append('\n');
        walk(new Lines(p, sb));
        sb.append("END\n");
        out.write(sb.toString());
    }

    /** The lines of the program's motions, with the tool and the path velocity set where they change. */
    private final class Lines extends Steps {
        private int tool = -1;
        private double vel = Double.NaN;

        Lines(RobotProgram p, StringBuilder sb) {
            super(p, sb);
        }

        @Override
        void workingstep(String ws) {
            sb.append("; workingstep ").append(ws.replace('\n', ' ')).append('\n');
            int t = program.toolOf(ws).number();
            if (t != tool) {
                tool = t;
                sb.append("$TOOL = TOOL_DATA[").append(t).append("]\n");
            }
        }

        /**
         * Starts the spindle at the speed and waits for it to run up, or stops it: output
         * {@value #SPINDLE_ON} starts the spindle drive, analog output {@value #SPINDLE_SPEED} gives
         * the speed as a fraction of {@value #SPINDLE_FULL_SCALE_RPM} rpm.
         */
        @Override
        void spindle(double rpm) {
            if (rpm > 0) {
                sb.append("; spindle on at ").append(f(rpm, 0)).append(" rpm before the tool cuts\n");
                sb.append(SPINDLE_SPEED)
                        .append(" = ")
                        .append(f(rpm / SPINDLE_FULL_SCALE_RPM, 6))
                        .append('\n');
                sb.append(SPINDLE_ON).append(" = TRUE\n");
                sb.append("WAIT SEC ")
                        .append(f(RapidWriter.SPINDLE_RUN_UP_S, 1))
                        .append('\n');
            } else {
                sb.append(SPINDLE_ON).append(" = FALSE\n");
            }
        }

        @Override
        void motion(RobotProgram.Motion m) {
            if (m.type() == RobotProgram.MotionType.JOINT) {
                sb.append("PTP {AXIS: ");
                for (int i = 0; i < m.jointValues().size(); i++) {
                    sb.append(i > 0 ? "," : "")
                            .append('A')
                            .append(i + 1)
                            .append(' ')
                            .append(f(m.joint(i), 6));
                }
                sb.append("}");
            } else {
                double v = m.speedMmPerS() / 1000.0;
                if (v != vel) {
                    vel = v;
                    sb.append("$VEL.CP = ").append(f(v, 6)).append('\n');
                }
                sb.append("LIN {E6POS: ");
                frame(sb, m.target())
                        .append(",S 'B")
                        .append(bits(status(m), 3))
                        .append("',T 'B")
                        .append(bits(turn(m), 6))
                        .append("'}");
                if (m.zoneMm() > 0) {
                    sb.append(" C_DIS");
                }
                RobotProgramWriter.appendJoints(sb, " ;", m, m.jointValues().size());
            }
            sb.append(" ; ").append(m.index()).append('\n');
        }

        @Override
        void dwell(double seconds) {
            sb.append("WAIT SEC ").append(f(seconds, 3)).append('\n');
        }
    }

    int status(RobotProgram.Motion m) {
        return status(m, arm);
    }

    /** KUKA's Status of a motion (see the class comment). */
    public static int status(RobotProgram.Motion m, RapidWriter.ArmGeometry arm) {
        int s = 0;
        if (arm.rear(m)) {
            s |= 1;
        }
        if (!arm.lowerArm(m)) {
            s |= 2;
        }
        if (m.jointValues().size() > 4 && !(m.joint(4) > RapidWriter.CONFIGURATION_TOLERANCE_DEG)) {
            s |= 4;
        }
        return s;
    }

    /** KUKA's Turn of a motion: bit i set when axis i + 1 is negative. */
    public static int turn(RobotProgram.Motion m) {
        int t = 0;
        for (int i = 0; i < Math.min(6, m.jointValues().size()); i++) {
            if (RapidWriter.negative(m.joint(i))) {
                t |= 1 << i;
            }
        }
        return t;
    }

    /** A frame as KRL writes it: {@code X x,Y y,Z z,A a,B b,C c}, mm and the ZYX angles in deg. */
    private static StringBuilder frame(StringBuilder sb, Transform3 frame) {
        Vec3 at = frame.translationPart();
        Vec3 abc = frame.zyxAnglesDeg();
        double[] v = {at.x(), at.y(), at.z(), abc.x(), abc.y(), abc.z()};
        for (int i = 0; i < v.length; i++) {
            sb.append(i > 0 ? "," : "").append("XYZABC".charAt(i)).append(' ').append(f(v[i], i < 3 ? 3 : 6));
        }
        return sb;
    }

    static String bits(int value, int width) {
        StringBuilder b = new StringBuilder(Integer.toBinaryString(value));
        while (b.length() < width) {
            b.insert(0, '0');
        }
        return b.toString();
    }

    static String f(double v, int decimals) {
        return RapidWriter.f(v, decimals);
    }
}
