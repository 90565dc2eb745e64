package org.fresa.cutting;

import org.fresa.model.EnumWords;

/**
 * The sense contours are cut in: {@link #PROCESS} (the default: the process's own, see
 * {@link CutProcess}), clockwise or counter-clockwise.
 */
public enum CutSense {
    PROCESS,
    CW,
    CCW;

    /** The name as written: {@code process}, {@code cw}, {@code ccw}. */
    public String word() {
        return EnumWords.of(this);
    }

    /** Whether contours are cut clockwise, the given sense standing for {@link #PROCESS}. */
    public boolean clockwise(boolean processClockwise) {
        return this == PROCESS ? processClockwise : this == CW;
    }

    @Override
    public String toString() {
        return word();
    }
}
