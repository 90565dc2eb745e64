package org.fresa.post;

import java.io.IOException;
import java.io.Writer;

/** Writes a {@link RobotProgram} in one robot language. Numbers with {@code Locale.ROOT}. */
public interface RobotProgramWriter {

    /** The format's name for {@code --formats} (rapid, krl). */
    String format();

    /** The file the program goes to (program.mod, program.src). */
    String fileName();

    void write(RobotProgram program, Writer out) throws IOException;

    /** A name the robot language accepts: a letter, then letters, digits and _, at most maxLength. */
    static String identifier(String name, int maxLength) {
        String s = name.replaceAll("[^A-Za-z0-9_]", "_");
        if (s.isEmpty() || !Character.isLetter(s.charAt(0))) {
            s = "P" + s;
        }
        return s.length() > maxLength ? s.substring(0, maxLength) : s;
    }

    /**
     * The joints the trajectory found for a target, after the language's comment marker
     * ({@code j=[q1,...]}), so that a reader can check them against trajectory.csv.
     */
    static void appendJoints(StringBuilder sb, String commentMarker, RobotProgram.Motion m, int joints) {
        sb.append(commentMarker).append(" j=[");
        for (int i = 0; i < joints; i++) {
            sb.append(i > 0 ? "," : "").append(RapidWriter.f(m.joint(i), 6));
        }
        sb.append(']');
    }
}
