package org.fresa.model;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.fresa.geom.Vec3;
import org.junit.jupiter.api.Test;

class CycleTimeTest {

    static final Vec3 TOP = new Vec3(0, 0, 10);
    static final Vec3 BOTTOM = new Vec3(0, 0, -20);

    /** 30 mm at 600 mm/min (3 s), 2.5 s dwell, spindle events (no time), 30 mm rapid at 1800 (1 s). */
    @Test
    void dwellsAddTheirTimeAndSpindleEventsNone() {
        List<Move> moves = List.of(
                new Move.Linear(BOTTOM, 600),
                new Move.Dwell(BOTTOM, 2.5),
                new Move.SpindleStop(BOTTOM),
                new Move.Rapid(TOP),
                new Move.SpindleStart(TOP, 1000, true));
        CycleTime t = CycleTime.of(TOP, moves, 1800);
        assertEquals(30, t.feedLengthMm(), 1e-12);
        assertEquals(30, t.rapidLengthMm(), 1e-12);
        assertEquals(3, t.feedSeconds(), 1e-12);
        assertEquals(1, t.rapidSeconds(), 1e-12);
        assertEquals(2.5, t.dwellSeconds(), 1e-12);
        assertEquals(6.5, t.seconds(), 1e-12);
        assertEquals(2.5, CycleTime.seconds(BOTTOM, moves.get(1), 1800), 0);
        assertEquals(0, CycleTime.seconds(BOTTOM, moves.get(2), 1800), 0);
        assertEquals(0, CycleTime.lengthMm(BOTTOM, moves.get(1)), 0);
        assertEquals(9.5, t.plus(new CycleTime(0, 0, 0, 1, 2)).seconds(), 1e-12);
        assertEquals(5, t.plus(t).dwellSeconds(), 1e-12);
    }
}
