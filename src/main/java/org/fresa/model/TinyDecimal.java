package org.fresa.model;

/**
 * {@link ExactDecimal}'s answer for the normal doubles below 1e-7, in exact multi-word integer
 * arithmetic. A robot trajectory has thousands of them (position errors of 1e-10 mm, joint
 * angles of 1e-17 deg): through BigDecimal's exact digits each one cost more than a whole row of
 * ordinary numbers in a cold JVM, and the JIT's time for BigInteger's division on top.
 *
 * <p>The method is {@code ExactDecimal.shortest}'s, with wider words: the first 18 significant
 * digits of d = M 2^E are floor(M 5^j 2^(E+j)) for j = 17 - floor(log10 d), and a candidate
 * c 10^s reads back as d when it lies inside d's rounding interval, compared exactly. Numbers are
 * little-endian arrays of unsigned 32-bit words without leading zero words (at most about 30 of
 * them: 5^341 times a 55-bit integer).
 */
final class TinyDecimal {
    static final double LIMIT = 1e-7;

    private static final long HIDDEN = 0x0010_0000_0000_0000L;
    private static final long POW10_17 = 100_000_000_000_000_000L;
    private static final long POW10_18 = 1_000_000_000_000_000_000L;
    private static final long[] POW10L = new long[19];
    /** 5^13, the largest power of five below 2^31. */
    private static final long POW5_13 = 1_220_703_125L;
    private static final long[] POW5 = new long[14];

    static {
        POW10L[0] = 1;
        for (int i = 1; i < POW10L.length; i++) {
            POW10L[i] = POW10L[i - 1] * 10;
        }
        POW5[0] = 1;
        for (int i = 1; i < POW5.length; i++) {
            POW5[i] = POW5[i - 1] * 5;
        }
    }

    private TinyDecimal() {
    }

    /**
     * The shortest round-trip decimal of d in scientific notation as {@code BigDecimal.toString}
     * writes it ("9.5E-8", "-1E-300"), or null when |d| is not a normal double below
     * {@link #LIMIT} (the two lowest binades are left to the reference: their rounding interval
     * is not the usual one).
     */
    static String shortest(double d) {
        double mag = Math.abs(d);
        long bits = Double.doubleToRawLongBits(mag);
        int biased = (int) (bits >>> 52);
        if (!(mag < LIMIT) || biased <= 1) {
            return null;
        }
        long m = (bits & (HIDDEN - 1)) | HIDDEN;
        int e = biased - 1075;
        int k = (int) Math.floor(Math.log10(mag));
        long c18 = -1;
        boolean sticky = false;
        for (int attempt = 0; attempt < 3; attempt++) {
            int j = 17 - k;
            int shift = -(e + j);
            if (j < 0 || shift < 0) {
                return null;
            }
            int[] big = mulPow5(of(m), j);
            long q = bitsFrom(big, shift);
            if (q < 0 || q >= POW10_18) {
                k++;
            } else if (q < POW10_17) {
                k--;
            } else {
                c18 = q;
                sticky = anyBitBelow(big, shift);
                break;
            }
        }
        if (c18 < 0) {
            return null;
        }
        boolean even = (m & 1) == 0;
        // the interval's ends in units of 2^(E-2); below a power of two the lower half is narrower
        long lowQ = m == HIDDEN ? 4 * m - 1 : 4 * m - 2;
        long highQ = 4 * m + 2;
        long bestC = -1;
        int bestS = 0;
        for (int p = 17; p >= 1; p--) {
            long unit = POW10L[18 - p];
            long down = c18 / unit;
            long rest = c18 - down * unit;
            boolean anyRest = rest != 0 || sticky;
            boolean nearIsUp = 2 * rest > unit || (2 * rest == unit && (sticky || (down & 1) == 1));
            long near = nearIsUp ? down + 1 : down;
            long up = anyRest ? down + 1 : down;
            int s = k - p + 1;
            long found = -1;
            if (readsBack(near, s, e, lowQ, highQ, even)) {
                found = near;
            } else if (readsBack(down, s, e, lowQ, highQ, even)) {
                found = down;
            } else if (readsBack(up, s, e, lowQ, highQ, even)) {
                found = up;
            }
            if (found < 0) {
                break;
            }
            bestC = found;
            bestS = s;
        }
        if (bestC <= 0) {
            return null;
        }
        while (bestC % 10 == 0) {
            bestC /= 10;
            bestS++;
        }
        String digits = Long.toString(bestC);
        int adjusted = bestS + digits.length() - 1;
        StringBuilder sb = new StringBuilder(digits.length() + 8);
        if (d < 0) {
            sb.append('-');
        }
        sb.append(digits.charAt(0));
        if (digits.length() > 1) {
            sb.append('.').append(digits, 1, digits.length());
        }
        return sb.append('E').append(adjusted).toString();
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

    /** The sign of c 10^s - q 2^b, exactly (c, q >= 0). */
    static int compare(long c, int s, long q, int b) {
        // c 5^s 2^s against q 2^b; a negative s moves 5^-s to the right-hand side
        int[] left = of(c);
        int[] right = of(q);
        if (s >= 0) {
            left = mulPow5(left, s);
        } else {
            right = mulPow5(right, -s);
        }
        int n = s - b;
        if (n >= 0) {
            left = shiftLeft(left, n);
        } else {
            right = shiftLeft(right, -n);
        }
        return compare(left, right);
    }

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
        return carry != 0 ? r : java.util.Arrays.copyOf(r, a.length);
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
        return r[r.length - 1] != 0 ? r : java.util.Arrays.copyOf(r, r.length - 1);
    }

    /** The sign of a - b, both without leading zero words. */
    static int compare(int[] a, int[] b) {
        if (a.length != b.length) {
            return a.length < b.length ? -1 : 1;
        }
        for (int i = a.length - 1; i >= 0; i--) {
            if (a[i] != b[i]) {
                return Integer.compareUnsigned(a[i], b[i]);
            }
        }
        return 0;
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
