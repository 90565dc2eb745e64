package org.fresa.post;

import java.io.IOException;
import java.io.Writer;
import org.fresa.model.Toolpath;

/**
 * A post-processor for a machine tool: writes a {@link Toolpath} as an NC program in one dialect.
 * Arcs are written as G02/G03 wherever the dialect has them; numbers with {@code Locale.ROOT}.
 */
public interface NcPost {

    /** The name used on the command line ({@code --post linuxcnc}). */
    String name();

    /** One line for {@code fresa posts}. */
    String description();

    /**
     * Writes the whole program.
     *
     * @param path the moves, in the machine's frame (mm)
     * @param programName a name for the program header (sanitised by the post as its dialect needs)
     */
    void write(Toolpath path, String programName, Writer out) throws IOException;

    /** The extension of the program files it writes, without the dot ({@code program.ngc}, {@code program.apt}). */
    default String fileExtension() {
        return "ngc";
    }
}
