package org.fresa.kin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The benchmark's path is solved completely and exactly (its timing is not asserted). */
class IkBenchmarkTest {

    @Test
    void theBenchmarkPathIsSolvedEverywhereToTheTolerances() {
        for (IkBenchmark.Figure f : new IkBenchmark.Figure[] {IkBenchmark.irb140(1), IkBenchmark.tricept806(1)}) {
            assertEquals(3131, f.points());
            assertEquals(0, f.failures());
            assertTrue(f.maxPosErrMm() <= 1e-7 && f.maxRotErrRad() <= 1e-9, f::toString);
        }
    }
}
