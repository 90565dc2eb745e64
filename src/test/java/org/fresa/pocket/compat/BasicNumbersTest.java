package org.fresa.pocket.compat;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class BasicNumbersTest {

    @Test
    void strSpellsNumbersAsTheThesisFilesDo() {
        assertAll(
                () -> assertEquals(" .2315189", BasicNumbers.str(BasicNumbers.val(".2315189"))),
                () -> assertEquals(" 5.255885E-02", BasicNumbers.str(BasicNumbers.val("5.255885E-02"))),
                () -> assertEquals("-25.48066", BasicNumbers.str(BasicNumbers.val("-25.48066"))),
                () -> assertEquals(" 46", BasicNumbers.str(Mbf.of(46))),
                () -> assertEquals("-.565", BasicNumbers.str(BasicNumbers.val("-.565"))),
                () -> assertEquals(" 0", BasicNumbers.str(Mbf.ZERO)),
                () -> assertEquals(" .01", BasicNumbers.str(BasicNumbers.val(".01"))),
                () -> assertEquals(" 1E+07", BasicNumbers.str(Mbf.of(10_000_000))));
    }

    /** Recorded with PC-BASIC 2.0.8 ({@code STR$} of the number with these four bytes). */
    @ParameterizedTest
    @CsvSource(textBlock = """
            8018ca4d, ' .5968369'
            862c136d, ' 43.01897'
            783f1ed9, ' 2.916267E-03'
            7d944417, '-.0723955'
            8760345c, ' 112.1023'
            89dafe69, '-437.9876'
            7f7c5c7f, ' .4928932'
            843c2593, ' 11.75917'
            7a14d7fa, ' 9.084696E-03'
            8ce9feb3, '-3743.919'
            83124924, ' 4.571429'
            """)
    void strIsTheInterpretersSevenDigits(String bits, String text) {
        assertEquals(text, BasicNumbers.str(new Mbf((int) Long.parseLong(bits, 16))));
    }

    @Test
    void strIsNotPlainRoundingToSevenDigits() {
        Mbf x = new Mbf((int) Long.parseLong("83124924", 16));
        String plain = new BigDecimal(x.toDouble())
                .round(new MathContext(7, RoundingMode.HALF_UP))
                .toPlainString();
        assertAll(
                () -> assertEquals("4.571428", plain),
                () -> assertEquals(" 4.571429", BasicNumbers.str(x)),
                // one unit in the last place above 40 is 40.0000038: it prints as 40.00001
                () -> assertEquals(
                        " 40.00001", BasicNumbers.str(new Mbf(Mbf.of(40).bits() + 1))));
    }

    @Test
    void valReadsTheNearestSingle() {
        Random r = new Random(21);
        for (int i = 0; i < 5_000; i++) {
            BigDecimal d = BigDecimal.valueOf(r.nextInt(9_999_999) + 1).movePointLeft(r.nextInt(12));
            String text = d.toPlainString();
            float nearest = new BigDecimal(text).floatValue();
            assertEquals(nearest, BasicNumbers.val(text).toFloat(), text);
        }
        assertEquals(0.009173051f, BasicNumbers.val("9.173051E-03").toFloat());
    }

    @Test
    void everyMoveWritesTheOffsetBackAsSevenDigitText() {
        // cavity 07, line 3 (D = 96.16654, K = -1) at the finishing allowance .16 × 20
        Mbf a = BasicNumbers.val(".16").times(BasicNumbers.val("20"));
        Mbf moved = BasicNumbers.val("96.16654").minus(a);
        assertAll(
                () -> assertEquals(3.1999998f, a.toFloat()),
                () -> assertEquals(92.966545f, moved.toFloat()),
                () -> assertEquals(" 92.96655", BasicNumbers.str(moved)),
                () -> assertEquals(BasicNumbers.val("92.96655"), BasicNumbers.roundTrip(moved)));
    }
}
