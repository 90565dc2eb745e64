package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The planner refuses technology that would make an endless program. */
class PocketTechnologyBoundsTest {

    private static PocketTechnology depth(double zTop, double maxDepth) {
        return new PocketTechnology(6, 0.6, 0.15, zTop, -5, maxDepth, 3000, 300, 100);
    }

    @Test
    void moreThanAMillionDepthPassesAreRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> depth(1e308, 2));
        IllegalArgumentException f = assertThrows(IllegalArgumentException.class, () -> depth(0, 1e-9));
        assertAll(
                () -> assertTrue(e.getMessage().contains("must be finite")
                        || e.getMessage().contains("more than")),
                () -> assertTrue(f.getMessage().contains("more than 1000000 depth passes"), f.getMessage()),
                () -> assertDoesNotThrow(() -> depth(995, 0.001)));
    }

    @ParameterizedTest
    @ValueSource(doubles = {0, -1, Double.NaN, Double.POSITIVE_INFINITY})
    void aSpindleThatDoesNotTurnIsRefused(double rpm) {
        assertThrows(IllegalArgumentException.class, () -> new PocketTechnology(6, 0.6, 0.15, 0, -5, 2, rpm, 300, 100));
    }

    @Test
    void aProgramOfMoreThanAMillionMovesIsNotDoable() {
        PocketTechnology t = depth(995, 1);
        ToolTooLargeException e = assertThrows(ToolTooLargeException.class, () -> t.checkMoves(1001));
        assertAll(
                () -> assertTrue(e.getMessage().contains("more than 1000000 in all"), e.getMessage()),
                () -> assertDoesNotThrow(() -> t.checkMoves(1000)));
    }
}
