package org.fresa.pocket.compat;

/**
 * The single-precision LOG and EXP of Microsoft's 8086 math package (GW-BASIC MATH1.ASM /
 * MATH2.ASM), which its {@code ^} uses for every non-integral power: the thesis's {@code x^.5}.
 *
 * <p>LOG(x): x = m·2^e with m in [.5, 1); log2(m) = P(m)/Q(m) (Hart's approximation 2524, two
 * cubics evaluated by Horner's rule in single precision); LOG(x) = (e + P/Q)·ln 2.
 * EXP(x): y = x·log2(e); n = INT(y); 2^(y - n) by Hart's polynomial 1302 of degree 6; times 2^n.
 * The coefficients are the package's own four-byte constants, kept here as those bytes.
 */
public final class MbfFunctions {

    private MbfFunctions() {}

    /** The four MBF bytes written in octal in the package's tables (mantissa low first). */
    private static Mbf octal(int b0, int b1, int b2, int exp) {
        return new Mbf(oct(b0) | oct(b1) << 8 | oct(b2) << 16 | oct(exp) << 24);
    }

    private static int oct(int written) {
        return Integer.parseInt(Integer.toString(written), 8);
    }

    private static final Mbf[] LOG_P = {
        octal(232, 367, 31, 203), octal(44, 143, 103, 203), octal(165, 315, 215, 204), octal(251, 177, 203, 202)
    };
    private static final Mbf[] LOG_Q = {
        octal(0, 0, 0, 201), octal(342, 260, 115, 203), octal(12, 162, 21, 203), octal(364, 4, 65, 177)
    };
    private static final Mbf LN2 = octal(30, 162, 61, 200);
    private static final Mbf LOG2_E = octal(73, 252, 70, 201);
    private static final Mbf[] EXP_C = {
        octal(174, 210, 131, 164),
        octal(340, 227, 46, 167),
        octal(304, 35, 36, 172),
        octal(136, 120, 143, 174),
        octal(32, 376, 165, 176),
        octal(30, 162, 61, 200),
        octal(0, 0, 0, 201)
    };

    /** {@code $POLY}: Horner's rule, highest coefficient first, in single precision. */
    static Mbf poly(Mbf x, Mbf[] coefficients) {
        Mbf acc = coefficients[0];
        for (int i = 1; i < coefficients.length; i++) {
            acc = acc.times(x).plus(coefficients[i]);
        }
        return acc;
    }

    /**
     * {@code SQR}: the bit-by-bit square root of the package (25 bits, the last one rounding), the
     * correctly rounded root.
     */
    public static Mbf sqr(Mbf x) {
        if (x.isZero()) {
            return Mbf.ZERO;
        }
        if (x.negative()) {
            throw new ArithmeticException("Illegal function call");
        }
        // x = M·2^E with M the 24-bit mantissa; make E even and scale M so the root has 33 bits
        long m = x.mantissa();
        int e = x.exponent() - 128 - 24;
        if ((e & 1) != 0) {
            m <<= 1;
            e--;
        }
        java.math.BigInteger n = java.math.BigInteger.valueOf(m).shiftLeft(40);
        java.math.BigInteger q = n.sqrt();
        int bits = q.bitLength();
        long r = q.shiftRight(bits - 25).longValue();
        long root = (r >>> 1) + (r & 1);
        int exp = bits + (e - 40) / 2;
        if (root >= (1L << 24)) {
            root >>>= 1;
            exp++;
        }
        return Mbf.pack(exp + 128, 0, root);
    }

    /** Natural logarithm of a positive number. */
    public static Mbf log(Mbf x) {
        if (x.isZero() || x.negative()) {
            throw new ArithmeticException("Illegal function call");
        }
        if (x.equals(Mbf.ONE)) {
            return Mbf.ZERO;
        }
        int e = x.exponent() - 128;
        Mbf m = new Mbf((x.bits() & 0x00ffffff) | (0x80 << 24));
        Mbf ratio = poly(m, LOG_P).dividedBy(poly(m, LOG_Q));
        return Mbf.of(e).plus(ratio).times(LN2);
    }

    /** e^x. */
    public static Mbf exp(Mbf x) {
        Mbf y = x.times(LOG2_E);
        int eb = y.exponent();
        if (eb >= 0210) {
            if (y.negative()) {
                return Mbf.ZERO;
            }
            throw new ArithmeticException("Overflow");
        }
        if (eb < 0150) {
            return Mbf.ONE;
        }
        Mbf n = y.floor();
        Mbf f = y.minus(n);
        int ni = (int) n.toDouble();
        Mbf twoToN = new Mbf(((ni + 0201) & 0xff) << 24);
        return poly(f, EXP_C).times(twoToN);
    }
}
