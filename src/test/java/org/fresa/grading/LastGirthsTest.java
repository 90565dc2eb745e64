package org.fresa.grading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Table 3.1 of the thesis: last girth by French size and width fitting. */
class LastGirthsTest {

    @ParameterizedTest
    @CsvSource({
        "42, A, 212.0",
        "42, H, 247.0",
        "40, D, 218.5",
        "38, C, 205.0",
        "36, G, 216.5",
        "33, B, 180.0",
        "31, E, 187.5",
        "29, A, 160.0",
        "29, H, 195.0",
        "30, F, 188.5",
        "34, D, 193.5",
        "41, B, 213.0"
    })
    void theGirthIsTheTablesEntry(double french, String fitting, double girth) {
        assertEquals(girth, LastGirths.girthMm(french, fitting).getAsDouble(), 0);
    }

    @Test
    void eachFittingAddsFiveMillimetresAndSizesGrowByFourOnAverage() {
        for (int s = 29; s <= 42; s++) {
            for (int f = 1; f < 8; f++) {
                assertEquals(
                        5.0,
                        LastGirths.girthMm(s, LastGirths.FITTINGS.get(f)).getAsDouble()
                                - LastGirths.girthMm(s, LastGirths.FITTINGS.get(f - 1))
                                        .getAsDouble(),
                        0);
            }
        }
        assertEquals(
                52.0,
                LastGirths.girthMm(42, "A").getAsDouble()
                        - LastGirths.girthMm(29, "A").getAsDouble(),
                0);
        assertTrue(LastGirths.girthMm(43, "A").isEmpty());
        assertTrue(LastGirths.girthMm(40.5, "A").isEmpty());
    }

    @Test
    void aBrazilianSizeIsTheFrenchLessTwoAndAGirthNamesItsFitting() {
        assertEquals(40, LastGirths.frenchSize(SizeSystem.BR, 38).getAsDouble(), 0);
        assertEquals(40, LastGirths.frenchSize(SizeSystem.PARIS, 40).getAsDouble(), 0);
        assertTrue(LastGirths.frenchSize(SizeSystem.UK, 7).isEmpty());
        assertEquals(Optional.of("D"), LastGirths.fittingOf(40, 219.0));
        assertEquals(Optional.of("A"), LastGirths.fittingOf(40, 201.0));
        assertEquals(Optional.empty(), LastGirths.fittingOf(40, 250.0));
    }
}
