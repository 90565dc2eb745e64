package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.fresa.check.ProgramCheck;
import org.fresa.io.AtomicFiles;
import org.fresa.io.OutputFolder;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.MillingDirection;
import org.fresa.pocket.PocketStrategy;
import org.fresa.setting.SettingRanges;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The program check as the writers run it: programs that pass are written, the others are not. */
class ProgramChecksTest {

    @TempDir
    Path dir;

    /** The thesis's eight pockets on both 7M posts: the check passes and the programs are written. */
    @Test
    void theThesisPocketsPassOnBothSevenMPosts() throws Exception {
        for (String line : Files.readAllLines(Path.of("samples/pocket/jobs.csv"))) {
            if (line.startsWith("contour")) {
                continue;
            }
            String[] f = line.split(",");
            for (String post : List.of("7m-compat", "7m")) {
                PocketSettings s = new PocketSettings(
                        Path.of("samples/pocket/" + f[0]),
                        Double.parseDouble(f[1]),
                        Double.parseDouble(f[2]),
                        Double.parseDouble(f[3]),
                        Double.parseDouble(f[4]),
                        Double.parseDouble(f[5]),
                        Double.parseDouble(f[6]),
                        Double.parseDouble(f[7]),
                        Double.parseDouble(f[8]),
                        Double.parseDouble(f[9]),
                        SettingRanges.Pocket.POST.require(post),
                        MillingDirection.CLIMB,
                        EntryRule.Kind.AUTO,
                        EntryRule.DEFAULT_ANGLE_DEG,
                        false,
                        Optional.empty(),
                        PocketStrategy.DEFAULT);
                Path out = dir.resolve(f[0] + "-" + post + ".nc");
                TaskOutcome o = PocketService.run(s, out, ProgressMonitor.NONE);
                assertEquals(0, o.exitStatus(), f[0] + " " + post + ": " + o.problems());
                assertTrue(Files.exists(out));
                assertTrue(ProgramCheck.of(Files.readString(out), ProgramChecks.dialect(post), ProgramChecks.pocket(s))
                        .ok());
            }
        }
    }

    /**
     * A STEP-NC file whose workingsteps have a feed but spindle $: no cutting program (the check
     * refuses the feed moves with the spindle stopped), exit 1, the other files written.
     */
    @Test
    void workingstepsWithoutASpindleSpeedGiveNoCuttingProgram() throws Exception {
        String text = Files.readString(Path.of("samples/stepnc/iso14649-11-example1.stp"))
                .replaceAll("(#\\d+= MILLING_TECHNOLOGY\\([^,]*,[^,]*,[^,]*,)-?[0-9.]+,", "$1\\$,");
        assertTrue(text.contains("MILLING_TECHNOLOGY(0.040,.TCP.,$,$,"), "the spindle speeds were replaced");
        Path file = dir.resolve("no-spindle.stp");
        Files.writeString(file, text);
        Path out = dir.resolve("out");
        TaskOutcome o = ToolpathService.run(
                file, org.fresa.post.MillingPost.LINUXCNC, new OutputFolder(out), ProgressMonitor.NONE);
        assertEquals(1, o.exitStatus(), o.problems().toString());
        assertTrue(Files.exists(out.resolve("summary.json")));
        Path ngc = out.resolve("program.ngc");
        if (Files.exists(ngc)) {
            // a planner that refuses such workingsteps may leave a program of the others: it must pass
            assertTrue(ProgramCheck.of(
                            Files.readString(ngc),
                            org.fresa.check.NcDialect.LINUXCNC,
                            org.fresa.check.Limits.milling().withOtherTools(org.fresa.check.ToolLimits.drill()))
                    .ok());
        } else {
            // refused by the program check, or earlier by the planner: either way the spindle is named
            assertTrue(
                    o.problems().stream().anyMatch(p -> p.contains("spindle")),
                    o.problems().toString());
        }
        assertFalse(Files.list(out).anyMatch(p -> p.getFileName().toString().startsWith(AtomicFiles.TEMP_PREFIX)));
    }

    /**
     * Every post's golden programs (the sample mixed and drilling toolpaths of the post tests,
     * src/test/resources/org/fresa/post) pass the check's words and spindle rules, their tools taken
     * as drills (the samples state no stock): no post writes a word out of range or a cut with the
     * spindle stopped.
     */
    @Test
    void everyPostsGoldenProgramsPassTheCheck() throws Exception {
        int checked = 0;
        try (var files = Files.list(Path.of("src/test/resources/org/fresa/post"))) {
            for (Path f :
                    files.filter(p -> p.toString().endsWith(".nc")).sorted().toList()) {
                String post = f.getFileName().toString().replaceAll("^[a-z]+\\.|\\.nc$", "");
                var result = ProgramCheck.of(
                        Files.readString(f),
                        ProgramChecks.dialect(post),
                        org.fresa.check.Limits.milling().withOtherTools(org.fresa.check.ToolLimits.drill()));
                assertTrue(result.ok(), f + ": " + result.failure());
                checked++;
            }
        }
        assertEquals(8, checked);
    }
}
