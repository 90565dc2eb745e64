package org.fresa.cutting;

import java.util.Locale;

/** The shape of the lead-in and lead-out: an arc (the default, a tangent entry) or a straight line. */
public enum LeadShape {
    ARC,
    LINE;

    /** The name as written: {@code arc}, {@code line}. */
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }

    @Override
    public String toString() {
        return word();
    }
}
