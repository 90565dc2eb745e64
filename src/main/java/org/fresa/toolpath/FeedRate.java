package org.fresa.toolpath;

import java.util.Objects;
import java.util.OptionalDouble;
import java.util.OptionalInt;
import org.fresa.model.ExactDecimal;
import org.fresa.stepnc.Operation;
import org.fresa.stepnc.Technology;

/**
 * The cutting feed of an operation in mm/min, and how it was read from the file.
 *
 * <p>ISO 14649-10 files give the feed in m/s (the reader converts it). STEP Modeler (GRIMA, the
 * thesis's example 2) writes the feed without a unit, with the spindle in rpm: values such as
 * 0.245 (Ø10 drills, 2 teeth), 0.073 (Ø20 four-tooth mill), 0.0505 (Ø16) and 0.0235 (Ø10), at
 * spindle speeds matching its cutting speeds exactly (n = 1000 v_c / (pi D)). Those are chip
 * loads, the figures a machining handbook tabulates: feed per tooth f_z for milling cutters
 * (v_f = f_z z n) and feed per revolution f_n for drills (v_f = f_n n). Read the other way round
 * they are implausible: 0.245 mm/tooth would be 0.49 mm/rev for a Ø10 drill in 250 HB steel, and
 * 0.073 mm/rev only 0.018 mm/tooth for a Ø20 carbide mill (rubbing, not cutting). So a unitless
 * feed is read as mm/tooth for milling operations when the tool has a tooth count, as mm/rev for
 * drilling-type operations and for milling tools without one, and the default feed is used only
 * when the spindle speed is missing too. Every such reading is reported ({@link #note()}).
 *
 * @param feedMmPerMin the feed used, > 0
 * @param readAs the unit the written feed was read in: the file's own unit (ISO 14649: "m/s",
 *     converted by the reader), "mm/tooth" or "mm/rev" (inferred), or "default" (the file gives
 *     no usable feed)
 * @param written the feed as written, when there is one
 * @param teeth the tooth count used for mm/tooth
 * @param spindleRpm the spindle speed used for mm/tooth and mm/rev
 */
public record FeedRate(
        double feedMmPerMin, String readAs, OptionalDouble written, OptionalInt teeth, OptionalDouble spindleRpm) {

    /** Feed when the file gives none that can be converted (mm/min). */
    public static final double DEFAULT_MM_PER_MIN = 1000;

    public FeedRate {
        Objects.requireNonNull(readAs, "readAs");
        Objects.requireNonNull(written, "written");
        Objects.requireNonNull(teeth, "teeth");
        Objects.requireNonNull(spindleRpm, "spindleRpm");
        if (!(feedMmPerMin > 0) || !Double.isFinite(feedMmPerMin)) {
            throw new IllegalArgumentException("feed must be > 0: " + feedMmPerMin);
        }
    }

    /** The operation's feed, by the rules of the class comment, at the file's spindle speed. */
    public static FeedRate of(Operation op) {
        Technology t = op.technology();
        return of(op, t.spindleRpm().isPresent() ? t.spindleRpm().getAsDouble() : 0);
    }

    /**
     * The operation's feed, by the rules of the class comment, with chip loads multiplied by the
     * spindle speed the workingstep is cut with (which may come from the cutting speed,
     * {@link CuttingData}).
     *
     * @param spindleRpm the spindle speed; 0 or less when there is none
     */
    public static FeedRate of(Operation op, double spindleRpm) {
        Technology t = op.technology();
        if (t.feedMmPerMin().isPresent() && t.feedMmPerMin().getAsDouble() > 0) {
            return new FeedRate(
                    t.feedMmPerMin().getAsDouble(),
                    t.feedrateUnit(),
                    t.feedrate(),
                    OptionalInt.empty(),
                    OptionalDouble.empty());
        }
        OptionalDouble rpm =
                spindleRpm > 0 && Double.isFinite(spindleRpm) ? OptionalDouble.of(spindleRpm) : OptionalDouble.empty();
        OptionalInt teeth = op.tool()
                .map(tool -> tool.teeth())
                .filter(k -> k.isPresent() && k.getAsInt() > 0)
                .orElse(OptionalInt.empty());
        OptionalDouble perTooth =
                t.feedPerTooth().isPresent() && t.feedPerTooth().getAsDouble() > 0
                        ? t.feedPerTooth()
                        : OptionalDouble.empty();
        boolean unitless = t.feedrate().isPresent()
                && t.feedrate().getAsDouble() > 0
                && t.feedrateUnit().equals("unstated");
        if (rpm.isPresent() && unitless) {
            double f = t.feedrate().getAsDouble();
            double n = rpm.getAsDouble();
            if (!op.type().isDrillingType() && teeth.isPresent()) {
                return new FeedRate(f * teeth.getAsInt() * n, "mm/tooth", t.feedrate(), teeth, rpm);
            }
            return new FeedRate(f * n, "mm/rev", t.feedrate(), OptionalInt.empty(), rpm);
        }
        if (rpm.isPresent() && perTooth.isPresent() && teeth.isPresent()) {
            return new FeedRate(
                    perTooth.getAsDouble() * teeth.getAsInt() * rpm.getAsDouble(), "mm/tooth", perTooth, teeth, rpm);
        }
        return new FeedRate(DEFAULT_MM_PER_MIN, "default", t.feedrate(), OptionalInt.empty(), OptionalDouble.empty());
    }

    /** True when the unit was not in the file (a reading to report). */
    public boolean inferred() {
        return readAs.equals("mm/tooth") || readAs.equals("mm/rev") || readAs.equals("default");
    }

    /**
     * One sentence saying how the feed was obtained, e.g. "feed 0.073 (no unit in the file) read
     * as mm/tooth: 0.073 x 4 teeth x 2307.7467 rpm = 673.8 mm/min".
     */
    public String note() {
        String w = written.isPresent() ? n(written.getAsDouble()) : "none";
        return switch (readAs) {
            case "mm/tooth" ->
                "feed " + w + " (no unit in the file) read as mm/tooth: " + w + " x "
                        + teeth.getAsInt() + " teeth x " + n(spindleRpm.getAsDouble()) + " rpm = " + n(feedMmPerMin)
                        + " mm/min";
            case "mm/rev" ->
                "feed " + w + " (no unit in the file) read as mm/rev: " + w + " x " + n(spindleRpm.getAsDouble())
                        + " rpm = " + n(feedMmPerMin) + " mm/min";
            case "default" ->
                "no usable feed in the file (feed " + w + ", no spindle speed to convert it): " + n(feedMmPerMin)
                        + " mm/min used";
            default -> "feed " + w + " " + readAs + " = " + n(feedMmPerMin) + " mm/min";
        };
    }

    private static String n(double d) {
        return ExactDecimal.of(Math.round(d * 1e4) / 1e4 + 0.0);
    }
}
