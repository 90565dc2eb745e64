package org.fresa.model;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;

/**
 * The shortest decimal text that reads back as the same double (spec/cli.md: "every number in
 * them is written exactly"), independent of the locale.
 *
 * <p>Java 17's {@code Double.toString} round-trips but is not always the shortest (JDK-4511638,
 * fixed in 19), and switches to exponent notation below 1e-3; this searches the fewest
 * significant digits that round-trip and writes them in plain notation for ordinary magnitudes.
 */
public final class ExactDecimal {
    private ExactDecimal() {
    }

    /**
     * @throws IllegalArgumentException for NaN and infinities, which have no decimal form
     */
    public static String of(double d) {
        if (!Double.isFinite(d)) {
            throw new IllegalArgumentException("not a finite number: " + d);
        }
        if (d == 0) {
            return (1 / d < 0) ? "-0" : "0";
        }
        if (d == Math.rint(d) && Math.abs(d) < 1e15) {
            return Long.toString((long) d);
        }
        String s = Double.toString(d);
        BigDecimal exact = new BigDecimal(d);
        int digits = new BigDecimal(s).precision();
        // binary search the fewest significant digits for which a decimal reads back as d; at a
        // given precision the candidate may be the rounded-down or the rounded-up neighbour
        BigDecimal best = new BigDecimal(s);
        int lo = 1;
        int hi = digits;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            BigDecimal r = roundTrip(exact, d, mid);
            if (r != null) {
                best = r;
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        if (best.precision() > lo) {
            BigDecimal r = roundTrip(exact, d, lo);
            if (r != null) {
                best = r;
            }
        }
        best = best.stripTrailingZeros();
        double mag = Math.abs(d);
        if (mag >= 1e-7 && mag < 1e16) {
            return best.toPlainString();
        }
        return best.toString().replace("E+", "E");
    }

    /** The decimal of that many significant digits nearest to d that reads back as d, or null. */
    private static BigDecimal roundTrip(BigDecimal exact, double d, int precision) {
        BigDecimal near = exact.round(new MathContext(precision, RoundingMode.HALF_EVEN));
        if (near.doubleValue() == d) {
            return near;
        }
        BigDecimal down = exact.round(new MathContext(precision, RoundingMode.DOWN));
        if (down.doubleValue() == d) {
            return down;
        }
        BigDecimal up = exact.round(new MathContext(precision, RoundingMode.UP));
        return up.doubleValue() == d ? up : null;
    }
}
