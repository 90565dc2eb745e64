package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class BenchmarksTest {

    @Test
    void aSteadyWorkloadEndsItsWarmUpSoonAfterTheMinimum() throws Exception {
        // a loop whose speed does not change: the plateau rule stops at 5 s plus a few windows
        long ns = Benchmarks.warmUp(() -> {
            double x = 0;
            for (int i = 0; i < 20_000; i++) {
                x += Math.sqrt(i);
            }
            return x > 0 ? 1000 : 0;
        });
        assertTrue(ns >= 5_000_000_000L && ns < 12_000_000_000L, ns + " ns");
    }

    @Test
    void theMedianOfAnEvenCountIsTheMeanOfTheMiddleTwo() {
        assertEquals(2.5, Benchmarks.median(new double[] {4, 1, 3, 2}));
        assertEquals(3, Benchmarks.median(new double[] {5, 3, 1}));
    }
}
