package org.fresa.sole;

import org.fresa.model.EnumWords;

/**
 * How a tread design repeats its figures (the job's {@code pattern}): once, along a line, on a
 * grid, round a centre, filling the sole, or at explicit copies.
 */
public enum PatternKind {
    SINGLE,
    LINEAR,
    GRID,
    POLAR,
    FILL,
    COPIES;

    /** The name as written: {@code single}, {@code linear}, ... */
    public String word() {
        return EnumWords.of(this);
    }

    @Override
    public String toString() {
        return word();
    }
}
