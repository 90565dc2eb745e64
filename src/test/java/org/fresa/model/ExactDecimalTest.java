package org.fresa.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

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
}
