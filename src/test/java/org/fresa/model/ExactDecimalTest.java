package org.fresa.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
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
    void theFastPathWritesWhatTheSearchWrites() {
        // issue 11: decimals of CAM magnitudes are found without BigDecimal; same text as the search
        Random rnd = new Random(11);
        for (int i = 0; i < 60_000; i++) {
            double d = switch (i % 5) {
                case 0 -> Math.round(rnd.nextGaussian() * 1e6) / 1000.0;
                case 1 -> rnd.nextGaussian() * 500;
                case 2 -> Math.round(rnd.nextDouble() * 1e9) / Math.pow(10, rnd.nextInt(16));
                case 3 -> (rnd.nextDouble() - 0.5) * Math.pow(10, rnd.nextInt(24) - 8);
            default -> Math.scalb(1.0 + rnd.nextInt(1 << 20), rnd.nextInt(200) - 100);
            };
            if (d != Math.rint(d) || Math.abs(d) >= 1e15) {
                assertEquals(ExactDecimal.bySearch(d), ExactDecimal.of(d), () -> "for " + d);
            }
        }
    }

    @Test
    void theIntegerPathWritesWhatTheDigitsPathWrites() {
        // the exact 128-bit comparison against the BigDecimal digits it replaced (checked by hand
        // on 10 million more values of these kinds); random bits, CAM magnitudes, powers of two and
        // their neighbours (the narrower interval below), a few ulps off short decimals
        java.util.SplittableRandom rnd = new java.util.SplittableRandom(11);
        int checked = 0;
        for (int i = 0; i < 70_000; i++) {
            double d = switch (i % 7) {
                case 0 -> Double.longBitsToDouble(rnd.nextLong());
                case 1 -> (rnd.nextDouble() * 2 - 1) * 1000;
                case 2 -> Math.copySign(Math.pow(10, rnd.nextDouble() * 22 - 7), rnd.nextDouble() - 0.5);
                case 3 -> Math.scalb(1.0, rnd.nextInt(-23, 50));
                case 4 -> Double.longBitsToDouble(Double.doubleToRawLongBits(
                        Math.round(rnd.nextDouble() * 1e6) / Math.pow(10, rnd.nextInt(1, 9))) + rnd.nextInt(-3, 4));
                case 5 -> Math.toDegrees(Math.atan2(rnd.nextDouble() - 0.5, rnd.nextDouble() - 0.5));
                default -> Double.longBitsToDouble(Double.doubleToRawLongBits(Math.scalb(1.0, rnd.nextInt(-23, 50)))
                        + rnd.nextInt(-2, 3));
            };
            String fast = Double.isFinite(d) ? ExactDecimal.shortest(d) : null;
            if (fast != null) {
                checked++;
                assertEquals(ExactDecimal.byDigits(d), fast, () -> "for " + d);
            }
        }
        assertTrue(checked > 50_000, "checked " + checked);
    }

    @Test
    void appendWritesWhatOfWritesAfterTheBuildersText() {
        java.util.SplittableRandom rnd = new java.util.SplittableRandom(5);
        for (int i = 0; i < 20_000; i++) {
            double d = switch (i % 4) {
                case 0 -> Double.longBitsToDouble(rnd.nextLong());
                case 1 -> Math.round(rnd.nextGaussian() * 1e7) / Math.pow(10, rnd.nextInt(0, 9));
                case 2 -> Math.copySign(Math.pow(10, rnd.nextDouble() * 30 - 12), rnd.nextDouble() - 0.5);
                default -> Math.toDegrees(Math.atan2(rnd.nextDouble() - 0.5, rnd.nextDouble() - 0.5));
            };
            if (Double.isFinite(d)) {
                String expected = ExactDecimal.of(d);
                assertEquals("a," + expected, ExactDecimal.append(new StringBuilder("a,"), d).toString());
                if (d != Math.rint(d)) {
                    assertEquals(ExactDecimal.byDigits(d), expected, () -> "for " + d);
                }
            }
        }
        // seven decimals and more go past the few-decimals path; 18 and more fraction digits
        assertEquals("0.1234567", ExactDecimal.of(0.1234567));
        double small = 1.2345678901234567E-7;
        assertEquals(ExactDecimal.byDigits(small), ExactDecimal.of(small));
        assertTrue(ExactDecimal.of(small).startsWith("0.000000123456789012345"), ExactDecimal.of(small));
    }
}
