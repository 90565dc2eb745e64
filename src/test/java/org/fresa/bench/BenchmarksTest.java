package org.fresa.bench;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.fresa.job.ProgressMonitor;
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
    void theInputsComeFromTheJarNotFromTheProjectFolder() throws Exception {
        // the same files as the checkout's, so that figures from an installed app compare with them
        assertArrayEquals(
                java.nio.file.Files.readAllBytes(java.nio.file.Path.of("samples/stepnc/example2.stp")),
                Benchmarks.input(Benchmarks.EXAMPLE2));
        assertArrayEquals(
                java.nio.file.Files.readAllBytes(java.nio.file.Path.of("samples/pocket/cavity02.dad")),
                Benchmarks.input(Benchmarks.CAVITY02));
        assertEquals(1_809_590, Benchmarks.input(Benchmarks.DXF).length);
        assertTrue(
                new String(Benchmarks.input("ezdxf/LICENSE.txt"), java.nio.charset.StandardCharsets.UTF_8)
                        .startsWith("Copyright (c) 2011-2018, Manfred Moitzi"),
                "the drawing's licence beside it");
    }

    @Test
    void everyFigureInThisJvmComesOutOfTheJarsInputs() {
        // a short pass (a few seconds of CPU): each in-JVM figure is a number, none missing with a
        // note, whatever the working folder holds; the whole-process figure needs the jar
        java.util.Map<String, Object> figures = Benchmarks.run(null, ProgressMonitor.NONE, Benchmarks.Effort.QUICK);
        for (String figure : Benchmarks.GOALS.keySet()) {
            if (!figure.equals("example2_irb140_process_s")) {
                assertTrue(figures.get(figure) instanceof Double d && d > 0, figure + ": " + figures.get(figure));
            }
        }
        @SuppressWarnings("unchecked")
        java.util.Map<String, Object> notes = (java.util.Map<String, Object>) figures.get("notes");
        assertEquals(java.util.Map.of("example2_irb140_process_s", "not run from the jar"), notes);
    }

    @Test
    void theMedianOfAnEvenCountIsTheMeanOfTheMiddleTwo() {
        assertEquals(2.5, Benchmarks.median(new double[] {4, 1, 3, 2}));
        assertEquals(3, Benchmarks.median(new double[] {5, 3, 1}));
    }
}
