package org.fresa.cutting;

import org.fresa.model.WordedEnum;

/** The shape of the lead-in and lead-out: an arc (the default, a tangent entry) or a straight line. */
public enum LeadShape implements WordedEnum {
    ARC,
    LINE;

    @Override
    public String toString() {
        return word();
    }
}
