package org.fresa.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AtomicFilesTest {

    @TempDir
    Path dir;

    @Test
    void aLeftoverUnderTheNextTemporaryNameIsSkippedNotOverwritten() throws Exception {
        String pid = Long.toString(ProcessHandle.current().pid());
        long next = AtomicFiles.COUNTER.get() + 1;
        // a killed run of the same process id left the next three names behind (fresh: not stale)
        for (long i = next; i < next + 3; i++) {
            Files.writeString(dir.resolve(AtomicFiles.TEMP_PREFIX + pid + "-" + i + AtomicFiles.TEMP_SUFFIX), "left");
        }
        AtomicFiles.writeString(dir.resolve("out.txt"), "new");
        assertEquals("new", Files.readString(dir.resolve("out.txt")));
        try (Stream<Path> s = Files.list(dir)) {
            // the three leftovers are untouched, our own temporary file is gone
            assertEquals(4, s.count());
        }
        for (long i = next; i < next + 3; i++) {
            assertEquals(
                    "left",
                    Files.readString(dir.resolve(AtomicFiles.TEMP_PREFIX + pid + "-" + i + AtomicFiles.TEMP_SUFFIX)));
        }
    }

    @Test
    void theResultIsAnOrdinaryReadableFile() throws Exception {
        Path out = dir.resolve("a.csv");
        AtomicFiles.writeString(out, "x");
        if (Files.getFileStore(out).supportsFileAttributeView(java.nio.file.attribute.PosixFileAttributeView.class)) {
            assertTrue(Files.getPosixFilePermissions(out)
                    .contains(java.nio.file.attribute.PosixFilePermission.OTHERS_READ));
        }
    }
}
