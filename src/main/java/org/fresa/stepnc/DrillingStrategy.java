package org.fresa.stepnc;

import java.util.Objects;
import java.util.OptionalDouble;

/**
 * ISO 14649-11 drilling_type_strategy: reduced cutting speed and feed over the first and the
 * last part of a drilling-type operation. Ratios are fractions of the operation's cutting speed
 * and feed (0..1 as ISO defines positive_ratio_measure; files that write percentages, 0..100,
 * are read as percentages and divided by 100). Lengths in mm.
 *
 * @param reducedCutAtStart reduced_cut_at_start: spindle speed ratio over the start depth
 * @param reducedFeedAtStart reduced_feed_at_start: feed ratio over the start depth
 * @param depthOfStartMm depth_of_start: depth cut with the start reductions
 * @param reducedCutAtEnd reduced_cut_at_end: spindle speed ratio over the end depth
 * @param reducedFeedAtEnd reduced_feed_at_end: feed ratio over the end depth
 * @param depthOfEndMm depth_of_end: the last part of the travel cut with the end reductions
 */
public record DrillingStrategy(
        OptionalDouble reducedCutAtStart,
        OptionalDouble reducedFeedAtStart,
        OptionalDouble depthOfStartMm,
        OptionalDouble reducedCutAtEnd,
        OptionalDouble reducedFeedAtEnd,
        OptionalDouble depthOfEndMm) {

    /** A strategy with no reductions. */
    public static final DrillingStrategy NONE = new DrillingStrategy(
            OptionalDouble.empty(),
            OptionalDouble.empty(),
            OptionalDouble.empty(),
            OptionalDouble.empty(),
            OptionalDouble.empty(),
            OptionalDouble.empty());

    public DrillingStrategy {
        Objects.requireNonNull(reducedCutAtStart, "reducedCutAtStart");
        Objects.requireNonNull(reducedFeedAtStart, "reducedFeedAtStart");
        Objects.requireNonNull(depthOfStartMm, "depthOfStartMm");
        Objects.requireNonNull(reducedCutAtEnd, "reducedCutAtEnd");
        Objects.requireNonNull(reducedFeedAtEnd, "reducedFeedAtEnd");
        Objects.requireNonNull(depthOfEndMm, "depthOfEndMm");
    }
}
