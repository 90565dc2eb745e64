package org.fresa.toolpath;

/**
 * How a drilling-type operation moves along the hole's axis (ISO 14649-11 drilling_type_strategy,
 * multistep_drilling and feed_on_retract). Lengths in mm, feeds as fractions of the tool's plunge
 * feed; a factor of 1 means no reduction.
 *
 * <p>Feed zones along the descent: from the retract height until the full diameter is
 * {@code startDepth} below the top (the tip then lies {@code tipLength} deeper) at
 * {@code startFeedFactor}; over the last {@code endDepth} of travel above the bottom at
 * {@code endFeedFactor}; at the full feed in between. Where both zones overlap the end zone wins,
 * as the breakthrough is what the end reduction protects. The spindle speed factors apply over
 * the same zones.
 *
 * @param tipLength length of the drill point along the axis (0 for reamers, boring bars), >= 0
 * @param startDepth depth_of_start, >= 0
 * @param startFeedFactor reduced_feed_at_start, > 0
 * @param endDepth depth_of_end, >= 0
 * @param endFeedFactor reduced_feed_at_end, > 0
 * @param firstPeck multistep_drilling first_depth below the top; 0 or less for one descent
 * @param peck depth_of_step of each further step; 0 or less for one descent
 * @param retractDistance lift after each step; 0 or less to go back to the retract height
 * @param retractFeedFactor feed_on_retract; 0 or less to leave at rapid
 * @param dwellBottomS dwell_time_bottom: wait at the bottom before leaving, >= 0 (0: none)
 * @param dwellStepS multistep_drilling.dwell_time_step: wait at the bottom of each step but the
 *     last (which waits dwellBottomS), >= 0 (0: none)
 * @param spindleStopAtBottom boring_operation.spindle_stop_at_bottom: stop the spindle at the
 *     bottom (after the dwell), leave with it stopped and start it again, at the section's
 *     speed, at the retract height
 * @param startSpeedFactor reduced_cut_at_start: spindle speed over the start zone as a fraction
 *     of the section's, > 0
 * @param endSpeedFactor reduced_cut_at_end: spindle speed over the end zone, > 0
 */
public record DrillCycle(
        double tipLength,
        double startDepth,
        double startFeedFactor,
        double endDepth,
        double endFeedFactor,
        double firstPeck,
        double peck,
        double retractDistance,
        double retractFeedFactor,
        double dwellBottomS,
        double dwellStepS,
        boolean spindleStopAtBottom,
        double startSpeedFactor,
        double endSpeedFactor) {

    /** One descent at the full feed, out at rapid. */
    public static final DrillCycle PLAIN = new DrillCycle(0, 0, 1, 0, 1, 0, 0, 0, 0);

    public DrillCycle {
        if (!(tipLength >= 0 && startDepth >= 0 && endDepth >= 0 && startFeedFactor > 0 && endFeedFactor > 0)
                || !Double.isFinite(tipLength
                        + startDepth
                        + endDepth
                        + startFeedFactor
                        + endFeedFactor
                        + firstPeck
                        + peck
                        + retractDistance
                        + retractFeedFactor)) {
            throw new IllegalArgumentException("bad drill cycle: tip " + tipLength + ", start " + startDepth + " x"
                    + startFeedFactor + ", end " + endDepth + " x" + endFeedFactor);
        }
        if (!(dwellBottomS >= 0 && dwellStepS >= 0) || !Double.isFinite(dwellBottomS + dwellStepS)) {
            throw new IllegalArgumentException(
                    "dwells must be >= 0 s: bottom " + dwellBottomS + ", step " + dwellStepS);
        }
        if (!(startSpeedFactor > 0 && endSpeedFactor > 0) || !Double.isFinite(startSpeedFactor + endSpeedFactor)) {
            throw new IllegalArgumentException(
                    "spindle speed factors must be > 0: start " + startSpeedFactor + ", end " + endSpeedFactor);
        }
    }

    /** A cycle without dwells and with the spindle running throughout. */
    public DrillCycle(
            double tipLength,
            double startDepth,
            double startFeedFactor,
            double endDepth,
            double endFeedFactor,
            double firstPeck,
            double peck,
            double retractDistance,
            double retractFeedFactor) {
        this(
                tipLength,
                startDepth,
                startFeedFactor,
                endDepth,
                endFeedFactor,
                firstPeck,
                peck,
                retractDistance,
                retractFeedFactor,
                0,
                0,
                false,
                1,
                1);
    }

    /** Pecks of {@code peck} from the top, back to the retract height after each. */
    public static DrillCycle pecking(double peck) {
        return new DrillCycle(0, 0, 1, 0, 1, peck, peck, 0, 0);
    }

    /** The same cycle leaving at the given fraction of the feed. */
    public DrillCycle withRetractFeed(double factor) {
        return withBottomAndExit(
                factor, dwellBottomS, dwellStepS, spindleStopAtBottom, startSpeedFactor, endSpeedFactor);
    }

    /** The same cycle with these dwells (s) at the bottom and at each step. */
    public DrillCycle withDwells(double bottomS, double stepS) {
        return withBottomAndExit(
                retractFeedFactor, bottomS, stepS, spindleStopAtBottom, startSpeedFactor, endSpeedFactor);
    }

    /** The same cycle stopping the spindle at the bottom, or not. */
    public DrillCycle withSpindleStopAtBottom(boolean stop) {
        return withBottomAndExit(retractFeedFactor, dwellBottomS, dwellStepS, stop, startSpeedFactor, endSpeedFactor);
    }

    /** The same cycle with these spindle speed fractions over the start and end zones. */
    public DrillCycle withSpeedFactors(double start, double end) {
        return withBottomAndExit(retractFeedFactor, dwellBottomS, dwellStepS, spindleStopAtBottom, start, end);
    }

    /**
     * The same feed zones and steps, with these ways of turning the spindle, waiting at the
     * bottom and leaving: what the withers above change one at a time.
     */
    private DrillCycle withBottomAndExit(
            double retractFeed,
            double dwellBottom,
            double dwellStep,
            boolean stop,
            double startSpeed,
            double endSpeed) {
        return new DrillCycle(
                tipLength,
                startDepth,
                startFeedFactor,
                endDepth,
                endFeedFactor,
                firstPeck,
                peck,
                retractDistance,
                retractFeed,
                dwellBottom,
                dwellStep,
                stop,
                startSpeed,
                endSpeed);
    }

    boolean pecks() {
        return firstPeck > 0 && peck > 0;
    }
}
