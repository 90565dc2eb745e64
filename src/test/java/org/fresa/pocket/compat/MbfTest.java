package org.fresa.pocket.compat;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class MbfTest {

    private static Mbf bits(String hex) {
        return new Mbf((int) Long.parseLong(hex, 16));
    }

    private static String hex(Mbf x) {
        return String.format(java.util.Locale.ROOT, "%08x", x.bits());
    }

    @Test
    void floatsConvertBothWaysExactly() {
        Random r = new Random(11);
        for (int i = 0; i < 10_000; i++) {
            float f = (float) ((r.nextDouble() - 0.5) * Math.pow(10, r.nextInt(12) - 6));
            assertEquals(f, Mbf.of(f).toFloat());
        }
        assertAll(
                () -> assertEquals(0x81000000, Mbf.ONE.bits()),
                () -> assertEquals(0x80000000, Mbf.of(0.5f).bits()),
                () -> assertEquals(0x84a00000, Mbf.of(-10f).bits()));
    }

    @Test
    void divisionIsRoundedToNearestLikeIeee() {
        Random r = new Random(12);
        for (int i = 0; i < 20_000; i++) {
            float a = (float) ((r.nextDouble() - 0.5) * Math.pow(10, r.nextInt(8) - 3));
            float b = (float) ((r.nextDouble() - 0.5) * Math.pow(10, r.nextInt(8) - 3));
            assertEquals(a / b, Mbf.of(a).dividedBy(Mbf.of(b)).toFloat(), a + " / " + b);
        }
    }

    /** Recorded with PC-BASIC 2.0.8, an emulator of the GW-BASIC interpreter checked against the real one. */
    @ParameterizedTest
    @CsvSource(textBlock = """
            783f1ed9, 7d19cb1f, 7465a228
            825bf466, 83ca2caa, 85adb538
            7d158d61, 79200ee7, 753b0222
            7a164a91, 8c0847db, 85200398
            8018ca4d, 781dbb30, 773c4793
            862c136d, 837b23d6, 8928cf22
            """)
    void multiplicationIsTheInterpretersTruncatedPartialProducts(String a, String b, String product) {
        Mbf p = bits(a).times(bits(b));
        assertEquals(product, hex(p));
    }

    @Test
    void multiplicationCanRoundOtherwiseThanIeee() {
        // the low half of the low × low partial product is dropped and three guard bits decide
        Mbf a = bits("825bf466");
        Mbf b = bits("83ca2caa");
        assertNotEquals(a.toFloat() * b.toFloat(), a.times(b).toFloat());
    }

    @Test
    void additionRoundsOnItsStickyGuardByte() {
        Random r = new Random(13);
        int differ = 0;
        for (int i = 0; i < 20_000; i++) {
            float a = (float) ((r.nextDouble() - 0.5) * Math.pow(10, r.nextInt(6) - 2));
            float b = (float) ((r.nextDouble() - 0.5) * Math.pow(10, r.nextInt(6) - 2));
            float ieee = a + b;
            float mbf = Mbf.of(a).plus(Mbf.of(b)).toFloat();
            if (ieee != mbf) {
                differ++;
                assertEquals(Math.ulp(ieee), Math.abs(ieee - mbf), 0, a + " + " + b);
            }
        }
        // the guard byte keeps garbage below its sticky bit: a subtraction of a far smaller number
        // now and then rounds the other way (MATH1.ASM $FADDS, $ROUNS)
        assertEquals(true, differ > 0 && differ < 1000, differ + " of 20000 sums differ from IEEE");
        assertEquals("82649386", hex(bits("70f50207").plus(bits("826493c4"))));
    }

    @Test
    void integralPowersAreRepeatedMultiplication() {
        Mbf x = BasicNumbers.val("-.9728306");
        assertAll(
                () -> assertEquals(x.times(x), x.pow(2)),
                () -> assertEquals(x.times(x), x.pow(Mbf.of(2))),
                () -> assertEquals(x.times(x).times(x.times(x)), x.pow(4)));
    }

    @Test
    void theThesisSquareRootsAreExactWhereTheInterpretersPowerIsNot() {
        Mbf half = BasicNumbers.val(".5");
        Mbf n = BasicNumbers.val("10000");
        assertAll(
                () -> assertEquals(" 100", BasicNumbers.str(n.pow(half))),
                () -> assertEquals(
                        " 90", BasicNumbers.str(BasicNumbers.val("8100").pow(half))),
                () -> assertEquals((float) Math.sqrt(2), Mbf.of(2).pow(half).toFloat()),
                // GW-BASIC's $FPWR: EXP(.5 * LOG(10000)) with its polynomial LOG and EXP
                () -> assertEquals(" 99.99999", BasicNumbers.str(MbfFunctions.exp(half.times(MbfFunctions.log(n))))),
                () -> assertEquals(Mbf.ZERO, MbfFunctions.log(Mbf.ONE)),
                () -> assertEquals(Math.log(7), MbfFunctions.log(Mbf.of(7)).toDouble(), 1e-6),
                () -> assertEquals(
                        Math.exp(-3.5), MbfFunctions.exp(Mbf.of(-3.5f)).toDouble(), 1e-7));
    }

    @Test
    void intIsTheFloor() {
        assertAll(
                () -> assertEquals(Mbf.of(-3), Mbf.of(-2.5f).floor()),
                () -> assertEquals(Mbf.of(63011), Mbf.of(63011.5f).floor()),
                () -> assertEquals(Mbf.of(-1), BasicNumbers.val("-.499").floor()));
    }
}
