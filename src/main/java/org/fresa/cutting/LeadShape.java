package org.fresa.cutting;

import org.fresa.model.EnumWords;

/** The shape of the lead-in and lead-out: an arc (the default, a tangent entry) or a straight line. */
public enum LeadShape {
    ARC,
    LINE;

    /** The name as written: {@code arc}, {@code line}. */
    public String word() {
        return EnumWords.of(this);
    }

    @Override
    public String toString() {
        return word();
    }
}
