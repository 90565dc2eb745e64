package org.fresa.grading;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class SizeSystemTest {

    @Test
    void theThesisTable32HasBrazilianAsFrenchMinus2AndAmericanAsEnglishPlusOneAndAHalf() {
        List<SizeTable.Row> rows = SizeTable.thesisTable32();
        assertEquals(16, rows.size());
        int both = 0;
        for (SizeTable.Row r : rows) {
            if (r.french().isPresent()) {
                assertEquals(r.french().getAsDouble() - 2, r.brazilian().getAsDouble(), 0);
                assertEquals(
                        r.brazilian().getAsDouble(),
                        SizeSystem.PARIS.convert(r.french().getAsDouble(), SizeSystem.BR));
            }
            if (r.english().isPresent()) {
                assertEquals(r.english().getAsDouble() + 1.5, r.american().getAsDouble(), 0);
                assertEquals(
                        r.american().getAsDouble(),
                        SizeSystem.UK.convert(r.english().getAsDouble(), SizeSystem.US));
            }
            if (r.french().isPresent() && r.english().isPresent()) {
                both++;
                // the table pairs sizes whose last lengths differ by less than an English size, but
                // not always the nearest: French 38 (253.3 mm) sits beside English 5 1/2 (258.2 mm),
                // 4.9 mm apart, more than half an English size (4.23 mm)
                double fr = SizeSystem.PARIS.lastLengthMm(r.french().getAsDouble());
                double en = SizeSystem.UK.lastLengthMm(r.english().getAsDouble());
                assertTrue(Math.abs(fr - en) < SizeSystem.UK.lengthStepMm(), r + ": " + fr + " vs " + en);
            }
        }
        assertEquals(5, both);
    }

    @ParameterizedTest
    @CsvSource(textBlock = """
            38, 36, 5.5, 7
            39, 37, 6, 7.5
            41, 39, 7.5, 9
            43, 41, 9, 10.5
            45, 43, 10.5, 12
            """)
    void theSeedsConversionOraclesAreRowsOfTheTable(double fr, double br, double en, double us) {
        assertTrue(SizeTable.thesisTable32().stream()
                .anyMatch(r -> r.french().orElse(-1) == fr
                        && r.brazilian().orElse(-1) == br
                        && r.english().orElse(-1) == en
                        && r.american().orElse(-1) == us));
    }

    @Test
    void frenchSizes40To44HaveNoEnglishEquivalentInTheTable() {
        for (double fr : new double[] {40, 42, 44}) {
            assertTrue(SizeTable.thesisTable32().stream()
                    .filter(r -> r.french().orElse(-1) == fr)
                    .allMatch(r -> r.english().isEmpty()));
        }
    }

    @Test
    void stepsAreThoseOfTheSystems() {
        assertAll(
                () -> assertEquals(6.66, SizeSystem.BR.lengthStepMm()),
                () -> assertEquals(1.66, SizeSystem.BR.widthStepMm()),
                () -> assertEquals(6.67, SizeSystem.PARIS.lengthStepMm(), 0.005),
                () -> assertEquals(8.47, SizeSystem.UK.lengthStepMm(), 0.005),
                () -> assertEquals(8.47, SizeSystem.US.lengthStepMm(), 0.005),
                () -> assertEquals(10, SizeSystem.MONDOPOINT.lengthStepMm()),
                () -> assertEquals(280, SizeSystem.MONDOPOINT.lastLengthMm(280)),
                () -> assertEquals(SizeSystem.PARIS.lastLengthMm(42), SizeSystem.BR.lastLengthMm(40), 1e-12));
    }

    @Test
    void rangesListWholeOrHalfSizes() {
        assertAll(
                () -> assertEquals(List.of(36.0, 37.0, 38.0), SizeRange.parse("36-38", SizeSystem.BR, false)),
                () -> assertEquals(List.of(36.0, 36.5, 37.0), SizeRange.parse("36-37", SizeSystem.BR, true)),
                () -> assertEquals(
                        List.of(260.0, 265.0, 270.0), SizeRange.parse("260-270", SizeSystem.MONDOPOINT, true)),
                () -> assertEquals(List.of(7.5), SizeRange.parse("7.5", SizeSystem.UK, false)));
    }
}
