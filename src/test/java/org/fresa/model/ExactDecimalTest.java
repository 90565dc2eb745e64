package org.fresa.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import java.util.Random;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ExactDecimalTest {

    @ParameterizedTest
    @CsvSource(textBlock = """
            0.1,                    0.1
            12.5,                   12.5
            -3,                     -3
            0.30000000000000004,    0.30000000000000004
            1.0E-5,                 0.00001
            2.0E23,                 2E23
            123456.789,             123456.789
            """)
    void writesTheShortestRoundTripDecimal(double value, String expected) {
        assertEquals(expected, ExactDecimal.of(value));
    }

    @Test
    void everyRandomDoubleReadsBack() {
        Random rnd = new Random(1);
        for (int i = 0; i < 20000; i++) {
            double d = Double.longBitsToDouble(rnd.nextLong());
            if (!Double.isFinite(d)) {
                continue;
            }
            String s = ExactDecimal.of(d);
            assertEquals(d, Double.parseDouble(s), s);
            double x = (rnd.nextDouble() - 0.5) * 2000;
            assertEquals(x, Double.parseDouble(ExactDecimal.of(x)));
        }
    }

    @Test
    void neverShorterThanJava19WouldBe() {
        // 2^-44 is a value whose Java 17 Double.toString has one digit too many
        double d = Math.scalb(1.0, -44);
        String s = ExactDecimal.of(d);
        assertEquals(d, Double.parseDouble(s));
        assertEquals("5.684341886080802E-14", s);
    }

    @Test
    void nanHasNoDecimal() {
        assertThrows(IllegalArgumentException.class, () -> ExactDecimal.of(Double.NaN));
    }

    @Test
    void writesWhatTheSearchOverBigDecimalRoundingsWrites() {
        // 120 000 values: random bits, CAM magnitudes (few decimals and full precision), angles,
        // powers of two and their neighbours (the narrower interval below them), a few ulps off
        // short decimals, robot errors far below 1e-7, huge values, the two lowest binades; the
        // values of hundreds of digits, slow for the oracle, are a quarter of them
        SplittableRandom rnd = new SplittableRandom(23);
        int checked = 0;
        for (int i = 0; i < 120_000; i++) {
            double d = switch (i % 12) {
                case 0 -> Double.longBitsToDouble(rnd.nextLong());
                case 1 -> Math.round(rnd.nextGaussian() * 1e6) / 1000.0;
                case 2 -> (rnd.nextDouble() * 2 - 1) * 1000;
                case 3 -> Math.copySign(Math.pow(10, rnd.nextDouble() * 40 - 20), rnd.nextDouble() - 0.5);
                case 4 -> Math.toDegrees(Math.atan2(rnd.nextDouble() - 0.5, rnd.nextDouble() - 0.5));
                case 5 ->
                    Double.longBitsToDouble(
                            Double.doubleToRawLongBits(Math.scalb(1.0, rnd.nextInt(-60, 60))) + rnd.nextInt(-2, 3));
                case 6 ->
                    Double.longBitsToDouble(
                            Double.doubleToRawLongBits(rnd.nextInt(1, 1_000_000) * Math.pow(10, rnd.nextInt(-30, 30)))
                                    + rnd.nextInt(-3, 4));
                case 7 -> Math.round(rnd.nextDouble() * 1e9) / Math.pow(10, rnd.nextInt(16));
                case 8 -> Double.longBitsToDouble(rnd.nextLong(1, 0x0020_0000_0000_0000L));
                case 9 -> Math.copySign(Math.pow(10, rnd.nextDouble() * 600 - 300), rnd.nextDouble() - 0.5);
                case 10 -> Math.copySign(Math.pow(10, rnd.nextDouble() * 14 - 24), rnd.nextDouble() - 0.5);
                default -> Math.round(rnd.nextGaussian() * 1e7) / Math.pow(10, rnd.nextInt(0, 9));
            };
            if (Double.isFinite(d)) {
                checked++;
                String expected = bySearch(d);
                assertEquals(expected, ExactDecimal.of(d), () -> "for " + d);
                assertEquals(
                        "a," + expected,
                        ExactDecimal.append(new StringBuilder("a,"), d).toString());
            }
        }
        assertTrue(checked > 100_000, "checked " + checked);
    }

    @Test
    void writesWhatTheSearchWritesAtTheEdges() {
        double[] edges = {
            Double.MIN_VALUE,
            -Double.MIN_VALUE,
            2 * Double.MIN_VALUE,
            Double.MIN_NORMAL,
            Math.nextDown(Double.MIN_NORMAL),
            Math.nextUp(Double.MIN_NORMAL),
            2 * Double.MIN_NORMAL,
            Math.nextDown(2 * Double.MIN_NORMAL),
            Double.MAX_VALUE,
            -Double.MAX_VALUE,
            Math.nextDown(Double.MAX_VALUE),
            1e-7,
            Math.nextDown(1e-7),
            Math.nextUp(1e-7),
            1e15,
            Math.nextDown(1e15),
            Math.nextUp(1e15),
            1e16,
            Math.nextDown(1e16),
            Math.nextUp(1e16),
            1e18,
            Math.nextUp(1e18),
            1e23,
            9007199254740993.0,
            12345678901234566.0,
            2.2934200000000004E25,
            0.1,
            0.2,
            0.3,
            1.0 / 3,
            2.0 / 3,
            5e-324,
            4.9e-324,
            1.7976931348623157E308,
            Math.PI,
            Math.E,
            123456.789,
            0.1234567,
            1.2345678901234567E-7,
            9.5e-8,
            1.0181791354279307E-17
        };
        for (double d : edges) {
            assertEquals(bySearch(d), ExactDecimal.of(d), () -> "for " + d);
            assertEquals(d, Double.parseDouble(ExactDecimal.of(d)));
        }
        for (int i = 1; i < 1000; i++) {
            for (double d : new double[] {
                i / 1000.0,
                i * 0.001,
                i / 7.0,
                i * 1e-9,
                i * 1e20,
                Math.scalb(1.0, i - 500),
                Math.scalb(1.0, i - 1075),
                Math.nextDown(Math.scalb(1.0, i + 24))
            }) {
                assertEquals(bySearch(d), ExactDecimal.of(d), () -> "for " + d);
            }
        }
        assertEquals("9.5E-8", ExactDecimal.of(9.5e-8));
        assertEquals("-1E-300", ExactDecimal.of(-1e-300));
        assertEquals("0.000000123456789012345", ExactDecimal.of(1.23456789012345E-7));
    }

    @Test
    void multiWordArithmeticIsExact() {
        int[] p = ExactDecimal.mulPow5(ExactDecimal.of(3), 40);
        java.math.BigInteger expected =
                java.math.BigInteger.valueOf(5).pow(40).multiply(java.math.BigInteger.valueOf(3));
        assertEquals(expected.shiftRight(40).longValueExact(), ExactDecimal.bitsFrom(p, 40));
        assertEquals(expected.getLowestSetBit() < 40, ExactDecimal.anyBitBelow(p, 40));
        assertEquals(-1, ExactDecimal.bitsFrom(p, 0));
        ExactDecimal.Division q = ExactDecimal.divPow5(ExactDecimal.shiftLeft(p, 3), 40);
        assertEquals(24, ExactDecimal.bitsFrom(q.quotient(), 0));
        assertTrue(q.exact());
        ExactDecimal.Division r = ExactDecimal.divPow5(ExactDecimal.of(1L << 62), 20);
        assertEquals((1L << 62) / 95367431640625L, ExactDecimal.bitsFrom(r.quotient(), 0));
        assertEquals(false, r.exact());
    }

    /**
     * The oracle: a binary search over the number of significant digits, with BigDecimal, for
     * the decimal of the fewest digits nearest to d that reads back. It searches up to 17 digits
     * (always enough) instead of starting from Java 17's {@code Double.toString}: between 2e25
     * and 4e25 that gives 17 digits that read back but are not the nearest ones
     * (2.2934200000000004E25 for 22934200000000004968153088), and the writer no longer calls it.
     */
    static String bySearch(double d) {
        BigDecimal exact = new BigDecimal(d);
        BigDecimal best = roundTrip(exact, d, 17);
        int lo = 1;
        int hi = 17;
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
