package org.fresa.pocket.compat;

import java.math.BigInteger;
import java.util.Locale;

/**
 * BASIC's {@code STR$} and {@code VAL} for single-precision numbers: how the thesis's program
 * turned its numbers into the 7-digit text it kept in its element records, and back.
 *
 * <p>{@code VAL}: the digits are collected as an integer N and scaled by the decimal exponent
 * with one double-precision (56-bit) division or multiplication, then converted to single by
 * {@code $CSD}, which rounds half away from zero on the first dropped bit (GW-BASIC MATH1.ASM
 * {@code $FIN}/{@code $FINE}, MATH2.ASM {@code $CSD}): the single nearest the decimal text.
 *
 * <p>{@code STR$}: the number's 24-bit mantissa, widened to a 32-bit working mantissa, is divided
 * by ten (a truncating bitwise long division) while it is above 9999999 and multiplied by ten
 * (2x + 8x, the shifted-out bits marking the lowest bit) while it is below 999999.94, the working
 * mantissa being rounded back to 24 bits (half up on its low byte) after each of the two loops;
 * the integer part, rounded half up on the first fraction bit, gives the 7 digits. Trailing zeros
 * are dropped, a non-negative number gets a leading blank, and E notation
 * ({@code 5.255885E-02}) is used when the decimal point would fall more than one place outside
 * the digits. This is the behaviour of the GW-BASIC interpreter as PC-BASIC (a free emulator
 * checked against the real interpreter) reproduces it, and it is not plain rounding to 7 digits:
 * 4.5714283 prints as {@code 4.571429}. Reading MATH2.ASM's {@code $FOTNV} literally instead
 * (scaling by double-precision powers of ten converted back to single, then ×10 and +.5 in single
 * precision) prints 92.966545 as {@code 92.96654}; cavity 07's printed N110 needs
 * {@code 92.96655} there (line 3 at the pre-finish offset becomes 86.16655, not 86.16654, and
 * the junction prints Y 62080, not 62081), so the thesis's runtime printed as the interpreter does.
 *
 * <p>The program writes every offset coefficient back as such text at every move (routine 9500),
 * so each pass starts from the 7-digit number, not from the binary one: {@link #roundTrip}.
 */
public final class BasicNumbers {

    private BasicNumbers() {}

    /**
     * The single nearest to num/den after a 56-bit rounding (nearest, ties to even) and
     * {@code $CSD} (half away from zero on bit 25); num, den > 0.
     */
    static Mbf fromRatio(BigInteger num, BigInteger den, boolean negative) {
        int e = num.bitLength() - den.bitLength();
        // q = num/den · 2^(56 - e'), with 56 or 57 significant bits
        int shift = 57 - e;
        BigInteger n = shift >= 0 ? num.shiftLeft(shift) : num;
        BigInteger d = shift >= 0 ? den : den.shiftLeft(-shift);
        BigInteger[] qr = n.divideAndRemainder(d);
        BigInteger q = qr[0];
        boolean sticky = qr[1].signum() != 0;
        int extra = q.bitLength() - 56;
        // round to 56 bits, nearest, ties to even
        BigInteger keep = q.shiftRight(extra);
        BigInteger dropped = q.subtract(keep.shiftLeft(extra));
        BigInteger half = BigInteger.ONE.shiftLeft(extra - 1);
        int c = dropped.compareTo(half);
        if (c > 0 || (c == 0 && (sticky || keep.testBit(0)))) {
            keep = keep.add(BigInteger.ONE);
        }
        int binExp = q.bitLength() - shift;
        if (keep.bitLength() > 56) {
            keep = keep.shiftRight(1);
            binExp++;
        }
        // $CSD: 24 bits, up when the 25th bit is set
        long m = keep.shiftRight(32).longValue();
        if (keep.testBit(31)) {
            m++;
            if (m >= (1L << 24)) {
                m >>>= 1;
                binExp++;
            }
        }
        // value = 0.m × 2^binExp
        return Mbf.pack(binExp + 128, negative ? 1 : 0, m);
    }

    /** BASIC {@code VAL} of a decimal number (leading blanks, sign, digits, point, E or D exponent). */
    public static Mbf val(String text) {
        String s = text.strip().toUpperCase(Locale.ROOT).replace('D', 'E');
        if (s.isEmpty()) {
            return Mbf.ZERO;
        }
        boolean negative = false;
        int i = 0;
        if (s.charAt(0) == '-' || s.charAt(0) == '+') {
            negative = s.charAt(0) == '-';
            i++;
        }
        BigInteger digits = BigInteger.ZERO;
        int fraction = 0;
        boolean point = false;
        for (; i < s.length(); i++) {
            char ch = s.charAt(i);
            if (ch == '.' && !point) {
                point = true;
            } else if (ch >= '0' && ch <= '9') {
                digits = digits.multiply(BigInteger.TEN).add(BigInteger.valueOf(ch - '0'));
                if (point) {
                    fraction++;
                }
            } else {
                break;
            }
        }
        int exp = 0;
        if (i < s.length() && s.charAt(i) == 'E') {
            int j = i + 1;
            int sign = 1;
            if (j < s.length() && (s.charAt(j) == '-' || s.charAt(j) == '+')) {
                sign = s.charAt(j) == '-' ? -1 : 1;
                j++;
            }
            int v = 0;
            for (; j < s.length() && Character.isDigit(s.charAt(j)); j++) {
                v = v * 10 + s.charAt(j) - '0';
            }
            exp = sign * v;
        }
        if (digits.signum() == 0) {
            return Mbf.ZERO;
        }
        int dx = exp - fraction;
        if (dx == 0 && digits.bitLength() <= 24) {
            Mbf v = Mbf.of(digits.intValue());
            return negative ? v.negate() : v;
        }
        BigInteger num = dx >= 0 ? digits.multiply(BigInteger.TEN.pow(dx)) : digits;
        BigInteger den = dx >= 0 ? BigInteger.ONE : BigInteger.TEN.pow(-dx);
        return fromRatio(num, den, negative);
    }

    /**
     * Working number for {@code STR$}: {exponent byte, 32-bit mantissa with its leading bit at bit
     * 31}, value = mantissa/2^32 · 2^(exponent - 128). Division by ten, bit by bit, truncating.
     */
    private static long[] div10(long exp, long man) {
        long rman = 0xA0000000L;
        long lexp = exp - 0x84 + 160 + 1;
        long work = man;
        long q = 0;
        while (rman > 0) {
            q <<= 1;
            lexp--;
            if (work > rman) {
                work -= rman;
                q++;
            }
            rman >>>= 1;
        }
        while (q < 0x80000000L) {
            lexp--;
            q <<= 1;
        }
        return new long[] {lexp, q};
    }

    /** Multiplication by ten as 2x + 8x; a nonzero bit shifted out of 8x sets the lowest bit. */
    private static long[] mul10(long exp, long man) {
        boolean exact = (man & 3) == 0;
        long m = (man >>> 2) + man;
        long e = exp + 3;
        if (m >= (1L << 32)) {
            e++;
            m >>>= 1;
        }
        if (!exact) {
            m |= 1;
        }
        return new long[] {e, m};
    }

    /** Back to 24 bits: up when the low byte is .5 or more. */
    private static long[] carry(long exp, long man) {
        if ((man & 0xff) > 0x7f) {
            man += 0x100;
        }
        if (man >= (1L << 32)) {
            exp++;
            man >>>= 1;
        }
        return new long[] {exp, man & ~0xffL};
    }

    private static boolean above(long[] a, long e, long m) {
        return a[0] != e ? a[0] > e : a[1] > m;
    }

    private static String format(boolean negative, long n, int dexp) {
        if (n >= 10_000_000L) {
            n /= 10;
            dexp++;
        }
        String sign = negative ? "-" : " ";
        String digits = Long.toString(n);
        int pointAfter = digits.length() + dexp;
        String stripped = digits.replaceAll("0+$", "");
        int exp10 = pointAfter - 1;
        if (exp10 > 6 || stripped.length() - exp10 > 8) {
            String mant = stripped.length() > 1 ? stripped.charAt(0) + "." + stripped.substring(1) : stripped;
            return sign + mant + "E" + (exp10 < 0 ? "-" : "+") + String.format(Locale.ROOT, "%02d", Math.abs(exp10));
        }
        String body;
        if (pointAfter <= 0) {
            body = "." + "0".repeat(-pointAfter) + stripped;
        } else if (pointAfter >= stripped.length()) {
            body = stripped + "0".repeat(pointAfter - stripped.length());
        } else {
            body = stripped.substring(0, pointAfter) + "." + stripped.substring(pointAfter);
        }
        return sign + body;
    }

    /** BASIC {@code STR$} of a single-precision number. */
    public static String str(Mbf x) {
        if (x.isZero()) {
            return " 0";
        }
        long[] w = {x.exponent(), (long) x.mantissa() << 8};
        int exp10 = 0;
        while (above(w, 0x98, 0x98967F00L)) {
            w = div10(w[0], w[1]);
            exp10++;
        }
        w = carry(w[0], w[1]);
        while (!above(w, 0x94, 0xF423FF00L) && !(w[0] == 0x94 && w[1] == 0xF423FF00L)) {
            w = mul10(w[0], w[1]);
            exp10--;
        }
        w = carry(w[0], w[1]);
        long e = w[0] - 152;
        long man = e > 0 ? w[1] << e : w[1] >>> -e;
        if ((man & 0x80) != 0) {
            man += 0x80;
        }
        return format(x.negative(), man >>> 8, exp10);
    }

    /** The number BASIC reads back from {@code STR$(x)}: what routine 9500 leaves in the record. */
    public static Mbf roundTrip(Mbf x) {
        return val(str(x));
    }
}
