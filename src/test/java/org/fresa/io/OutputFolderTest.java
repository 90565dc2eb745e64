package org.fresa.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class OutputFolderTest {

    @TempDir
    Path dir;

    @Test
    void aFailedWriteLeavesNeitherFileNorTemporary() throws IOException {
        OutputFolder out = new OutputFolder(dir);
        assertThrows(
                IOException.class,
                () -> out.write("program.ngc", o -> {
                    o.write("G0 X1\n".getBytes());
                    throw new IOException("disk full");
                }));
        try (Stream<Path> s = Files.list(dir)) {
            assertEquals(List.of(), s.toList());
        }
    }

    @Test
    void parallelRenderingWritesEveryFileInTheOrderAskedAtFinish() throws Exception {
        OutputFolder out = new OutputFolder(dir);
        ExecutorService pool = Executors.newFixedThreadPool(2);
        CountDownLatch secondDone = new CountDownLatch(1);
        try {
            out.beginParallel(pool);
            // the first body waits for the second, so the second is certainly rendered first
            out.write("first.csv", o -> {
                try {
                    secondDone.await();
                } catch (InterruptedException e) {
                    throw new java.io.InterruptedIOException();
                }
                o.write("1".getBytes());
            });
            out.writeString("second.csv", "2");
            secondDone.countDown();
            assertFalse(Files.exists(dir.resolve("second.csv")));
            out.finishParallel();
        } finally {
            pool.shutdownNow();
        }
        assertEquals(List.of(dir.resolve("first.csv"), dir.resolve("second.csv")), out.written());
        assertEquals("1", Files.readString(dir.resolve("first.csv")));
        assertEquals("2", Files.readString(dir.resolve("second.csv")));
    }

    @Test
    void aFailedParallelRenderingWritesNothingFromItOn() throws Exception {
        OutputFolder out = new OutputFolder(dir);
        ExecutorService pool = Executors.newFixedThreadPool(2);
        try {
            out.beginParallel(pool);
            out.writeString("a.csv", "a");
            out.write("b.csv", o -> {
                throw new IOException("disk full");
            });
            out.writeString("c.csv", "c");
            IOException e = assertThrows(IOException.class, out::finishParallel);
            assertEquals("disk full", e.getMessage());
        } finally {
            pool.shutdownNow();
        }
        try (Stream<Path> s = Files.list(dir)) {
            assertEquals(List.of(dir.resolve("a.csv")), s.toList());
        }
        assertEquals(List.of(dir.resolve("a.csv")), out.written());
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

    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.ValueSource(
            strings = {
                "../x.ngc",
                "..",
                ".",
                "",
                "a/../../b.csv",
                "/tmp/x.csv",
                "C:\\Windows\\x.ngc",
                "C:x.ngc",
                "c:/x.ngc",
                "\\\\server\\share\\x",
                "..\\x.ngc",
                "x\u0000.ngc",
                "x.ngc\u0000../../etc",
                "NUL",
                "nul.ngc",
                "CON.csv",
                "com1.txt",
                "LPT9.dxf",
                "x.",
                ".fresa-tmp-1.part",
                "-rf",
                " x.ngc",
                "x y.ngc"
            })
    void hostileNamesAreRefused(String name) {
        OutputFolder out = new OutputFolder(dir);
        assertThrows(IllegalArgumentException.class, () -> out.resolve(name), name);
    }

    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.ValueSource(
            strings = {
                "../x.ngc",
                "..",
                ".",
                "",
                "a/../../b.csv",
                "/tmp/x.csv",
                "C:\\Windows\\x.ngc",
                "C:x.ngc",
                "\\\\server\\share\\x",
                "x\u0000.ngc",
                "NUL",
                "nul.ngc",
                "CON",
                "com1",
                "x.",
                "...",
                ".fresa-tmp-1.part",
                "layer/../../0",
                "\u00e9t\u00e9 1"
            })
    void sanitizedNamesStayInTheFolder(String name) throws IOException {
        OutputFolder out = new OutputFolder(dir);
        String safe = OutputFolder.sanitize(name);
        Path p = out.write(safe + ".txt", os -> os.write(1));
        org.junit.jupiter.api.Assertions.assertAll(
                name,
                () -> assertEquals(dir.toAbsolutePath().normalize(), p.getParent()),
                () -> assertFalse(safe.startsWith(".")),
                () -> assertEquals(List.of(p), out.written()));
    }

    @Test
    void staleTemporaryFilesOfAKilledRunAreRemovedByTheNextWrite() throws IOException {
        Path old = Files.createFile(dir.resolve(AtomicFiles.TEMP_PREFIX + "123" + AtomicFiles.TEMP_SUFFIX));
        Path young = Files.createFile(dir.resolve(AtomicFiles.TEMP_PREFIX + "456" + AtomicFiles.TEMP_SUFFIX));
        Files.setLastModifiedTime(
                old,
                java.nio.file.attribute.FileTime.from(
                        java.time.Instant.now().minus(AtomicFiles.STALE).minusSeconds(60)));
        new OutputFolder(dir).writeString("a.txt", "a");
        org.junit.jupiter.api.Assertions.assertAll(
                () -> assertFalse(Files.exists(old), "a leftover older than " + AtomicFiles.STALE + " is removed"),
                () -> org.junit.jupiter.api.Assertions.assertTrue(
                        Files.exists(young), "a young one may be another run's and stays"));
    }
}
