package org.fresa.pocket.compat;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Optional;
import org.junit.jupiter.api.Test;

class ThesisJunctionTest {

    private static final Mbf COMPAR = BasicNumbers.val("8.937393E-04");

    private static ThesisJunction.Carrier line(String a, String b, String d) {
        return new ThesisJunction.Carrier(false, BasicNumbers.val(a), BasicNumbers.val(b), BasicNumbers.val(d));
    }

    private static ThesisJunction.Carrier circle(String x, String y, String r) {
        return new ThesisJunction.Carrier(true, BasicNumbers.val(x), BasicNumbers.val(y), BasicNumbers.val(r));
    }

    /** The program's micrometres: INT(v·1000 + .499) in single precision. */
    private static long um(Mbf v) {
        return (long)
                v.times(Mbf.of(1000)).plus(BasicNumbers.val(".499")).floor().toDouble();
    }

    @Test
    void nearTangentLineAndArcMeetWhereTheSinglePrecisionDiscriminantPutsThem() {
        // the example part's slot end: line 1 misses tangency with arc 2 by 0.05 µm; on the
        // finishing pass (t = 2) the exact crossing is (45.2885, 34.9144), the thesis printed
        // N125 X 45278 Y 34912: the discriminant's rounding noise, which this routine reproduces
        ThesisJunction.Point p = ThesisJunction.of(
                        line(".2315189", "-.9728306", "-23.48066"), circle("46", "32", "3"), false, COMPAR)
                .orElseThrow();
        ThesisJunction.Point q = ThesisJunction.of(
                        line(".2315189", "-.9728306", "-22.76066"), circle("46", "32", "2.28"), false, COMPAR)
                .orElseThrow();
        assertAll(
                () -> assertEquals(45278, um(p.x())),
                () -> assertEquals(34912, um(p.y())),
                // the pre-finish pass, N90 X 45457 Y 34214
                () -> assertEquals(45457, um(q.x())),
                () -> assertEquals(34214, um(q.y())));
    }

    @Test
    void tangentCirclesMeetOnTheLineOfCentres() {
        // cavity 04: the zero-radius arc at (40, 30) grown to 25.44 against circle 2 shrunk to 24.56
        ThesisJunction.Point p = ThesisJunction.of(
                        circle("40", "30", "25.44"), circle("90", "30", "24.56"), false, BasicNumbers.val(".00583"))
                .orElseThrow();
        assertAll(() -> assertEquals(65440, um(p.x())), () -> assertEquals(30000, um(p.y())));
    }

    @Test
    void selectorChoosesTheSmallerOrLargerRoot() {
        // Table B.4: y = 30 and circle (90, 30) r 50: S gives x = 40, L gives x = 140
        ThesisJunction.Carrier y30 = line("0", "1", "30");
        ThesisJunction.Carrier c = circle("90", "30", "50");
        assertAll(
                () -> assertEquals(
                        40f,
                        ThesisJunction.of(y30, c, false, COMPAR)
                                .orElseThrow()
                                .x()
                                .toFloat()),
                () -> assertEquals(
                        140f,
                        ThesisJunction.of(y30, c, true, COMPAR)
                                .orElseThrow()
                                .x()
                                .toFloat()),
                () -> assertEquals(
                        30f,
                        ThesisJunction.of(y30, c, true, COMPAR)
                                .orElseThrow()
                                .y()
                                .toFloat()));
    }

    @Test
    void theProgramStopsWhereThereIsNoJunction() {
        Optional<ThesisJunction.Point> parallel =
                ThesisJunction.of(line("1", "0", "5"), line("1", "0", "9"), false, COMPAR);
        Optional<ThesisJunction.Point> miss =
                ThesisJunction.of(line("1", "0", "20"), circle("0", "0", "5"), false, COMPAR);
        assertAll(() -> assertTrue(parallel.isEmpty()), () -> assertTrue(miss.isEmpty()));
    }
}
