package org.fresa.setting;

import java.util.Objects;
import org.fresa.model.CamInputException;
import org.fresa.model.ExactDecimal;

/**
 * The values one numeric setting may take, with the names the command line ({@code --z-top})
 * and job files ({@code zTopMm}) give it, so that both refuse the same values with the same
 * words. The bounds are physical (what a machine, a tool or a shoe can be) and keep every run
 * within seconds and the heap: NaN and the infinities lie outside every range.
 *
 * @param option the command-line option, or empty for a setting that only job files have
 * @param attribute the job file's attribute ({@code schemas/job.xsd})
 * @param min the smallest value, in {@code unit}
 * @param minIncluded whether {@code min} itself is allowed
 * @param max the largest value, in {@code unit}
 * @param maxIncluded whether {@code max} itself is allowed
 * @param unit the unit as the user reads it ({@code mm}, {@code rpm}, {@code mm/min}), empty for a
 *     pure number
 * @param whole whether only whole numbers are allowed (counts, tool numbers)
 */
public record SettingRange(
        String option,
        String attribute,
        double min,
        boolean minIncluded,
        double max,
        boolean maxIncluded,
        String unit,
        boolean whole) {

    public SettingRange {
        Objects.requireNonNull(option, "option");
        Objects.requireNonNull(attribute, "attribute");
        Objects.requireNonNull(unit, "unit");
        if (!(min < max) || !Double.isFinite(min) || !Double.isFinite(max)) {
            throw new IllegalArgumentException("a range needs finite min < max: " + min + ", " + max);
        }
    }

    /** The closed range [min, max]. */
    public static SettingRange of(String option, String attribute, double min, double max, String unit) {
        return new SettingRange(option, attribute, min, true, max, true, unit, false);
    }

    /** The range (min, max]: for quantities that must be more than min (a stepover fraction). */
    public static SettingRange above(String option, String attribute, double min, double max, String unit) {
        return new SettingRange(option, attribute, min, false, max, true, unit, false);
    }

    /** The range [min, max): for quantities that must stay below max (a shrinkage fraction). */
    public static SettingRange below(String option, String attribute, double min, double max, String unit) {
        return new SettingRange(option, attribute, min, true, max, false, unit, false);
    }

    /** The whole numbers from min to max (counts, tool numbers). */
    public static SettingRange wholeNumbers(String option, String attribute, long min, long max, String unit) {
        return new SettingRange(option, attribute, min, true, max, true, unit, true);
    }

    /** Whether the value is allowed (never for NaN or an infinity). */
    public boolean contains(double v) {
        boolean lower = minIncluded ? v >= min : v > min;
        boolean upper = maxIncluded ? v <= max : v < max;
        return lower && upper && (!whole || v == Math.rint(v));
    }

    /** What is expected, as a phrase: "a number from 0.01 to 1000 mm". */
    public String expected() {
        String what = whole ? "a whole number" : "a number";
        String u = unit.isEmpty() ? "" : " " + unit;
        if (minIncluded && maxIncluded) {
            return what + " from " + text(min) + " to " + text(max) + u;
        }
        return what
                + (minIncluded ? " of at least " : " above ")
                + text(min)
                + u
                + (maxIncluded ? " and at most " : " and below ")
                + text(max)
                + u;
    }

    /** The problem with a value outside the range, one sentence without the name. */
    public String problem(double v) {
        return "expected " + expected() + ", found " + text(v);
    }

    /**
     * The value, when allowed.
     *
     * @throws CamInputException naming the command-line option, for a value outside the range
     */
    public double check(double v) throws CamInputException {
        if (!contains(v)) {
            throw new CamInputException(option.isEmpty() ? attribute : option, problem(v));
        }
        return v;
    }

    /** {@link #check} for an int option. */
    public int check(int v) throws CamInputException {
        check((double) v);
        return v;
    }

    /**
     * The value, when allowed; for readers of files that find the line afterwards.
     *
     * @throws OutOfRange for a value outside the range
     */
    public double require(double v) {
        if (!contains(v)) {
            throw new OutOfRange(this, v);
        }
        return v;
    }

    /** {@link #require} for an int attribute. */
    public int require(int v) {
        require((double) v);
        return v;
    }

    /** A value as the user wrote it, near enough: NaN and infinities by name. */
    static String text(double v) {
        if (Double.isNaN(v)) {
            return "NaN";
        }
        if (Double.isInfinite(v)) {
            return v > 0 ? "Infinity" : "-Infinity";
        }
        return ExactDecimal.of(v);
    }

    /**
     * A value outside its range met inside a reader, which turns it into a
     * {@link CamInputException} with the file and line.
     */
    public static final class OutOfRange extends IllegalArgumentException {
        private static final long serialVersionUID = 1L;

        private final transient SettingRange range;
        private final double value;

        OutOfRange(SettingRange range, double value) {
            super(range.attribute() + ": " + range.problem(value));
            this.range = range;
            this.value = value;
        }

        public SettingRange range() {
            return range;
        }

        public double value() {
            return value;
        }
    }
}
