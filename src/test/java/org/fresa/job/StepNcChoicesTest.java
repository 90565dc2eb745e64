package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.io.OutputFolder;
import org.fresa.job.JobSettings.StepNcSettings;
import org.fresa.post.Rs274;
import org.fresa.testing.InterpreterCheck;
import org.fresa.toolpath.PlanningChoices;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The STEP-NC task with refused workingsteps and the planner's choices: a refused
 * workingstep makes the run exit 1 with its name and reason, the others' toolpath.csv,
 * program.ngc and summary.json are written; the choices come from the job file as from the
 * options.
 */
class StepNcChoicesTest {

    static final Path TECHNOLOGY = Path.of("src/test/resources/org/fresa/toolpath/technology.stp");
    static final Path HOLES = Path.of("src/test/resources/org/fresa/toolpath/holes.stp");

    @TempDir
    Path dir;

    @Test
    void refusedWorkingstepsExitOneAndTheOthersAreWritten() throws Exception {
        TaskOutcome o = ToolpathService.run(
                TECHNOLOGY,
                org.fresa.post.MillingPost.LINUXCNC,
                PlanningChoices.DEFAULT,
                new OutputFolder(dir),
                ProgressMonitor.NONE);
        String ngc = Files.readString(dir.resolve("program.ngc"));
        String summary = Files.readString(dir.resolve("summary.json"));
        assertAll(
                () -> assertEquals(1, o.exitStatus()),
                () -> assertTrue(o.problems().stream().anyMatch(p -> p.startsWith("workingstep 'WS NO SPEED' (#11)"))),
                () -> assertTrue(o.problems().stream().anyMatch(p -> p.startsWith("workingstep 'WS NO FEED' (#13)"))),
                () -> assertTrue(o.problems().stream()
                        .anyMatch(p -> p.startsWith("workingstep 'WS SPINDLE 100 TIMES TOO SLOW' (#12)"))),
                () -> assertTrue(ngc.contains("S5730 M3") && ngc.contains("S4800 M3"), ngc),
                () -> assertFalse(ngc.contains("S6 ") || ngc.contains("S584"), ngc),
                () -> assertTrue(
                        summary.contains("\"planned\": 2") && summary.contains("\"spindle_rpm\": 4800"), summary),
                () -> assertTrue(Files.exists(dir.resolve("toolpath.csv"))));
    }

    @Test
    void theJobsStepncElementCarriesTheChoices() throws Exception {
        Path job = dir.resolve("job.xml");
        Files.writeString(
                job,
                "<?xml version=\"1.0\"?>\n<job xmlns=\"urn:fresa:job:1\" version=\"1\" task=\"toolpath\">"
                        + "<stepnc file=\"" + TECHNOLOGY.toAbsolutePath()
                        + "\" trustCuttingSpeed=\"true\" breakthroughMm=\"2.5\"/>"
                        + "</job>\n");
        Job j = JobXml.read(job);
        StepNcSettings s = j.stepnc().orElseThrow();
        TaskOutcome o = ToolpathService.run(j, new OutputFolder(dir.resolve("out")), ProgressMonitor.NONE);
        assertAll(
                () -> assertEquals(new PlanningChoices(true, 2.5), s.choices()),
                () -> assertEquals(1, o.exitStatus()),
                () -> assertTrue(
                        Files.readString(dir.resolve("out/program.ngc")).contains("S584 M3")),
                () -> assertTrue(
                        Files.readString(dir.resolve("out/summary.json")).contains("\"planned\": 3")));
    }

    @Test
    void theChoicesAreSavedOnlyWhenNotTheDefaults() throws Exception {
        Path file = dir.resolve("job.xml");
        JobXml.write(
                Job.empty(JobTask.TOOLPATH)
                        .withStepnc(new StepNcSettings(HOLES.toAbsolutePath(), org.fresa.post.MillingPost.LINUXCNC)),
                file);
        String plain = Files.readString(file);
        Job chosen = Job.empty(JobTask.TOOLPATH)
                .withStepnc(new StepNcSettings(HOLES.toAbsolutePath(), org.fresa.post.MillingPost.LINUXCNC, true, 0.5));
        JobXml.write(chosen, file);
        assertAll(
                () -> assertFalse(plain.contains("breakthroughMm") || plain.contains("trustCuttingSpeed"), plain),
                () -> assertEquals(chosen, JobXml.read(file)));
    }

    @Test
    void aHandMadeFilesThroughHolesDrillOneMillimetreThroughByDefault() throws Exception {
        TaskOutcome o = ToolpathService.run(
                HOLES, org.fresa.post.MillingPost.LINUXCNC, new OutputFolder(dir), ProgressMonitor.NONE);
        assertAll(
                () -> assertEquals(0, o.exitStatus(), o.problems().toString()),
                () -> assertTrue(Files.readString(dir.resolve("program.ngc")).contains("Z-2.803")));
    }

    @Test
    @InterpreterCheck
    void theHandMadeFilesProgramsAreAcceptedByLinuxCncDownToTheirBreakthrough() throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        ToolpathService.run(
                HOLES,
                org.fresa.post.MillingPost.LINUXCNC,
                new OutputFolder(dir.resolve("holes")),
                ProgressMonitor.NONE);
        ToolpathService.run(
                TECHNOLOGY,
                org.fresa.post.MillingPost.LINUXCNC,
                new PlanningChoices(true, 1),
                new OutputFolder(dir.resolve("tech")),
                ProgressMonitor.NONE);
        Rs274.Result holes = Rs274.run(dir.resolve("holes/program.ngc"), 6);
        Rs274.Result tech = Rs274.run(dir.resolve("tech/program.ngc"), 6);
        double lowest = holes.motions().stream()
                .filter(c -> c.end() != null)
                .mapToDouble(c -> c.end().z())
                .min()
                .orElseThrow();
        assertAll(
                () -> assertEquals(0, holes.exitStatus(), holes.stderr()),
                () -> assertEquals(0, tech.exitStatus(), tech.stderr()),
                // hole A: the block's bottom (z 0), the 118 deg point and 1 mm, posted to 1 um
                () -> assertEquals(-(3 * Math.tan(Math.toRadians(31)) + 1), lowest, 5e-4));
    }
}
