package org.fresa.sole;

import org.fresa.model.WordedEnum;

/**
 * How a tread design repeats its figures (the job's {@code pattern}): once, along a line, on a
 * grid, round a centre, filling the sole, or at explicit copies.
 */
public enum PatternKind implements WordedEnum {
    SINGLE,
    LINEAR,
    GRID,
    POLAR,
    FILL,
    COPIES;

    @Override
    public String toString() {
        return word();
    }
}
