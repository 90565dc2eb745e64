package org.fresa.grading;

import java.util.ArrayList;
import java.util.List;

/** The sizes of a range {@code A-B} in a system, whole sizes or also the half sizes between. */
public final class SizeRange {

    /** The largest number of sizes in one run, against a typo such as 36-440. */
    public static final int MAX_SIZES = 400;

    private SizeRange() {}

    /**
     * Parses {@code A-B} (or a single size {@code A}); sizes run from A up to B in whole-size
     * steps of the system (halves too when halfSizes).
     *
     * @throws IllegalArgumentException with a message for the user
     */
    public static List<Double> parse(String text, SizeSystem system, boolean halfSizes) {
        String t = text.trim();
        int dash = t.indexOf('-', 1);
        double a;
        double b;
        try {
            if (dash < 0) {
                a = Double.parseDouble(t);
                b = a;
            } else {
                a = Double.parseDouble(t.substring(0, dash).trim());
                b = Double.parseDouble(t.substring(dash + 1).trim());
            }
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("expected sizes as A-B (e.g. 36-44), found '" + text + "'");
        }
        if (!Double.isFinite(a) || !Double.isFinite(b) || b < a) {
            throw new IllegalArgumentException("expected sizes A-B with A <= B, found '" + text + "'");
        }
        system.checkSize(a, "size");
        system.checkSize(b, "size");
        double step = system.wholeSizeStep() / (halfSizes ? 2 : 1);
        // counted in double: a range of 1e308 sizes would overflow a long
        double count = Math.floor((b - a) / step + 1e-9) + 1;
        if (!(count <= MAX_SIZES)) {
            throw new IllegalArgumentException("too many sizes in '" + text + "': "
                    + String.format(java.util.Locale.ROOT, "%.0f", count) + " (at most " + MAX_SIZES + ")");
        }
        long n = (long) count;
        List<Double> out = new ArrayList<>();
        for (long i = 0; i < n; i++) {
            out.add(a + i * step);
        }
        return out;
    }
}
