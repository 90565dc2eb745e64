package org.fresa.robot;

import org.fresa.model.WordedEnum;

/**
 * The files a robot run may write besides the trajectory: {@code csv} (trajectory.csv),
 * {@code xml} (program.xml), {@code rapid} (program.mod), {@code krl} (program.src) and
 * {@code png} (the joint and error plots).
 */
public enum RobotFormat implements WordedEnum {
    CSV,
    XML,
    RAPID,
    KRL,
    PNG;

    @Override
    public String toString() {
        return word();
    }
}
