package org.fresa.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class TinyDecimalTest {

    @Test
    void writesWhatTheDigitsPathWrites() {
        // the exact multi-word comparison against the BigDecimal digits it replaced below 1e-7
        // (checked by hand on 5 million more values of these kinds): random normal bits, robot
        // errors and near-zero joint angles, powers of two and their neighbours (the narrower
        // interval below them), a few ulps off short decimals, the range's ends
        SplittableRandom rnd = new SplittableRandom(7);
        int checked = 0;
        for (int i = 0; i < 60_000; i++) {
            double d = switch (i % 6) {
                case 0 -> Double.longBitsToDouble(rnd.nextLong(0x0020_0000_0000_0000L,
                        Double.doubleToRawLongBits(TinyDecimal.LIMIT)));
                case 1 -> Math.copySign(Math.pow(10, -7 - rnd.nextDouble() * 14), rnd.nextDouble() - 0.5);
                case 2 -> Math.scalb(1.0, rnd.nextInt(-1020, -24));
                case 3 -> Double.longBitsToDouble(Double.doubleToRawLongBits(Math.scalb(1.0, rnd.nextInt(-1020, -24)))
                        + rnd.nextInt(-2, 3));
                case 4 -> Double.longBitsToDouble(Double.doubleToRawLongBits(
                        rnd.nextInt(1, 1_000_000) * Math.pow(10, -rnd.nextInt(8, 300))) + rnd.nextInt(-3, 4));
                default -> Double.longBitsToDouble(Double.doubleToRawLongBits(TinyDecimal.LIMIT) - rnd.nextInt(1, 1000));
            };
            String tiny = TinyDecimal.shortest(d);
            if (tiny != null) {
                checked++;
                assertEquals(ExactDecimal.byDigits(d), tiny, () -> "for " + d);
                assertEquals(d, Double.parseDouble(tiny));
            }
        }
        assertTrue(checked > 59_000, "checked " + checked);
    }

    @Test
    void writesScientificNotationAsTheReference() {
        assertEquals("9.5E-8", ExactDecimal.of(9.5e-8));
        assertEquals("-1E-300", ExactDecimal.of(-1e-300));
        assertEquals("1.0181791354279307E-17", ExactDecimal.of(1.0181791354279307E-17));
        assertEquals("5.684341886080802E-14", TinyDecimal.shortest(Math.scalb(1.0, -44)));
    }

    @Test
    void leavesTheLowestBinadesAndOrdinaryMagnitudesToOthers() {
        assertNull(TinyDecimal.shortest(Double.MIN_VALUE));
        assertNull(TinyDecimal.shortest(Double.MIN_NORMAL));
        assertNull(TinyDecimal.shortest(1e-7));
        assertNull(TinyDecimal.shortest(0.5));
        // the reference still answers there
        assertEquals(Double.MIN_VALUE, Double.parseDouble(ExactDecimal.of(Double.MIN_VALUE)));
    }

    @Test
    void multiWordHelpersAreExact() {
        int[] p = TinyDecimal.mulPow5(TinyDecimal.of(3), 40);
        java.math.BigInteger expected = java.math.BigInteger.valueOf(5).pow(40).multiply(java.math.BigInteger.valueOf(3));
        assertEquals(expected.shiftRight(40).longValueExact(), TinyDecimal.bitsFrom(p, 40));
        assertEquals(expected.getLowestSetBit() < 40, TinyDecimal.anyBitBelow(p, 40));
        assertEquals(-1, TinyDecimal.bitsFrom(p, 0));
        assertEquals(0, TinyDecimal.compare(TinyDecimal.shiftLeft(TinyDecimal.of(5), 70),
                TinyDecimal.mulPow5(TinyDecimal.shiftLeft(TinyDecimal.of(1), 70), 1)));
        assertEquals(1, TinyDecimal.compare(1, 0, 1, -1));
        assertEquals(-1, TinyDecimal.compare(1, -1, 1, -3));
        assertEquals(0, TinyDecimal.compare(5, -1, 1, -1));
    }
}
