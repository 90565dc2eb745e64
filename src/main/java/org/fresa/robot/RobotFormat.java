package org.fresa.robot;

import org.fresa.model.EnumWords;

/**
 * The files a robot run may write besides the trajectory: {@code csv} (trajectory.csv),
 * {@code xml} (program.xml), {@code rapid} (program.mod), {@code krl} (program.src) and
 * {@code png} (the joint and error plots).
 */
public enum RobotFormat {
    CSV,
    XML,
    RAPID,
    KRL,
    PNG;

    /** The name as the command line and job files write it. */
    public String word() {
        return EnumWords.of(this);
    }

    @Override
    public String toString() {
        return word();
    }
}
