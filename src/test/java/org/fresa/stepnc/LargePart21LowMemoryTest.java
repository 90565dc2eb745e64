package org.fresa.stepnc;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A 100 MB Part 21 file is read and bound within a 512 MB heap. The file is example 2
 * repeated with its instance names shifted, so every copy is a complete, valid program. Runs in
 * the {@code low-memory} surefire execution ({@code -Xmx512m}); skipped in a larger heap, where
 * it would prove nothing.
 */
class LargePart21LowMemoryTest {

    private static final long MIB = 1024 * 1024;
    private static final long TARGET_BYTES = 100 * MIB;

    @TempDir
    Path dir;

    @Test
    void aHundredMegabyteFileIsReadAndBoundIn512Megabytes() throws Exception {
        long maxHeap = Runtime.getRuntime().maxMemory();
        assumeTrue(
                maxHeap <= 520 * MIB,
                "needs -Xmx512m (the low-memory surefire execution), has " + maxHeap / MIB + " MiB");
        Path big = dir.resolve("big.stp");
        int copies = RepeatedPart21.write(Path.of("samples/stepnc/example2.stp"), big, TARGET_BYTES);
        assertTrue(Files.size(big) >= TARGET_BYTES, "generated " + Files.size(big) + " bytes");

        StepNcProgram p = StepNcReader.read(big);

        StepNcProgram one = StepNcReader.read(Path.of("samples/stepnc/example2.stp"));
        int perCopy = one.workingsteps().size() + one.skipped().size();
        assertAll(
                () -> assertEquals((long) copies * one.instanceCount(), p.instanceCount()),
                () -> assertEquals(one.workingsteps(), p.workingsteps()),
                () -> assertEquals(
                        (long) copies * perCopy,
                        p.workingsteps().size() + p.skipped().size()),
                () -> assertEquals(one.projectId(), p.projectId()));
    }
}
