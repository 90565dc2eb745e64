package org.fresa.pocket;

import org.fresa.model.EnumWords;

/**
 * Which way the cutter goes round the walls: {@link #CLIMB} (the default: counter-clockwise with
 * a clockwise spindle, the chip thick at entry and thin at exit) or {@link #CONVENTIONAL}.
 */
public enum MillingDirection {
    CLIMB,
    CONVENTIONAL;

    /** The name as written: {@code climb}, {@code conventional}. */
    public String word() {
        return EnumWords.of(this);
    }

    /** Whether the passes are climb-milled. */
    public boolean climb() {
        return this == CLIMB;
    }

    @Override
    public String toString() {
        return word();
    }
}
