package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Optional;
import org.fresa.geom.Vec2;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class WarningListTest {

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            open chain of 5 elements from (23.000, 109.000) to (83.000, 109.000), gap 60.00 mm: not cut | 23 | 109
            part 15 hole 1 (2.000 x 2.000 mm at 92.000, -9.500) is too small for a 2.000 mm kerf: not cut | 92 | -9.5
            two drawn contours cross or touch at (-1.250, 0.000): cut as drawn | -1.25 | 0
            """)
    void aWarningNamingAPointHasThatPlace(String text, double x, double y) {
        assertEquals(Optional.of(Vec2.of(x, y)), WarningList.placeIn(text));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            3 duplicate elements removed
            part 4 hole 1: no room for a lead-in; pierced on the contour
            LINE 1F at line 2345: not parallel to the XY plane (extrusion 0, 0, -1)
            """)
    void aWarningWithoutAPointHasNone(String text) {
        assertEquals(Optional.empty(), WarningList.placeIn(text));
    }
}
