package org.fresa.cutting;

import org.fresa.model.WordedEnum;

/**
 * Who allows for the kerf: {@link #SOFTWARE} (the default: the path is the contour offset by half
 * the kerf) or {@link #CONTROLLER} (the drawn contour with G41/G42, the kerf left to the controller).
 */
public enum KerfCompensation implements WordedEnum {
    SOFTWARE,
    CONTROLLER;

    @Override
    public String toString() {
        return word();
    }
}
