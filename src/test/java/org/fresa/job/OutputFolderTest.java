package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class OutputFolderTest {

    @TempDir
    Path dir;

    @Test
    void aFailedWriteLeavesNeitherFileNorTemporary() throws IOException {
        OutputFolder out = new OutputFolder(dir);
        assertThrows(IOException.class, () -> out.write("program.ngc", o -> {
            o.write("G0 X1\n".getBytes());
            throw new IOException("disk full");
        }));
        try (Stream<Path> s = Files.list(dir)) {
            assertEquals(List.of(), s.toList());
        }
    }

    @Test
    void aWriteReplacesTheFileWhole() throws IOException {
        OutputFolder out = new OutputFolder(dir);
        out.writeString("a.csv", "old");
        out.writeString("a.csv", "new");
        assertEquals("new", Files.readString(dir.resolve("a.csv")));
    }

    @Test
    void namesFromInputsCannotEscapeTheFolder() {
        OutputFolder out = new OutputFolder(dir);
        assertThrows(IllegalArgumentException.class, () -> out.resolve("../evil.ngc"));
        assertThrows(IllegalArgumentException.class, () -> out.resolve("/etc/passwd"));
        assertThrows(IllegalArgumentException.class, () -> out.resolve("sub/x.csv"));
        assertFalse(OutputFolder.sanitize("../../ws 1/x").contains("/"));
    }
}
