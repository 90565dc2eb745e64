package org.fresa.model;

import java.util.Arrays;

/**
 * The shortest decimal text that reads back as the same double (spec/cli.md: "every number in
 * them is written exactly"), independent of the locale.
 *
 * <p>Java 17's {@code Double.toString} round-trips but is not always the shortest (JDK-4511638,
 * fixed in 19), and switches to exponent notation below 1e-3. This finds the fewest significant
 * digits that round-trip, the way a search over BigDecimal roundings finds them (that search is
 * the test's oracle), and writes them as {@code BigDecimal.toPlainString} does for
 * 1e-7 <= |d| < 1e16 and as {@code BigDecimal.toString} does outside (without the "+").
 *
 * <p>The method, one for every finite double: d = M 2^E lies in its rounding interval, the reals
 * that read back as d, (M -+ 1/2) 2^E (M - 1/4 below a power of two), the ends included for an
 * even M (the round-half-even of {@code Double.parseDouble}). With j = 17 - floor(log10 d), the
 * interval's ends and d itself are scaled by 10^j to integers of 18 digits (floor, and whether
 * anything was cut off), in exact arithmetic on arrays of 32-bit words. A candidate of p digits
 * (d's digits rounded to nearest half-even, truncated, truncated plus one, in that order) then
 * reads back when its scaled value lies in the scaled interval: a comparison of longs. Reading
 * back is monotone in p and 17 digits always do, so bisection finds the fewest. No BigInteger
 * and no {@code Double.toString}: in a cold JVM those (and the JIT's time for them) cost the CSV
 * writers of a robot trajectory more than the rest of their work.
 */
public final class ExactDecimal {
    private ExactDecimal() {}

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
        Shortest s = shortest(Math.abs(d));
        return write(sb, d < 0, s.digits(), s.exponent(), Math.abs(d));
    }

    /** digits 10^exponent, digits without trailing zeros. */
    record Shortest(long digits, int exponent) {}

    private static final long HIDDEN = 0x0010_0000_0000_0000L;
    private static final long[] POW10 = powers(10, 19);

    /** base^0 .. base^(count - 1), each exact in a long. */
    private static long[] powers(long base, int count) {
        long[] p = new long[count];
        p[0] = 1;
        for (int i = 1; i < count; i++) {
            p[i] = p[i - 1] * base;
        }
        return p;
    }

    /** The fewest digits that read back as mag (finite, > 0). */
    static Shortest shortest(double mag) {
        long bits = Double.doubleToRawLongBits(mag);
        int biased = (int) (bits >>> 52);
        long fraction = bits & (HIDDEN - 1);
        // subnormals: no hidden bit, the exponent of the lowest normal binade
        long m = biased == 0 ? fraction : fraction | HIDDEN;
        int e = biased == 0 ? -1074 : biased - 1075;
        // the ends in units of 2^(E-2); only below a power of two (not the lowest normal, whose
        // lower neighbour is a subnormal one ulp away) is the lower half narrower
        long lowQ = fraction == 0 && biased > 1 ? 4 * m - 1 : 4 * m - 2;
        long highQ = 4 * m + 2;
        boolean even = (m & 1) == 0;
        int k = (int) Math.floor(Math.log10(mag));
        // log10 may be off by one next to a power of ten: the 18 digits say which way
        for (int attempt = 0; attempt < 4; attempt++) {
            int j = 17 - k;
            Scaled c18 = scaled(m, e, j);
            if (c18.floor() < 0 || c18.floor() >= POW10[18]) {
                k++;
            } else if (c18.floor() < POW10[17]) {
                k--;
            } else {
                return fewest(c18, scaled(lowQ, e - 2, j), scaled(highQ, e - 2, j), even, k);
            }
        }
        throw new IllegalStateException("no 18 digits for " + mag);
    }

    /** floor(q 2^b 10^j) when it is below 2^63 (otherwise -1), and whether it is exact. */
    record Scaled(long floor, boolean exact) {}

    static Scaled scaled(long q, int b, int j) {
        int[] n = of(q);
        int twos = b + j;
        boolean exact = true;
        if (j >= 0) {
            n = mulPow5(n, j);
        }
        if (twos > 0) {
            n = shiftLeft(n, twos);
        }
        if (j < 0) {
            // only |d| >= 1e18 gets here, and it is an integer: twos > 0
            Division r = divPow5(n, -j);
            n = r.quotient();
            exact = r.exact();
        }
        if (twos < 0) {
            exact &= !anyBitBelow(n, -twos);
            return new Scaled(bitsFrom(n, -twos), exact);
        }
        return new Scaled(bitsFrom(n, 0), exact);
    }

    /**
     * The shortest candidate inside [low, high] (ends included when even), all three scaled by
     * 10^(17 - k) to 18 digits.
     */
    private static Shortest fewest(Scaled c18, Scaled low, Scaled high, boolean even, int k) {
        long bestC = candidate(c18, 17, low, high, even);
        int bestP = 17;
        if (bestC < 0) {
            throw new IllegalStateException("17 digits do not read back");
        }
        int lo = 1;
        while (lo < bestP) {
            int mid = (lo + bestP) >>> 1;
            long c = candidate(c18, mid, low, high, even);
            if (c >= 0) {
                bestC = c;
                bestP = mid;
            } else {
                lo = mid + 1;
            }
        }
        int exponent = k - bestP + 1;
        while (bestC % 10 == 0) {
            bestC /= 10;
            exponent++;
        }
        return new Shortest(bestC, exponent);
    }

    /**
     * The p-digit candidate of the 18 digits (nearest half-even, truncated, truncated plus one,
     * in that order) that reads back, or -1.
     */
    private static long candidate(Scaled c18, int p, Scaled low, Scaled high, boolean even) {
        long unit = POW10[18 - p];
        long down = c18.floor() / unit;
        long rest = c18.floor() - down * unit;
        boolean sticky = !c18.exact();
        boolean anyRest = rest != 0 || sticky;
        boolean nearIsUp = 2 * rest > unit || (2 * rest == unit && (sticky || (down & 1) == 1));
        long near = nearIsUp ? down + 1 : down;
        long up = anyRest ? down + 1 : down;
        if (inside(near * unit, low, high, even)) {
            return near;
        } else if (inside(down * unit, low, high, even)) {
            return down;
        } else if (inside(up * unit, low, high, even)) {
            return up;
        }
        return -1;
    }

    /** Whether the integer c lies in [low, high], the ends included when even (and exact). */
    private static boolean inside(long c, Scaled low, Scaled high, boolean even) {
        // an inexact end lies strictly between its floor and the next integer
        boolean aboveLow = c > low.floor() || (c == low.floor() && low.exact() && even);
        boolean belowHigh = c < high.floor() || (c == high.floor() && (!high.exact() || even));
        return aboveLow && belowHigh;
    }

    /** Appends digits 10^exponent as BigDecimal writes the search's answer. */
    private static StringBuilder write(StringBuilder sb, boolean negative, long digits, int exponent, double mag) {
        if (negative) {
            sb.append('-');
        }
        String text = Long.toString(digits);
        if (mag >= 1e-7 && mag < 1e16) {
            if (exponent >= 0) {
                sb.append(text);
                for (int i = 0; i < exponent; i++) {
                    sb.append('0');
                }
                return sb;
            }
            int point = text.length() + exponent;
            if (point > 0) {
                return sb.append(text, 0, point).append('.').append(text, point, text.length());
            }
            sb.append("0.");
            for (int i = point; i < 0; i++) {
                sb.append('0');
            }
            return sb.append(text);
        }
        if (exponent == 0) {
            // 17 digits at 1e16 and more: BigDecimal's scale is 0, its text plain
            return sb.append(text);
        }
        sb.append(text.charAt(0));
        if (text.length() > 1) {
            sb.append('.').append(text, 1, text.length());
        }
        return sb.append('E').append(exponent + text.length() - 1);
    }

    // Exact arithmetic on non-negative integers as little-endian arrays of unsigned 32-bit words
    // without leading zero words (at most about 40 of them: 5^341 times a 55-bit integer, or
    // 2^1023 times one).

    /** 5^13, the largest power of five below 2^31. */
    private static final long POW5_13 = 1_220_703_125L;

    private static final long[] POW5 = powers(5, 14);

    static int[] of(long v) {
        int lo = (int) v;
        int hi = (int) (v >>> 32);
        if (hi != 0) {
            return new int[] {lo, hi};
        }
        return lo != 0 ? new int[] {lo} : new int[0];
    }

    static int[] mulPow5(int[] a, int n) {
        int[] r = a;
        while (n >= 13) {
            r = mulSmall(r, POW5_13);
            n -= 13;
        }
        return n > 0 ? mulSmall(r, POW5[n]) : r;
    }

    /** a f, for 0 < f < 2^31. */
    private static int[] mulSmall(int[] a, long f) {
        int[] r = new int[a.length + 1];
        long carry = 0;
        for (int i = 0; i < a.length; i++) {
            long p = (a[i] & 0xFFFF_FFFFL) * f + carry;
            r[i] = (int) p;
            carry = p >>> 32;
        }
        r[a.length] = (int) carry;
        return carry != 0 ? r : Arrays.copyOf(r, a.length);
    }

    /** floor(a / 5^n), and whether nothing was cut off. */
    record Division(int[] quotient, boolean exact) {}

    static Division divPow5(int[] a, int n) {
        int[] r = a.clone();
        boolean exact = true;
        while (n > 0) {
            long f = n >= 13 ? POW5_13 : POW5[n];
            n -= Math.min(n, 13);
            long rem = 0;
            for (int i = r.length - 1; i >= 0; i--) {
                long cur = (rem << 32) | (r[i] & 0xFFFF_FFFFL);
                r[i] = (int) (cur / f);
                rem = cur % f;
            }
            // floor(floor(a / f) / g) = floor(a / (f g))
            exact &= rem == 0;
        }
        int len = r.length;
        while (len > 0 && r[len - 1] == 0) {
            len--;
        }
        return new Division(Arrays.copyOf(r, len), exact);
    }

    static int[] shiftLeft(int[] a, int n) {
        if (a.length == 0 || n == 0) {
            return a;
        }
        int words = n >>> 5;
        int bitsIn = n & 31;
        int[] r = new int[a.length + words + 1];
        for (int i = 0; i < a.length; i++) {
            long v = (a[i] & 0xFFFF_FFFFL) << bitsIn;
            r[i + words] |= (int) v;
            r[i + words + 1] = (int) (v >>> 32);
        }
        return r[r.length - 1] != 0 ? r : Arrays.copyOf(r, r.length - 1);
    }

    /** floor(a / 2^n) when it is below 2^63, otherwise -1. */
    static long bitsFrom(int[] a, int n) {
        int words = n >>> 5;
        int bitsIn = n & 31;
        if (a.length > words + 3) {
            return -1;
        }
        long w0 = words < a.length ? a[words] & 0xFFFF_FFFFL : 0;
        long w1 = words + 1 < a.length ? a[words + 1] & 0xFFFF_FFFFL : 0;
        long w2 = words + 2 < a.length ? a[words + 2] & 0xFFFF_FFFFL : 0;
        long low64 = (w1 << 32) | w0;
        long result;
        if (bitsIn == 0) {
            if (w2 != 0) {
                return -1;
            }
            result = low64;
        } else {
            if (w2 >>> bitsIn != 0) {
                return -1;
            }
            result = (low64 >>> bitsIn) | (w2 << (64 - bitsIn));
        }
        return result < 0 ? -1 : result;
    }

    static boolean anyBitBelow(int[] a, int n) {
        int words = n >>> 5;
        for (int i = 0; i < Math.min(words, a.length); i++) {
            if (a[i] != 0) {
                return true;
            }
        }
        int bitsIn = n & 31;
        return bitsIn != 0 && words < a.length && (a[words] & ((1 << bitsIn) - 1)) != 0;
    }
}
