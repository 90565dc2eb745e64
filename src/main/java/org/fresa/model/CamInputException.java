package org.fresa.model;

import java.util.Objects;
import java.util.OptionalInt;

/**
 * A user's input cannot be used: a file that does not parse, a value out of range, a contour
 * that does not close. The message is for the user (file, line, column, what was expected) and
 * carries no technical detail; the command line prints it and exits with status 2.
 *
 * <p>Readers subclass this (Part 21, DXF, contour files) to add what locates the fault in
 * their format (an instance name, an entity handle).
 */
public class CamInputException extends Exception {

    private static final long serialVersionUID = 1L;

    private final String source;
    private final int line;
    private final int column;
    private final String problem;

    /**
     * @param source the file name (or another name for where the input came from)
     * @param line 1-based line, or 0 when unknown
     * @param column 1-based column, or 0 when unknown
     * @param problem what is wrong and what was expected, one sentence
     */
    public CamInputException(String source, int line, int column, String problem) {
        this(source, line, column, problem, null);
    }

    public CamInputException(String source, int line, int column, String problem, Throwable cause) {
        super(format(source, line, column, problem), cause);
        this.source = Objects.requireNonNull(source, "source");
        this.line = line;
        this.column = column;
        this.problem = Objects.requireNonNull(problem, "problem");
    }

    /** A problem with the input as a whole, not at one line. */
    public CamInputException(String source, String problem) {
        this(source, 0, 0, problem);
    }

    private static String format(String source, int line, int column, String problem) {
        StringBuilder sb = new StringBuilder(source);
        if (line > 0) {
            sb.append(": line ").append(line);
            if (column > 0) {
                sb.append(", column ").append(column);
            }
        }
        return sb.append(": ").append(problem).toString();
    }

    public String source() {
        return source;
    }

    public OptionalInt line() {
        return line > 0 ? OptionalInt.of(line) : OptionalInt.empty();
    }

    public OptionalInt column() {
        return column > 0 ? OptionalInt.of(column) : OptionalInt.empty();
    }

    /** The problem without the location prefix. */
    public String problem() {
        return problem;
    }
}
