package org.fresa.io;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.job.Job;
import org.fresa.job.JobRunner;
import org.fresa.job.JobXml;
import org.fresa.job.ProgressMonitor;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** One run per output folder, within one JVM; {@code FolderLockProcessTest} has two processes. */
@SuppressWarnings("try") // each lock is held for its block, never read
class FolderLockTest {

    @TempDir
    Path dir;

    @Test
    void aSecondRunIntoTheSameFolderIsRefusedWhileTheFirstHoldsIt() throws Exception {
        OutputFolder folder = new OutputFolder(dir.resolve("out"));
        try (FolderLock first = FolderLock.acquire(folder)) {
            FolderLock.FolderBusyException e = assertThrows(
                    FolderLock.FolderBusyException.class,
                    () -> FolderLock.acquire(new OutputFolder(dir.resolve("out/../out"))));
            assertAll(
                    () -> assertTrue(e.getMessage().contains("another Fresa run"), e.getMessage()),
                    () -> assertTrue(Files.exists(folder.dir().resolve(FolderLock.FILE_NAME))));
        }
        try (FolderLock again = FolderLock.acquire(folder)) {
            assertEquals(folder.dir(), again.dir());
        }
    }

    @Test
    void theLockFileGoesWithTheRunAndAFolderItMadeEmptyToo() throws Exception {
        OutputFolder made = new OutputFolder(dir.resolve("new"));
        Path existing = Files.createDirectory(dir.resolve("existing"));
        try (FolderLock a = FolderLock.acquire(made);
                FolderLock b = FolderLock.acquire(new OutputFolder(existing))) {
            assertTrue(Files.isDirectory(made.dir()));
        }
        assertAll(
                () -> assertFalse(Files.exists(made.dir()), "an empty folder the run made is removed"),
                () -> assertTrue(Files.isDirectory(existing), "a folder that was there stays"),
                () -> assertFalse(Files.exists(existing.resolve(FolderLock.FILE_NAME))));
    }

    @Test
    void aFolderWithTheRunsFilesStays() throws Exception {
        OutputFolder made = new OutputFolder(dir.resolve("new"));
        try (FolderLock a = FolderLock.acquire(made)) {
            made.writeString("summary.json", "{}\n");
        }
        try (var s = Files.list(made.dir())) {
            assertEquals(
                    java.util.List.of("summary.json"),
                    s.map(p -> p.getFileName().toString()).toList());
        }
    }

    @Test
    void aLockFileLeftByAKilledRunIsTakenOver() throws Exception {
        Path out = Files.createDirectory(dir.resolve("out"));
        Files.writeString(out.resolve(FolderLock.FILE_NAME), "process 1, started 2020-01-01 00:00:00 #0-1\n");
        try (FolderLock l = FolderLock.acquire(new OutputFolder(out))) {
            assertTrue(Files.readString(out.resolve(FolderLock.FILE_NAME))
                    .startsWith("process " + ProcessHandle.current().pid()));
        }
        assertFalse(Files.exists(out.resolve(FolderLock.FILE_NAME)));
    }

    @Test
    void aJobRunHoldsItsFolder() throws Exception {
        OutputFolder folder = new OutputFolder(dir.resolve("out"));
        try (FolderLock first = FolderLock.acquire(folder)) {
            Job job = JobXml.read(Path.of("samples/jobs/grade-sole40.xml"));
            assertThrows(FolderLock.FolderBusyException.class, () -> JobRunner.run(job, folder, ProgressMonitor.NONE));
        }
    }
}
