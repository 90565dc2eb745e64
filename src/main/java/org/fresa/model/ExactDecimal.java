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
        BigDecimal exact = new BigDecimal(s);
        int digits = exact.precision();
        // binary search the fewest significant digits that still read back as d
        int lo = 1;
        int hi = digits;
        BigDecimal best = exact;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            BigDecimal r = new BigDecimal(d).round(new MathContext(mid, RoundingMode.HALF_EVEN));
            if (r.doubleValue() == d) {
                best = r;
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        if (lo < digits && best.precision() != lo) {
            best = new BigDecimal(d).round(new MathContext(lo, RoundingMode.HALF_EVEN));
        }
        best = best.stripTrailingZeros();
        double mag = Math.abs(d);
        if (mag >= 1e-7 && mag < 1e16) {
            return best.toPlainString();
        }
        return best.toString().replace("E+", "E");
    }
}
