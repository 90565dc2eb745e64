package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.fresa.model.ExactDecimal;
import org.fresa.stepnc.Operation;
import org.fresa.stepnc.Technology;

/**
 * The spindle speed and the feed a STEP-NC workingstep is cut with, read from its
 * MILLING_TECHNOLOGY and checked, so that no workingstep is cut with the spindle stopped or at
 * a speed its own file contradicts.
 *
 * <p>Rules:
 * <ul>
 * <li>The spindle speed is the file's spindle when it is given (and above 0). Without it, it is
 * the cutting speed's: n = 1000 v / (pi D) with v in m/min and D the cutter diameter in mm, and
 * the workingstep says so ({@link #notes()}). With neither, the workingstep is refused.
 * <li>When both are given and differ by {@value #DISAGREEMENT_FACTOR} times or more (a spindle
 * written in the wrong unit: 5.84 for the 584 rpm its cutting speed gives a 6 mm cutter), the
 * workingstep is refused with both values, unless the cutting speed is trusted
 * ({@link PlanningChoices#trustCuttingSpeed()}): then it is cut at the cutting speed's spindle
 * speed, with a note.
 * <li>The feed is {@link FeedRate#of(Operation, double)} at that spindle speed: a feed with a
 * unit as written, a feed without one as a chip load times the spindle speed. A workingstep
 * with no feed at all (feedrate unset or 0 and no feed_per_tooth with a tooth count) is refused:
 * no feed is guessed.
 * <li>Spindle speeds outside {@value #MIN_SPINDLE_RPM} to {@value #MAX_SPINDLE_RPM} rpm and
 * feeds outside {@value #MIN_FEED_MM_PER_MIN} to {@value #MAX_FEED_MM_PER_MIN} mm/min (the
 * machine range of the program check) refuse the workingstep.
 * </ul>
 *
 * @param spindleRpm the spindle speed the workingstep is cut with, rpm, > 0
 * @param fromCuttingSpeed whether it comes from the cutting speed rather than the spindle
 * @param feed the cutting feed and how it was read
 * @param notes sentences to report (a speed taken from the cutting speed, a spindle overruled)
 */
public record CuttingData(double spindleRpm, boolean fromCuttingSpeed, FeedRate feed, List<String> notes) {

    /** A spindle and a cutting speed this many times apart contradict each other. */
    public static final double DISAGREEMENT_FACTOR = 10;
    /** Slowest spindle speed planned (rpm). */
    public static final double MIN_SPINDLE_RPM = 1;
    /** Fastest spindle speed planned (rpm). */
    public static final double MAX_SPINDLE_RPM = 100_000;
    /** Slowest feed planned (mm/min). */
    public static final double MIN_FEED_MM_PER_MIN = 0.1;
    /** Fastest feed planned (mm/min). */
    public static final double MAX_FEED_MM_PER_MIN = 100_000;

    /**
     * Handbook feeds per revolution run from about 0.005 D (finishing, small drills) up: a feed a
     * fifth of that rubs instead of cutting, and in a file it is most often a unit mistaken by a
     * factor of 60 or 1000 (mm/s for m/s, mm/min for mm/rev).
     */
    public static final double SLOWEST_FEED_PER_REV_PER_DIAMETER = 0.001;

    public CuttingData {
        Objects.requireNonNull(feed, "feed");
        notes = List.copyOf(notes);
        if (!(spindleRpm > 0) || !Double.isFinite(spindleRpm)) {
            throw new IllegalArgumentException("spindle speed must be > 0: " + spindleRpm);
        }
    }

    /**
     * The cutting data of an operation by the rules of the class comment.
     *
     * @param toolDiameterMm the cutter diameter, > 0
     * @throws IllegalArgumentException naming what is missing or contradictory, for a workingstep
     *     that must not be cut
     */
    public static CuttingData of(Operation op, double toolDiameterMm, boolean trustCuttingSpeed) {
        Technology t = op.technology();
        List<String> notes = new ArrayList<>();
        double spindle = t.spindleRpm().isPresent()
                        && t.spindleRpm().getAsDouble() > 0
                        && Double.isFinite(t.spindleRpm().getAsDouble())
                ? t.spindleRpm().getAsDouble()
                : Double.NaN;
        double fromV = cuttingSpeedRpm(t, toolDiameterMm);
        double rpm;
        boolean fromCuttingSpeed;
        if (Double.isNaN(spindle) && Double.isNaN(fromV)) {
            throw new IllegalArgumentException("no spindle speed and no cutting speed in the file ("
                    + (t.instanceId() == 0
                            ? "the operation has no MILLING_TECHNOLOGY"
                            : "MILLING_TECHNOLOGY #" + t.instanceId())
                    + "): the tool would cut with the spindle stopped");
        } else if (Double.isNaN(spindle)) {
            rpm = fromV;
            fromCuttingSpeed = true;
            notes.add("no spindle speed in the file: " + n(rpm) + " rpm from the cutting speed " + cutSpeed(t)
                    + " for the " + n(toolDiameterMm) + " mm tool (n = 1000 v / (pi D))");
        } else if (!Double.isNaN(fromV) && Math.max(spindle, fromV) / Math.min(spindle, fromV) >= DISAGREEMENT_FACTOR) {
            String both = "spindle " + n(spindle) + " rpm and cutting speed " + cutSpeed(t) + " (" + n(fromV)
                    + " rpm for the " + n(toolDiameterMm) + " mm tool) disagree by a factor of "
                    + n(Math.rint(Math.max(spindle, fromV) / Math.min(spindle, fromV)));
            if (!trustCuttingSpeed) {
                throw new IllegalArgumentException(both + otherUnit(t, spindle, toolDiameterMm)
                        + "; correct the file, or plan from the cutting speed with --trust-cutting-speed");
            }
            rpm = fromV;
            fromCuttingSpeed = true;
            notes.add(both + ": planned at " + n(rpm) + " rpm from the cutting speed (--trust-cutting-speed)");
        } else {
            rpm = spindle;
            fromCuttingSpeed = false;
        }
        if (!(rpm >= MIN_SPINDLE_RPM && rpm <= MAX_SPINDLE_RPM)) {
            throw new IllegalArgumentException("spindle speed " + n(rpm) + " rpm"
                    + (fromCuttingSpeed ? " (from the cutting speed " + cutSpeed(t) + ")" : "") + " is outside "
                    + n(MIN_SPINDLE_RPM)
                    + " to " + n(MAX_SPINDLE_RPM) + " rpm");
        }
        FeedRate feed = FeedRate.of(op, rpm);
        if (feed.readAs().equals("default")) {
            throw new IllegalArgumentException("no feed in the file (MILLING_TECHNOLOGY #" + t.instanceId()
                    + ": feedrate " + (t.feedrate().isPresent() ? n(t.feedrate().getAsDouble()) : "unset")
                    + ", no feed_per_tooth with a tooth count): no feed is guessed");
        }
        if (!(feed.feedMmPerMin() >= MIN_FEED_MM_PER_MIN && feed.feedMmPerMin() <= MAX_FEED_MM_PER_MIN)) {
            throw new IllegalArgumentException("feed " + n(feed.feedMmPerMin()) + " mm/min ("
                    + (feed.inferred() ? feed.note() : "as written") + ") is outside " + n(MIN_FEED_MM_PER_MIN)
                    + " to " + n(MAX_FEED_MM_PER_MIN) + " mm/min");
        }
        double perRevMm = feed.feedMmPerMin() / rpm;
        if (perRevMm < SLOWEST_FEED_PER_REV_PER_DIAMETER * toolDiameterMm) {
            notes.add(feed.note() + (feed.spindleRpm().isPresent() ? "" : " at " + n(rpm) + " rpm") + ": "
                    + n(perRevMm) + " mm per revolution, less than a " + n(toolDiameterMm)
                    + " mm cutter forms a chip with (" + n(SLOWEST_FEED_PER_REV_PER_DIAMETER * toolDiameterMm)
                    + "); planned as written: check the file's feed and its unit");
        }
        return new CuttingData(rpm, fromCuttingSpeed, feed, notes);
    }

    /**
     * The spindle speed the technology's cutting speed gives a cutter of this diameter (rpm), NaN
     * when the file has no cutting speed above 0: n = 1000 v / (pi D), v in m/min (ISO 14649-10
     * writes m/s, STEP Modeler m/min).
     */
    static double cuttingSpeedRpm(Technology t, double toolDiameterMm) {
        if (t.cutSpeed().isEmpty()
                || !(t.cutSpeed().getAsDouble() > 0)
                || !Double.isFinite(t.cutSpeed().getAsDouble())
                || !(toolDiameterMm > 0)) {
            return Double.NaN;
        }
        double mPerMin = t.cutSpeed().getAsDouble() * ("m/s".equals(t.cutSpeedUnit()) ? 60 : 1);
        double rpm = 1000 * mPerMin / (Math.PI * toolDiameterMm);
        return Double.isFinite(rpm) ? rpm : Double.NaN;
    }

    /**
     * A hint when the cutting speed read in the other unit (m/min for m/s, or the reverse) agrees
     * with the spindle at a speed a cutting spindle turns (100 rpm or more): GRIMA's ISO-dialect
     * files write m/min where ISO 14649-10 has m/s.
     */
    private static String otherUnit(Technology t, double spindleRpm, double toolDiameterMm) {
        boolean perSecond = "m/s".equals(t.cutSpeedUnit());
        double other = 1000 * t.cutSpeed().getAsDouble() * (perSecond ? 1 : 60) / (Math.PI * toolDiameterMm);
        if (other >= 100 && Math.max(other, spindleRpm) / Math.min(other, spindleRpm) < DISAGREEMENT_FACTOR) {
            return " (read in " + (perSecond ? "m/min" : "m/s") + ", the cutting speed would give " + n(other)
                    + " rpm)";
        }
        return "";
    }

    private static String cutSpeed(Technology t) {
        return n(t.cutSpeed().getAsDouble()) + " " + t.cutSpeedUnit();
    }

    private static String n(double d) {
        if (!Double.isFinite(d)) {
            return String.valueOf(d);
        }
        double r = Math.abs(d) >= 1e12 ? d : Math.round(d * 1e4) / 1e4;
        return ExactDecimal.of(r + 0.0);
    }
}
