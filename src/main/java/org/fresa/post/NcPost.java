package org.fresa.post;

import java.io.IOException;
import java.io.Writer;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

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
    default void write(Toolpath path, String programName, Writer out) throws IOException {
        Program p = begin(programName, out);
        for (ToolpathSection s : path.sections()) {
            p.section(s);
        }
        p.end();
    }

    /**
     * Starts a program written section by section, for a toolpath too long to hold whole: the
     * text is the same as {@link #write}'s for the same sections.
     *
     * @param programName a name for the program header (sanitised by the post as its dialect needs)
     */
    Program begin(String programName, Writer out) throws IOException;

    /** A program being written: its sections in machining order, then its end. */
    interface Program {
        /** Writes one section's blocks, after those of the sections before it. */
        void section(ToolpathSection s) throws IOException;

        /** Writes the program's end and flushes the writer. */
        void end() throws IOException;
    }

    /** The extension of the program files it writes, without the dot ({@code program.ngc}, {@code program.apt}). */
    default String fileExtension() {
        return "ngc";
    }
}
