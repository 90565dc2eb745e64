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
        StringBuilder sb = new StringBuilder(24);
        append(sb, d);
        return sb.toString();
    }

    /**
     * Appends {@link #of}'s text: the CSV writers call this for every number, and building each
     * number's String first cost them a third of their time.
     *
     * @throws IllegalArgumentException for NaN and infinities, which have no decimal form
     */
    public static StringBuilder append(StringBuilder sb, double d) {
        if (!Double.isFinite(d)) {
            throw new IllegalArgumentException("not a finite number: " + d);
        }
        if (d == 0) {
            return sb.append((1 / d < 0) ? "-0" : "0");
        }
        if (d == Math.rint(d) && Math.abs(d) < 1e15) {
            return sb.append((long) d);
        }
        if (fewDecimals(sb, d) || shortest(sb, d)) {
            return sb;
        }
        String tiny = TinyDecimal.shortest(d);
        return sb.append(tiny != null ? tiny : byDigits(d));
    }

    /**
     * The search's answer from the exact decimal digits of d, without BigDecimal rounding: the
     * candidates of p digits (nearest half-even, truncated, truncated plus one, in that order)
     * are cut from the digit string and read back with {@link Double#parseDouble}, which rounds
     * correctly as {@link BigDecimal#doubleValue} does. Round-tripping is monotone in p, so when
     * one digit fewer than {@code Double.toString} gives fails, no shorter one exists and the
     * search would keep {@code Double.toString}'s digits.
     */
    static String byDigits(double d) {
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
    private static boolean fewDecimals(StringBuilder sb, double d) {
        double mag = Math.abs(d);
        if (mag < 1e-7 || mag >= 1e15) {
            return false;
        }
        // a full-precision value would take every k up to 2^52 before giving up: past a few
        // decimals the exact search is cheaper
        for (int k = 1; k <= MAX_FEW_DECIMALS; k++) {
            double scaled = mag * POW10[k];
            if (scaled >= TWO_53 / 2) {
                return false;
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
                return false;
            }
            if (hits == 1) {
                plain(sb, d < 0, found, k);
                return true;
            }
        }
        return false;
    }

    private static final int MAX_FEW_DECIMALS = 6;

    /** Appends m * 10^-k in plain notation, k > 0, m not a multiple of 10 (k is the fewest). */
    private static void plain(StringBuilder sb, boolean negative, long m, int k) {
        if (negative) {
            sb.append('-');
        }
        if (k >= POW10L.length) {
            // m < 10^18 <= 10^k: nothing before the point
            String digits = Long.toString(m);
            sb.append("0.");
            for (int i = digits.length(); i < k; i++) {
                sb.append('0');
            }
            sb.append(digits);
            return;
        }
        long unit = POW10L[k];
        sb.append(m / unit).append('.');
        long frac = m % unit;
        // leading zeros of the fraction: it has k digits
        for (long z = unit / 10; z > frac; z /= 10) {
            sb.append('0');
        }
        sb.append(frac);
    }

    private static final long[] POW5 = new long[28];
    private static final long[] POW10L = new long[19];

    static {
        POW5[0] = 1;
        for (int i = 1; i < POW5.length; i++) {
            POW5[i] = POW5[i - 1] * 5;
        }
        POW10L[0] = 1;
        for (int i = 1; i < POW10L.length; i++) {
            POW10L[i] = POW10L[i - 1] * 10;
        }
    }

    /**
     * {@link #byDigits}'s answer for 1e-7 <= |d| < 1e15 in exact integer arithmetic: in a cold
     * JVM the BigDecimal digits, {@code Double.toString} and {@code Double.parseDouble} of the
     * search cost more than the rest of the CSV writing together (and the JIT's time for them).
     * The first 18 significant digits of the exact value (d = M 2^E, so d 10^j = M 5^j 2^(E+j),
     * 128 bits) and whether anything nonzero follows give the candidates of p digits as
     * byDigits cuts them; a candidate c 10^s reads back as d when it lies inside d's rounding
     * interval, (M -+ 1/2) 2^E (M - 1/4 below a power of two), the ends included for an even M
     * (the round-half-even of {@code Double.parseDouble}), compared exactly. Searching down
     * from 17 digits (always enough) finds the fewest digits, as round-tripping is monotone in
     * p. Null when the 18 digits cannot be formed (outside that range). Below 1e-7 the answer is
     * {@link TinyDecimal}'s, in scientific notation as the reference writes it there.
     */
    static String shortest(double d) {
        if (Math.abs(d) < TinyDecimal.LIMIT) {
            return TinyDecimal.shortest(d);
        }
        StringBuilder sb = new StringBuilder(24);
        return shortest(sb, d) ? sb.toString() : null;
    }

    /** Appends {@link #shortest(double)}'s text for 1e-7 <= |d| < 1e15, or appends nothing and says so. */
    private static boolean shortest(StringBuilder sb, double d) {
        double mag = Math.abs(d);
        if (!(mag >= TinyDecimal.LIMIT && mag < 1e15)) {
            return false;
        }
        long bits = Double.doubleToRawLongBits(mag);
        long m = (bits & 0x000F_FFFF_FFFF_FFFFL) | 0x0010_0000_0000_0000L;
        int e = (int) (bits >>> 52) - 1075;
        int k = (int) Math.floor(Math.log10(mag));
        long c18 = -1;
        boolean sticky = false;
        for (int attempt = 0; attempt < 3; attempt++) {
            int j = 17 - k;
            if (j < 0 || j >= POW5.length) {
                return false;
            }
            long hi = Math.multiplyHigh(m, POW5[j]);
            long lo = m * POW5[j];
            int shift = -(e + j);
            if (shift < 0 || shift >= 128) {
                return false;
            }
            long q;
            if (shift == 0) {
                sticky = false;
                q = hi == 0 ? lo : -1;
            } else if (shift < 64) {
                sticky = (lo & ((1L << shift) - 1)) != 0;
                q = (hi >>> shift) == 0 ? (lo >>> shift) | (hi << (64 - shift)) : -1;
            } else {
                sticky = lo != 0 || (shift > 64 && (hi & ((1L << (shift - 64)) - 1)) != 0);
                q = hi >>> (shift - 64);
            }
            if (q < 0) {
                k++;
            } else if (q >= POW10L[18]) {
                k++;
            } else if (q < POW10L[17]) {
                k--;
            } else {
                c18 = q;
                break;
            }
        }
        if (c18 < 0) {
            return false;
        }
        boolean even = (m & 1) == 0;
        // the interval's ends in units of 2^(E-2)
        long lowQ = m == 0x0010_0000_0000_0000L ? 4 * m - 1 : 4 * m - 2;
        long highQ = 4 * m + 2;
        // round-tripping is monotone in p and 17 digits always do: the fewest by bisection
        long bestC = candidate(c18, sticky, 17, k, e, lowQ, highQ, even);
        int bestP = 17;
        if (bestC < 0) {
            return false;
        }
        int lo = 1;
        while (lo < bestP) {
            int mid = (lo + bestP) >>> 1;
            long c = candidate(c18, sticky, mid, k, e, lowQ, highQ, even);
            if (c >= 0) {
                bestC = c;
                bestP = mid;
            } else {
                lo = mid + 1;
            }
        }
        int bestS = k - bestP + 1;
        if (bestC <= 0) {
            return false;
        }
        while (bestC % 10 == 0) {
            bestC /= 10;
            bestS++;
        }
        if (bestS >= 0) {
            return false;
        }
        plain(sb, d < 0, bestC, -bestS);
        return true;
    }

    /**
     * The p-digit candidate (nearest half-even, truncated, truncated plus one, in that order, as
     * byDigits tries them) of the 18 digits c18 (and anything nonzero after them: sticky) that
     * reads back, or -1.
     */
    private static long candidate(long c18, boolean sticky, int p, int k, int e, long lowQ, long highQ, boolean even) {
        long unit = POW10L[18 - p];
        long down = c18 / unit;
        long rest = c18 - down * unit;
        boolean anyRest = rest != 0 || sticky;
        boolean nearIsUp = 2 * rest > unit || (2 * rest == unit && (sticky || (down & 1) == 1));
        long near = nearIsUp ? down + 1 : down;
        long up = anyRest ? down + 1 : down;
        int s = k - p + 1;
        if (readsBack(near, s, e, lowQ, highQ, even)) {
            return near;
        } else if (readsBack(down, s, e, lowQ, highQ, even)) {
            return down;
        } else if (readsBack(up, s, e, lowQ, highQ, even)) {
            return up;
        }
        return -1;
    }

    /** Whether c 10^s lies inside (lowQ, highQ) 2^(e-2), the ends included when even. */
    private static boolean readsBack(long c, int s, int e, long lowQ, long highQ, boolean even) {
        int lo = compare(c, s, lowQ, e - 2);
        if (lo < 0 || (lo == 0 && !even)) {
            return false;
        }
        int hi = compare(c, s, highQ, e - 2);
        return hi < 0 || (hi == 0 && even);
    }

    /** The sign of c 10^s - q 2^b, exactly (c, q >= 0, |s| <= 27). */
    private static int compare(long c, int s, long q, int b) {
        // c 5^s 2^s against q 2^b; a negative s moves 5^-s to the right-hand side
        long f = s >= 0 ? POW5[s] : 1;
        long g = s >= 0 ? 1 : POW5[-s];
        long lHi = Math.multiplyHigh(c, f);
        long lLo = c * f;
        long rHi = Math.multiplyHigh(q, g);
        long rLo = q * g;
        int diff = s - b;
        if (diff >= 0) {
            return shiftedCompare(lHi, lLo, diff, rHi, rLo);
        }
        return -shiftedCompare(rHi, rLo, -diff, lHi, lLo);
    }

    /** The sign of (aHi aLo) 2^n - (bHi bLo), unsigned 128-bit values below 2^126. */
    private static int shiftedCompare(long aHi, long aLo, int n, long bHi, long bLo) {
        if (aHi == 0 && aLo == 0) {
            return (bHi | bLo) == 0 ? 0 : -1;
        }
        int len = aHi != 0 ? 128 - Long.numberOfLeadingZeros(aHi) : 64 - Long.numberOfLeadingZeros(aLo);
        if (len + n > 127) {
            return 1;
        }
        long hi;
        long lo;
        if (n == 0) {
            hi = aHi;
            lo = aLo;
        } else if (n < 64) {
            hi = (aHi << n) | (aLo >>> (64 - n));
            lo = aLo << n;
        } else {
            hi = aLo << (n - 64);
            lo = 0;
        }
        int c = Long.compareUnsigned(hi, bHi);
        return c != 0 ? c : Long.compareUnsigned(lo, bLo);
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
