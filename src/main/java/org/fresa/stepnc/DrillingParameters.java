package org.fresa.stepnc;

import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;

/**
 * The attributes of an ISO 14649-11 drilling_type_operation beyond cutting_depth, with those of
 * its subtypes multistep_drilling and boring_operation (reaming, boring). Lengths in mm, times in
 * s, ratios as fractions of the feed; each is empty when the file leaves it unset or the
 * operation's entity does not have it.
 *
 * @param dwellTimeBottomS dwell_time_bottom
 * @param feedOnRetract feed_on_retract: retract feed as a fraction of the feed
 * @param retractDistanceMm multistep_drilling.retract_distance: lift after each step
 * @param firstDepthMm multistep_drilling.first_depth: depth of the first step below the top
 * @param depthOfStepMm multistep_drilling.depth_of_step: depth of each further step
 * @param dwellTimeStepS multistep_drilling.dwell_time_step
 * @param spindleStopAtBottom boring_operation.spindle_stop_at_bottom
 */
public record DrillingParameters(
        OptionalDouble dwellTimeBottomS,
        OptionalDouble feedOnRetract,
        OptionalDouble retractDistanceMm,
        OptionalDouble firstDepthMm,
        OptionalDouble depthOfStepMm,
        OptionalDouble dwellTimeStepS,
        Optional<Boolean> spindleStopAtBottom) {

    /** No attributes set. */
    public static final DrillingParameters NONE = new DrillingParameters(
            OptionalDouble.empty(),
            OptionalDouble.empty(),
            OptionalDouble.empty(),
            OptionalDouble.empty(),
            OptionalDouble.empty(),
            OptionalDouble.empty(),
            Optional.empty());

    public DrillingParameters {
        Objects.requireNonNull(dwellTimeBottomS, "dwellTimeBottomS");
        Objects.requireNonNull(feedOnRetract, "feedOnRetract");
        Objects.requireNonNull(retractDistanceMm, "retractDistanceMm");
        Objects.requireNonNull(firstDepthMm, "firstDepthMm");
        Objects.requireNonNull(depthOfStepMm, "depthOfStepMm");
        Objects.requireNonNull(dwellTimeStepS, "dwellTimeStepS");
        Objects.requireNonNull(spindleStopAtBottom, "spindleStopAtBottom");
    }
}
