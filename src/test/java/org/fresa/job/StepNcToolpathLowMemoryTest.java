package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import org.fresa.io.OutputFolder;
import org.fresa.post.MillingPost;
import org.fresa.stepnc.RepeatedPart21;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A generated STEP-NC file whose every copy of example 2 is executed is planned end to end within
 * a 512 MB heap, as {@code fresa toolpath} does: read, bound, planned, {@code toolpath.csv} and the
 * program written and the program checked, every copy's workingsteps in the program. The file is
 * 48 MB (28 860 workingsteps, a 410 MB {@code toolpath.csv}), more than a planner that holds the
 * whole toolpath can plan in 512 MB; the 121 MB one of the issue (71 214 workingsteps, a 1 GB
 * {@code toolpath.csv}) is planned in 512 MB too ({@code java -Xmx512m -jar fresa.jar toolpath}),
 * with more CPU seconds than a test may take. Runs in the
 * {@code low-memory} surefire execution ({@code -Xmx512m}); skipped in a larger heap, where it
 * would prove nothing.
 */
class StepNcToolpathLowMemoryTest {

    private static final long MIB = 1024 * 1024;
    private static final long TARGET_BYTES = 48_000_000L;
    private static final Path EXAMPLE2 = Path.of("samples/stepnc/example2.stp");

    @TempDir
    Path dir;

    @Test
    void everyCopyOfAFortyEightMegabyteFileIsPlannedIn512Megabytes() throws Exception {
        long maxHeap = Runtime.getRuntime().maxMemory();
        assumeTrue(
                maxHeap <= 520 * MIB,
                "needs -Xmx512m (the low-memory surefire execution), has " + maxHeap / MIB + " MiB");
        TaskOutcome one = ToolpathService.run(
                EXAMPLE2, MillingPost.LINUXCNC, new OutputFolder(dir.resolve("one")), ProgressMonitor.NONE);
        Path big = dir.resolve("copies.stp");
        int copies = RepeatedPart21.writeExecuted(EXAMPLE2, big, TARGET_BYTES);
        Path out = dir.resolve("out");

        long t0 = System.nanoTime();
        TaskOutcome o = ToolpathService.run(big, MillingPost.LINUXCNC, new OutputFolder(out), ProgressMonitor.NONE);
        double seconds = (System.nanoTime() - t0) / 1e9;
        System.out.printf(
                Locale.ROOT,
                "StepNcToolpathLowMemoryTest: %d workingsteps of a %.1f MB file planned in %.1f s%n",
                ((Number) o.summary().get("workingsteps")).intValue(),
                Files.size(big) / 1e6,
                seconds);

        Map<String, Object> s = o.summary();
        Map<String, Object> s1 = one.summary();
        long rows;
        String lastRow = "";
        try (BufferedReader r = Files.newBufferedReader(out.resolve("toolpath.csv"), StandardCharsets.UTF_8)) {
            rows = -1;
            for (String line = r.readLine(); line != null; line = r.readLine()) {
                rows++;
                lastRow = line;
            }
        }
        String programEnd = tail(out.resolve("program.ngc"));
        long csvRows = rows;
        String last = lastRow;
        assertAll(
                o.problems().toString(),
                // one copy's status: its side setups need another setup, the rest is planned
                () -> assertEquals(one.exitStatus(), o.exitStatus()),
                () -> assertEquals(copies * count(s1, "workingsteps"), count(s, "workingsteps")),
                () -> assertEquals(copies * count(s1, "planned"), count(s, "planned")),
                () -> assertEquals(copies * count(s1, "moves"), count(s, "moves")),
                () -> assertEquals(copies * count(s1, "points"), count(s, "points")),
                () -> assertEquals(count(s, "points"), csvRows),
                () -> assertTrue(last.startsWith((csvRows - 1) + ","), last),
                () -> assertFalse(s.containsKey("program_refused"), String.valueOf(s.get("program_refused"))),
                () -> assertTrue(programEnd.endsWith("M30\n%\n"), programEnd),
                () -> assertEquals(
                        copies * ((java.util.List<?>) s1.get("not_planned")).size(),
                        ((java.util.List<?>) s.get("not_planned")).size()),
                () -> assertTrue(Files.exists(out.resolve("summary.json"))));
    }

    private static long count(Map<String, Object> summary, String key) {
        return ((Number) summary.get(key)).longValue();
    }

    /** The last bytes of a file, as text. */
    private static String tail(Path file) throws java.io.IOException {
        try (java.io.RandomAccessFile f = new java.io.RandomAccessFile(file.toFile(), "r")) {
            long n = Math.min(64, f.length());
            byte[] b = new byte[(int) n];
            f.seek(f.length() - n);
            f.readFully(b);
            return new String(b, StandardCharsets.US_ASCII);
        }
    }
}
