package org.fresa.stepnc;

import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;

/**
 * MILLING_TECHNOLOGY: feed, cutting speed and spindle speed. The raw values are kept as written,
 * with the unit the file's dialect uses ({@link StepNcProgram.Dialect}): ISO 14649-10 writes
 * feed and cutting speed in m/s and the spindle in revolutions per second (NIST's files mark
 * clockwise with a negative sign); STEP Modeler (GRIMA) writes the spindle in rpm and the
 * cutting speed in m/min, and does not say in which unit its feed is.
 *
 * @param feedrate as written
 * @param feedrateUnit the unit of {@code feedrate}, or "unstated"
 * @param feedrateReference TCP or CCP
 * @param cutSpeed as written
 * @param cutSpeedUnit the unit of {@code cutSpeed}
 * @param spindle as written (sign kept)
 * @param spindleUnit the unit of {@code spindle}
 * @param feedPerTooth as written, mm
 * @param feedMmPerMin the feed converted to mm/min when the unit is known
 * @param spindleRpm |spindle| in rpm when the unit is known
 * @param spindleClockwise true when the file marks clockwise rotation (a negative spindle, as NIST and GRIMA write it)
 */
public record Technology(
        long instanceId,
        OptionalDouble feedrate,
        String feedrateUnit,
        Optional<String> feedrateReference,
        OptionalDouble cutSpeed,
        String cutSpeedUnit,
        OptionalDouble spindle,
        String spindleUnit,
        OptionalDouble feedPerTooth,
        OptionalDouble feedMmPerMin,
        OptionalDouble spindleRpm,
        boolean spindleClockwise) {
    public Technology {
        Objects.requireNonNull(feedrate);
        Objects.requireNonNull(feedrateUnit);
        Objects.requireNonNull(feedrateReference);
        Objects.requireNonNull(cutSpeed);
        Objects.requireNonNull(cutSpeedUnit);
        Objects.requireNonNull(spindle);
        Objects.requireNonNull(spindleUnit);
        Objects.requireNonNull(feedPerTooth);
        Objects.requireNonNull(feedMmPerMin);
        Objects.requireNonNull(spindleRpm);
    }

    public static final Technology NONE = new Technology(
            0,
            OptionalDouble.empty(),
            "unstated",
            Optional.empty(),
            OptionalDouble.empty(),
            "unstated",
            OptionalDouble.empty(),
            "unstated",
            OptionalDouble.empty(),
            OptionalDouble.empty(),
            OptionalDouble.empty(),
            false);
}
