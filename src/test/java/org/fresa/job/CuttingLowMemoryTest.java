package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.fresa.bench.SquareSheet;
import org.fresa.job.JobSettings.CuttingSettings;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A generated sheet of square parts ({@link SquareSheet}) is cut whole within a 512 MB heap:
 * read, chained, nested, offset, ordered, routed around the cut parts, posted and checked, every
 * part cut. The program is posted a cut at a time to the file and checked there, never held as
 * text. The sheet is a quarter of the 50 MB drawing (45 000 parts, 13 MB): the whole one is cut in
 * 512 MB too ({@code java -Xmx512m -jar fresa.jar cut}, docs/cutting.md), but with more than the
 * CPU seconds a test may take (74 s of CPU with the collector's). Runs in the
 * {@code low-memory} surefire execution ({@code -Xmx512m});
 * skipped in a larger heap, where it would prove nothing. The time is printed, not asserted: the
 * 60 s goal is the benchmark's ({@code cut_parts_per_s}).
 */
class CuttingLowMemoryTest {

    private static final long MIB = 1024 * 1024;

    @TempDir
    Path dir;

    @Test
    void aQuarterOfTheFiftyMegabyteSheetIsCutIn512Megabytes() throws Exception {
        long maxHeap = Runtime.getRuntime().maxMemory();
        assumeTrue(
                maxHeap <= 520 * MIB,
                "needs -Xmx512m (the low-memory surefire execution), has " + maxHeap / MIB + " MiB");
        Path dxf = dir.resolve("squares.dxf");
        int parts = SquareSheet.FIFTY_MB_SQUARES / 4 / SquareSheet.PER_ROW * SquareSheet.PER_ROW;
        SquareSheet.write(dxf, parts);
        assertTrue(Files.size(dxf) >= 12_500_000L, Files.size(dxf) + " bytes");
        Path out = dir.resolve("squares.ngc");
        CuttingSettings s = new CuttingSettings(
                dxf,
                2,
                org.fresa.cutting.CutProcess.PLASMA,
                3,
                1,
                org.fresa.cutting.LeadShape.ARC,
                org.fresa.cutting.CuttingOptions.DEFAULT_GAP_MM,
                org.fresa.dxf.DrawingUnits.AUTO,
                false,
                org.fresa.post.CuttingPost.LINUXCNC);
        long t0 = System.nanoTime();
        TaskOutcome o = CuttingService.run(s, out, false, ProgressMonitor.NONE);
        double seconds = (System.nanoTime() - t0) / 1e9;
        System.out.printf(
                Locale.ROOT,
                "CuttingLowMemoryTest: %d parts of a %.1f MB drawing cut in %.1f s (%.0f parts/s)%n",
                parts,
                Files.size(dxf) / 1e6,
                seconds,
                parts / seconds);
        assertAll(
                o.problems().toString(),
                () -> assertEquals(0, o.exitStatus()),
                () -> assertEquals(parts, ((Number) o.summary().get("pierces")).intValue()),
                () -> assertEquals(0, ((Number) o.summary().get("not_cut")).intValue()),
                () -> assertTrue(Files.size(out) > 0));
    }
}
