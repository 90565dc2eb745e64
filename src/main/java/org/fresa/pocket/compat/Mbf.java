package org.fresa.pocket.compat;

/**
 * A single-precision number in Microsoft Binary Format (MBF), with the arithmetic of the 8086
 * math package that Microsoft's BASIC interpreter and compiler runtime shared (GW-BASIC's
 * MATH1.ASM and MATH2.ASM, published by Microsoft under the MIT licence): the arithmetic the 1988
 * thesis's program ran in.
 *
 * <p>Layout, as four bytes in memory: mantissa low, mantissa middle, sign bit and mantissa high
 * 7 bits, exponent. The value is 0.1mmm... (binary, the leading 1 implied) × 2^(exponent - 128);
 * exponent 0 is zero. The mantissa has 24 bits like an IEEE single, so every MBF value with an
 * exponent byte from 3 to 254 is exactly a Java {@code float}; the exponent bias and the rounding
 * differ:
 * <ul>
 * <li>addition and subtraction align the smaller operand with a guard byte whose bits below the
 * top two collapse into a sticky bit (bit 5) that is set again at every single-bit shift, so the
 * guard byte keeps low garbage; the result is rounded on the top three guard bits only, a tie
 * (100) going to even ({@code $FADDS}, {@code $NORMS}, {@code $ROUNS}). A subtraction with a
 * far smaller operand can so round half an ulp the other way from an IEEE subtraction;
 * <li>multiplication adds 16-bit partial products, dropping the low half of the low × low product,
 * and rounds on the top three bits of the remaining guard byte, a tie going to even
 * ({@code $FMULS});
 * <li>division is a long division with a sticky remainder bit, rounded to nearest with ties to
 * even ({@code $FDIVS}): the same result as IEEE division;
 * <li>{@code x^n} for an integral n below 32768 is repeated squaring ({@code XTON}), so
 * {@code x^2} is {@code x*x}; the thesis's square roots, written {@code x^.5}, are exact
 * (correctly rounded) roots, as {@code SQR} computes them bit by bit. The GW-BASIC interpreter's
 * {@code $FPWR} computes every non-integral power as {@code EXP(y*LOG(x))} with its polynomial
 * LOG and EXP ({@link MbfFunctions}), several ulps off ({@code 10000^.5} = 99.99999); the printed
 * programs show the thesis's compiled program did not: cavity 04's zero-radius arc at the corner
 * (40, 30) is the junction of y = 30 and circle 2, x = (180 - √10000)/2, written back as text;
 * with 99.99999 it reads 40.00001, the junction of that arc with circle 2 one offset later is no
 * longer a tangency and N90 prints Y 29978 for the printed 30000 (cavity 02 likewise loses N75);
 * with the exact root all of cavity 02 and 04 print as in the thesis. Other non-integral powers
 * (none in the program) keep the interpreter's EXP(y·LOG(x));
 * <li>{@code INT} is the floor.
 * </ul>
 *
 * @param bits the four bytes as a little-endian int (mantissa low byte lowest, exponent highest)
 */
public record Mbf(int bits) implements Comparable<Mbf> {

    public static final Mbf ZERO = new Mbf(0);
    public static final Mbf ONE = new Mbf(0x81000000);

    private static final int HIDDEN = 0x800000;
    private static final Mbf HALF_POWER = new Mbf(0x80000000);

    /** The MBF value of a float (exact for every float of the pocket's size range). */
    public static Mbf of(float f) {
        if (f == 0) {
            return ZERO;
        }
        if (!Float.isFinite(f)) {
            throw new IllegalArgumentException("not a finite number: " + f);
        }
        int ieee = Float.floatToIntBits(f);
        int sign = ieee >>> 31;
        int e = (ieee >>> 23) & 0xff;
        int m = ieee & 0x7fffff;
        if (e == 0) {
            // subnormal float: normalise (far below any length the thesis handles)
            int shift = Integer.numberOfLeadingZeros(m) - 8;
            m = (m << shift) & 0x7fffff;
            e = 1 - shift;
        }
        return pack(e + 2, sign, m | HIDDEN);
    }

    /** An integer, exactly (|n| < 2^24). */
    public static Mbf of(int n) {
        return of((float) n);
    }

    /** The value as a double (exact). */
    public double toDouble() {
        int e = exponent();
        if (e == 0) {
            return 0;
        }
        double v = Math.scalb((double) mantissa(), e - 128 - 24);
        return negative() ? -v : v;
    }

    /** The value as a float (exact for exponent bytes 3 to 254). */
    public float toFloat() {
        return (float) toDouble();
    }

    int exponent() {
        return (bits >>> 24) & 0xff;
    }

    boolean negative() {
        return exponent() != 0 && (bits & 0x800000) != 0;
    }

    /** The 24-bit mantissa with its leading 1. */
    int mantissa() {
        return (bits & 0x7fffff) | HIDDEN;
    }

    public boolean isZero() {
        return exponent() == 0;
    }

    static Mbf pack(int e, int sign, long m) {
        if (e <= 0 || m == 0) {
            return ZERO;
        }
        if (e > 255) {
            throw new ArithmeticException("Overflow");
        }
        return new Mbf((e << 24) | (sign << 23) | (int) (m & 0x7fffff));
    }

    public Mbf negate() {
        return isZero() ? this : new Mbf(bits ^ 0x800000);
    }

    public Mbf abs() {
        return negative() ? negate() : this;
    }

    /** {@code $ROUNS}: rounds the 24-bit mantissa m on the top three bits of the guard byte. */
    private static Mbf round(int e, int sign, long m, int guard) {
        int ah = (guard & 0xE0) + 0x80;
        if (ah < 0x100) {
            return pack(e, sign, m);
        }
        ah &= 0xff;
        m++;
        if (m >= (1L << 24)) {
            m = HIDDEN;
            e++;
        } else if (ah == 0) {
            m &= ~1L;
        }
        return pack(e, sign, m);
    }

    /** {@code $NORMS}: shifts the mantissa and guard byte left until the leading bit is set, then rounds. */
    private static Mbf normalise(int e, int sign, long mantissaAndGuard) {
        long x = mantissaAndGuard;
        if (x == 0) {
            return ZERO;
        }
        while ((x & 0x80000000L) == 0) {
            x <<= 1;
            e--;
            if (e <= 0) {
                return ZERO;
            }
        }
        return round(e, sign, x >>> 8, (int) (x & 0xff));
    }

    /** {@code $FADDS}: this + other. */
    public Mbf plus(Mbf other) {
        if (other.isZero()) {
            return this;
        }
        if (isZero()) {
            return other;
        }
        Mbf big = this;
        Mbf small = other;
        if (other.exponent() > exponent()) {
            big = other;
            small = this;
        }
        int shift = big.exponent() - small.exponent();
        int sign = big.negative() ? 1 : 0;
        boolean subtract = big.negative() != small.negative();
        if (shift >= 25) {
            return big;
        }
        long mb = small.mantissa();
        int ah = 0;
        while (shift > 0) {
            if (shift >= 8) {
                int old = ah;
                ah = (int) (mb & 0xff);
                if (old != 0) {
                    ah |= 0x20;
                }
                mb >>>= 8;
                shift -= 8;
                if ((ah & 0x1f) != 0) {
                    ah |= 0x20;
                }
            } else {
                ah = (int) ((mb & 1) << 7) | (ah >>> 1);
                mb >>>= 1;
                if ((ah & 0x10) != 0) {
                    ah |= 0x20;
                }
                shift--;
            }
        }
        long ma = big.mantissa();
        int e = big.exponent();
        if (!subtract) {
            long m = ma + mb;
            if (m >= (1L << 24)) {
                e++;
                ah = (int) ((m & 1) << 7) | (ah >>> 1);
                m >>>= 1;
            }
            return round(e, sign, m, ah);
        }
        long x = (ma << 8) - ((mb << 8) | ah);
        if (x < 0) {
            x = -x;
            sign ^= 1;
        }
        return normalise(e, sign, x);
    }

    public Mbf minus(Mbf other) {
        return plus(other.negate());
    }

    /** {@code $FMULS}: this × other. */
    public Mbf times(Mbf other) {
        if (isZero() || other.isZero()) {
            return ZERO;
        }
        long a = mantissa();
        long b = other.mantissa();
        long loA = a & 0xffff, hiA = a >>> 16;
        long loB = b & 0xffff, hiB = b >>> 16;
        long acc = ((loA * loB) >>> 16) + loA * hiB + hiA * loB + ((hiA * hiB) << 16);
        int sign = negative() != other.negative() ? 1 : 0;
        int e;
        if ((acc & 0x80000000L) != 0) {
            e = exponent() + other.exponent() - 128;
        } else {
            acc <<= 1;
            e = exponent() + other.exponent() - 129;
        }
        if (e <= 0) {
            return ZERO;
        }
        return round(e, sign, acc >>> 8, (int) (acc & 0xff));
    }

    /** {@code $FDIVS}: this / other. */
    public Mbf dividedBy(Mbf other) {
        if (other.isZero()) {
            throw new ArithmeticException("Division by zero");
        }
        if (isZero()) {
            return ZERO;
        }
        long num = (long) mantissa() << 31;
        long q = num / other.mantissa();
        if (num % other.mantissa() != 0) {
            q |= 1;
        }
        int sign = negative() != other.negative() ? 1 : 0;
        int e;
        if ((q & 0x80000000L) != 0) {
            e = exponent() - other.exponent() + 129;
        } else {
            q <<= 1;
            e = exponent() - other.exponent() + 128;
        }
        if (e <= 0) {
            return ZERO;
        }
        long m = q >>> 8;
        int ext = (int) (q & 0xff);
        if (ext > 0x80 || (ext == 0x80 && (m & 1) != 0)) {
            m++;
            if (m >= (1L << 24)) {
                m >>>= 1;
                e++;
            }
        }
        return pack(e, sign, m);
    }

    /** BASIC's INT: the largest integer not above the value. */
    public Mbf floor() {
        double v = toDouble();
        double f = Math.floor(v);
        return f == v ? this : of((float) f);
    }

    /** True when the value is an integer. */
    public boolean isIntegral() {
        return Math.floor(toDouble()) == toDouble();
    }

    /** {@code XTON}: this^n for 0 <= n < 32768 by repeated squaring (Knuth vol. 2 p. 400). */
    public Mbf pow(int n) {
        if (n < 0 || n >= 32768) {
            throw new IllegalArgumentException("integral power out of range: " + n);
        }
        Mbf y = ONE;
        Mbf z = this;
        int k = n;
        while (true) {
            if ((k & 1) != 0) {
                y = y.times(z);
            }
            k >>>= 1;
            if (k == 0) {
                return y;
            }
            z = z.times(z);
        }
    }

    /** {@code $FPWR}: this^y; integral y below 32768 by squaring, otherwise EXP(y·LOG(this)). */
    public Mbf pow(Mbf y) {
        if (y.isZero()) {
            return ONE;
        }
        if (isZero()) {
            return ZERO;
        }
        if (y.isIntegral() && y.abs().toDouble() < 32768) {
            Mbf p = pow((int) y.abs().toDouble());
            return y.negative() ? ONE.dividedBy(p) : p;
        }
        if (negative()) {
            throw new ArithmeticException("Illegal function call");
        }
        if (y.equals(HALF_POWER)) {
            return MbfFunctions.sqr(this);
        }
        return MbfFunctions.exp(y.times(MbfFunctions.log(this)));
    }

    /** Exact comparison of the values. */
    @Override
    public int compareTo(Mbf o) {
        return Double.compare(toDouble(), o.toDouble());
    }

    public boolean greaterThan(Mbf o) {
        return compareTo(o) > 0;
    }

    public boolean lessThan(Mbf o) {
        return compareTo(o) < 0;
    }

    @Override
    public String toString() {
        return BasicNumbers.str(this);
    }
}
