package org.fresa.grading;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Size numbers are above 0 and at most a 1 m last, in every system. */
class SizeBoundsTest {

    static final double TOL = 1e-9;

    @ParameterizedTest
    @CsvSource(textBlock = """
            br,          148
            paris,       150
            uk,          93.1102362204724
            us,          94.6102362204724
            mondopoint,  1000
            """)
    void theLargestSizeIsALastOfOneMetre(String system, double max) {
        SizeSystem s = SizeSystem.ofId(system);
        assertAll(
                () -> assertEquals(max, s.maxSize(), 1e-6),
                () -> assertEquals(SizeSystem.MAX_LAST_LENGTH_MM, s.lastLengthMm(s.maxSize()), TOL));
    }

    @Test
    void sizeZeroAndNegativeSizesAreRefused() {
        IllegalArgumentException zero =
                assertThrows(IllegalArgumentException.class, () -> SizeRange.parse("0-1", SizeSystem.BR, false));
        IllegalArgumentException base = assertThrows(
                IllegalArgumentException.class, () -> GradingPlan.of(SizeSystem.BR, -40, List.of(39.0, 40.0)));
        assertAll(
                () -> assertTrue(zero.getMessage().contains("size 0 is not a Brazilian size"), zero.getMessage()),
                () -> assertTrue(base.getMessage().contains("base size -40"), base.getMessage()));
    }

    @Test
    void aRangeReachingAnAbsurdSizeIsRefusedNotWrappedToNoSizes() {
        IllegalArgumentException e = assertThrows(
                IllegalArgumentException.class, () -> SizeRange.parse("1-1e308", SizeSystem.MONDOPOINT, false));
        assertTrue(e.getMessage().contains("size 1.0E308 is not a Mondopoint size"), e.getMessage());
    }

    @Test
    void theLargestSizeOfASystemIsStillGraded() {
        assertEquals(List.of(147.0, 148.0), SizeRange.parse("147-148", SizeSystem.BR, false));
    }
}
