package org.fresa.cutting;

import org.fresa.model.EnumWords;

/**
 * Who allows for the kerf: {@link #SOFTWARE} (the default: the path is the contour offset by half
 * the kerf) or {@link #CONTROLLER} (the drawn contour with G41/G42, the kerf left to the controller).
 */
public enum KerfCompensation {
    SOFTWARE,
    CONTROLLER;

    /** The name as written: {@code software}, {@code controller}. */
    public String word() {
        return EnumWords.of(this);
    }

    @Override
    public String toString() {
        return word();
    }
}
