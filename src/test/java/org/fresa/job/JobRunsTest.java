package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.fresa.io.OutputFolder;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The run set of a job: which modules {@code fresa run} executes, kept by job files compatibly. */
class JobRunsTest {

    @TempDir
    Path dir;

    @Test
    void everySampleJobRunsItsOneTaskAndIsWrittenBackWithoutARunSet() throws Exception {
        try (Stream<Path> jobs = Files.list(Path.of("samples/jobs"))) {
            for (Path p : jobs.filter(f -> f.toString().endsWith(".xml")).toList()) {
                Job job = JobXml.read(p);
                assertEquals(List.of(job.task()), job.runs(), p.toString());
                Path copy = dir.resolve(p.getFileName());
                JobXml.write(job, copy);
                assertFalse(Files.readString(copy).contains("runs="), p.toString());
            }
        }
    }

    @Test
    void aRunSetIsKeptInTaskOrderAndReadBack() throws Exception {
        Job job = JobXml.read(Path.of("samples/jobs/grade-sole40.xml"))
                .withStepnc(new JobSettings.StepNcSettings(
                        Path.of("samples/stepnc/example2.stp").toAbsolutePath(), org.fresa.post.MillingPost.LINUXCNC));
        Job both = job.withRuns(List.of(JobTask.GRADE, JobTask.STEPNC));
        assertAll(
                () -> assertEquals(List.of(JobTask.STEPNC, JobTask.GRADE), both.runs()),
                () -> assertEquals(JobTask.STEPNC, both.task()));
        Path file = dir.resolve("both.xml");
        JobXml.write(both, file);
        assertTrue(Files.readString(file).contains("task=\"stepnc\""));
        assertEquals(both, JobXml.read(file));
    }

    @Test
    void aJobRunsNothingIsRefused() {
        Job job = Job.empty(JobTask.POCKET);
        assertThrows(IllegalArgumentException.class, () -> job.withRuns(List.of()));
    }

    @Test
    void eachTaskOfARunSetWritesIntoItsOwnFolderAndOnlyTheTicked() throws Exception {
        Job job = JobXml.read(Path.of("samples/jobs/grade-sole40.xml"))
                .withStepnc(new JobSettings.StepNcSettings(
                        Path.of("samples/stepnc/example2.stp").toAbsolutePath(), org.fresa.post.MillingPost.LINUXCNC))
                .withRuns(List.of(JobTask.STEPNC, JobTask.GRADE));
        TaskOutcome o = JobRunner.run(job, new OutputFolder(dir.resolve("out")), ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        try (Stream<Path> s = Files.list(dir.resolve("out"))) {
            assertEquals(
                    List.of("grade", "stepnc"),
                    s.filter(Files::isDirectory)
                            .map(p -> p.getFileName().toString())
                            .sorted()
                            .toList());
        }
        assertTrue(
                o.files().stream()
                        .allMatch(
                                f -> f.startsWith(dir.resolve("out/grade")) || f.startsWith(dir.resolve("out/stepnc"))),
                o.files().toString());
        assertTrue(
                o.files().stream().anyMatch(f -> f.startsWith(dir.resolve("out/grade"))),
                o.files().toString());
        assertTrue(
                o.files().stream().anyMatch(f -> f.startsWith(dir.resolve("out/stepnc"))),
                o.files().toString());
    }
}
