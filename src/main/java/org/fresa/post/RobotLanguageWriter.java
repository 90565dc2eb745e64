package org.fresa.post;

/**
 * A robot language's program, written along the motions in the order they run. Each language says
 * what it writes for a workingstep, a change of spindle speed, a motion and a dwell; the walk is
 * one, so every language starts the spindle at its speed before the first motion that needs it
 * (no motion into the material with the spindle off) and stops it after the last.
 */
abstract class RobotLanguageWriter implements RobotProgramWriter {

    private final String format;
    private final String extension;

    /** How to tell the arm's configurations (rear, lower arm) from the joints of this robot. */
    final RapidWriter.ArmGeometry arm;

    /**
     * @param format the language's name for {@code --formats}
     * @param extension the extension its controller reads a program under ({@code mod}, {@code src})
     */
    RobotLanguageWriter(String format, String extension, RapidWriter.ArmGeometry arm) {
        this.format = format;
        this.extension = extension;
        this.arm = arm;
    }

    @Override
    public final String format() {
        return format;
    }

    /** Every language's program goes to {@code program.}<i>extension</i>, beside {@code program.xml}. */
    @Override
    public final String fileName() {
        return "program." + extension;
    }

    /**
     * The lines a language writes into its program text as the walk reaches each part of the
     * program.
     */
    abstract static class Steps {
        final RobotProgram program;
        final StringBuilder sb;

        Steps(RobotProgram program, StringBuilder sb) {
            this.program = program;
            this.sb = sb;
        }

        /** A workingstep begins: written before its first motion. */
        abstract void workingstep(String name);

        /** The spindle is set to a new speed before the motion that runs at it; 0 stops it. */
        abstract void spindle(double rpm);

        /** One motion, ending its line with the motion's index. */
        abstract void motion(RobotProgram.Motion m);

        /** A wait at the end point of the motion just written (s). */
        abstract void dwell(double seconds);
    }

    /** Walks the program's motions in order, telling the language each part to write. */
    static void walk(Steps steps) {
        String ws = null;
        double rpm = 0;
        for (RobotProgram.Motion m : steps.program.motions()) {
            if (!m.workingstep().equals(ws)) {
                ws = m.workingstep();
                steps.workingstep(ws);
            }
            if (m.spindleRpm() != rpm) {
                steps.spindle(m.spindleRpm());
                rpm = m.spindleRpm();
            }
            steps.motion(m);
            if (m.dwellS() > 0) {
                steps.dwell(m.dwellS());
            }
        }
        if (rpm != 0) {
            steps.spindle(0);
        }
    }
}
