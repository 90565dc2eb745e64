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
        String fast = fewDecimals(d);
        return fast != null ? fast : byDigits(d);
    }

    /**
     * The search's answer from the exact decimal digits of d, without BigDecimal rounding: the
     * candidates of p digits (nearest half-even, truncated, truncated plus one, in that order)
     * are cut from the digit string and read back with {@link Double#parseDouble}, which rounds
     * correctly as {@link BigDecimal#doubleValue} does. Round-tripping is monotone in p, so when
     * one digit fewer than {@code Double.toString} gives fails, no shorter one exists and the
     * search would keep {@code Double.toString}'s digits.
     */
    private static String byDigits(double d) {
        String s = Double.toString(d);
        BigDecimal shortest = new BigDecimal(s);
        int n = shortest.precision();
        double mag = Math.abs(d);
        BigDecimal exact = new BigDecimal(mag);
        String digits = exact.unscaledValue().toString();
        int scale = exact.scale();
        BigDecimal best = null;
        for (int p = n - 1; p >= 1; p--) {
            // as many digits as the exact value has: the exact value itself
            BigDecimal r = p >= digits.length() ? exact : cut(digits, scale, p, mag);
            if (r == null) {
                break;
            }
            best = r;
        }
        if (best == null) {
            best = shortest.abs();
        }
        best = best.stripTrailingZeros();
        if (d < 0) {
            best = best.negate();
        }
        if (mag >= 1e-7 && mag < 1e16) {
            return best.toPlainString();
        }
        return best.toString().replace("E+", "E");
    }

    /** The p-digit candidate of digits * 10^-scale that reads back as mag, or null. */
    private static BigDecimal cut(String digits, int scale, int p, double mag) {
        long down = Long.parseLong(digits, 0, p, 10);
        int restScale = scale - (digits.length() - p);
        boolean anyRest = false;
        for (int i = p; i < digits.length() && !anyRest; i++) {
            anyRest = digits.charAt(i) != '0';
        }
        char first = digits.charAt(p);
        boolean beyondFirst = false;
        for (int i = p + 1; i < digits.length() && !beyondFirst; i++) {
            beyondFirst = digits.charAt(i) != '0';
        }
        boolean nearIsUp = first > '5' || (first == '5' && (beyondFirst || (down & 1) == 1));
        long near = nearIsUp ? down + 1 : down;
        long up = anyRest ? down + 1 : down;
        long[] order = {near, down, up};
        for (long m : order) {
            if (Double.parseDouble(m + "E" + (-restScale)) == mag) {
                return BigDecimal.valueOf(m, restScale);
            }
        }
        return null;
    }

    private static final double[] POW10 = new double[23];

    static {
        double p = 1;
        for (int i = 0; i < POW10.length; i++) {
            POW10[i] = p;
            p *= 10;
        }
    }

    private static final double TWO_53 = 9007199254740992.0;

    /**
     * The common case without BigDecimal: the fewest decimals k for which an integer m near
     * d * 10^k reads back as d. m / 10^k of two exact doubles is rounded once, exactly as the
     * decimal m E-k is read, so the test is exact; when two neighbours would both do (a tie the
     * search decides by rounding the exact value), or m needs more than 53 bits, this gives up.
     */
    private static String fewDecimals(double d) {
        double mag = Math.abs(d);
        if (mag < 1e-7 || mag >= 1e15) {
            return null;
        }
        for (int k = 1; k < POW10.length; k++) {
            double scaled = mag * POW10[k];
            if (scaled >= TWO_53 / 2) {
                return null;
            }
            long m0 = Math.round(scaled);
            long found = -1;
            int hits = 0;
            for (long m = Math.max(0, m0 - 1); m <= m0 + 1; m++) {
                if (m / POW10[k] == mag) {
                    found = m;
                    hits++;
                }
            }
            if (hits > 1) {
                return null;
            }
            if (hits == 1) {
                return plain(d < 0, found, k);
            }
        }
        return null;
    }

    /** m * 10^-k in plain notation, k > 0, m not a multiple of 10 (k is the fewest). */
    private static String plain(boolean negative, long m, int k) {
        String digits = Long.toString(m);
        StringBuilder sb = new StringBuilder(digits.length() + k + 3);
        if (negative) {
            sb.append('-');
        }
        if (digits.length() <= k) {
            sb.append("0.");
            for (int i = digits.length(); i < k; i++) {
                sb.append('0');
            }
            sb.append(digits);
        } else {
            sb.append(digits, 0, digits.length() - k).append('.').append(digits, digits.length() - k, digits.length());
        }
        return sb.toString();
    }

    /** The reference: a binary search over the number of significant digits, with BigDecimal. */
    static String bySearch(double d) {
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
