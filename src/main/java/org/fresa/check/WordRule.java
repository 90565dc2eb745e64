package org.fresa.check;

/**
 * Every word can be read and is finite and within the machine's range: coordinates within
 * {@value #MAX_COORDINATE_MM} mm, S within the spindle's range, F within the feed range (a
 * time of at most {@value #MAX_DWELL_S} s in a G04 block), G and M codes, tool, offset and block
 * numbers non-negative integers of the sizes controls take.
 */
public final class WordRule extends Rule {

    /** No machine Fresa writes for travels this far from its zero, mm. */
    public static final double MAX_COORDINATE_MM = 10_000;
    /** The longest dwell, s. */
    public static final double MAX_DWELL_S = 3600;
    /** Rotary axes, degrees. */
    static final double MAX_ANGLE_DEG = 36_000;

    public WordRule() {
        super("words", "every word is a finite number within the machine's range");
    }

    @Override
    public String broken(Step s, Limits l) {
        if (s.block().problem().isPresent()) {
            return s.block().problem().get();
        }
        for (Words.Word w : s.block().words()) {
            String why = outOfRange(w, s, l);
            if (why != null) {
                return "word " + w + " out of range: " + why;
            }
        }
        return null;
    }

    private static String outOfRange(Words.Word w, Step s, Limits l) {
        double v = w.value();
        if (!Double.isFinite(v)) {
            return "not a finite number";
        }
        switch (w.address()) {
            case "X", "Y", "Z", "I", "J", "K", "U", "V", "W", "R":
                if (s.dwell() && (w.address().equals("X"))) {
                    return time(v);
                }
                return Math.abs(v * s.dialect().mmPerUnit()) <= MAX_COORDINATE_MM
                        ? null
                        : "coordinates lie within " + Num.of(MAX_COORDINATE_MM) + " mm of the zero";
            case "A", "B", "C":
                return Math.abs(v) <= MAX_ANGLE_DEG ? null : "rotary axes within " + Num.of(MAX_ANGLE_DEG) + " degrees";
            case "F":
                if (s.dwell()) {
                    return time(v);
                }
                return v >= l.feedMinMmPerMin() && v <= l.feedMaxMmPerMin()
                        ? null
                        : "the feed rate is " + Num.of(l.feedMinMmPerMin()) + ".." + Num.of(l.feedMaxMmPerMin())
                                + " mm/min";
            case "S":
                return v >= l.spindleMinRpm() && v <= l.spindleMaxRpm()
                        ? null
                        : "the spindle turns " + Num.of(l.spindleMinRpm()) + ".." + Num.of(l.spindleMaxRpm()) + " rpm";
            case "P":
                return s.dwell() ? time(v) : integer(v, 0, 99_999, "P (turns, output numbers)");
            case "G", "M":
                return v >= 0 && v <= 999 ? null : w.address() + " codes are 0..999";
            case "T":
                return integer(v, 0, 99_999, "tool numbers");
            case "H", "D":
                return integer(v, 0, 999, "offset numbers");
            case "N":
                return integer(v, 0, 99_999_999, "block numbers");
            case "O":
                return integer(v, 0, 99_999, "program numbers");
            case "TURN":
                return integer(v, 0, 99_999, "extra turns");
            default:
                return Math.abs(v) <= 100_000 ? null : "no word of the dialect takes a number this large";
        }
    }

    private static String time(double v) {
        return v >= 0 && v <= MAX_DWELL_S ? null : "a dwell lasts 0.." + Num.of(MAX_DWELL_S) + " s";
    }

    private static String integer(double v, double min, double max, String what) {
        return v == Math.rint(v) && v >= min && v <= max
                ? null
                : what + " are whole numbers " + Num.of(min) + ".." + Num.of(max);
    }
}
