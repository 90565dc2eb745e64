package org.fresa.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.fresa.geom.Vec3;
import org.junit.jupiter.api.Test;

class MoveTest {

    static final Vec3 P = new Vec3(1, 2, -3);

    @Test
    void aDwellTakesZeroOrMoreFiniteSeconds() {
        assertEquals(0, new Move.Dwell(P, 0).seconds());
        assertEquals(1.5, new Move.Dwell(P, 1.5).seconds());
        for (double bad : new double[] {-0.001, Double.NaN, Double.POSITIVE_INFINITY}) {
            assertThrows(IllegalArgumentException.class, () -> new Move.Dwell(P, bad), "seconds " + bad);
        }
        assertThrows(NullPointerException.class, () -> new Move.Dwell(null, 1));
    }

    @Test
    void aSpindleStartNeedsAPositiveFiniteSpeed() {
        assertEquals(800, new Move.SpindleStart(P, 800, true).rpm());
        for (double bad : new double[] {0, -1, Double.NaN, Double.POSITIVE_INFINITY}) {
            assertThrows(IllegalArgumentException.class, () -> new Move.SpindleStart(P, bad, true), "rpm " + bad);
        }
        assertThrows(NullPointerException.class, () -> new Move.SpindleStop(null));
    }

    @Test
    void onlyRapidsFeedsAndArcsTravel() {
        assertTrue(new Move.Rapid(P).travels());
        assertTrue(new Move.Linear(P, 100).travels());
        assertTrue(new Move.Circular(P, Vec3.ZERO, Vec3.UNIT_Z, true, 0, 100).travels());
        assertFalse(new Move.Dwell(P, 1).travels());
        assertFalse(new Move.SpindleStop(P).travels());
        assertFalse(new Move.SpindleStart(P, 100, false).travels());
    }
}
