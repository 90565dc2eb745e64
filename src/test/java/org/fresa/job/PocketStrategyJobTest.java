package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import org.fresa.io.OutputFolder;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.model.CamInputException;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.MillingDirection;
import org.fresa.pocket.PocketStrategy;
import org.fresa.post.PocketPost;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The pocket strategy in the job file: written and read back alike, left out when it is the
 * default (a saved default job reads and writes as before), refused out of range, and
 * {@code fresa run} of the saved job writing the program {@code fresa pocket} writes.
 */
class PocketStrategyJobTest {

    @TempDir
    Path dir;

    private static PocketSettings settings(Path contour, PocketStrategy st) {
        return new PocketSettings(
                        contour,
                        6,
                        0.6,
                        0.1,
                        0,
                        -4,
                        2,
                        3000,
                        300,
                        100,
                        PocketPost.LINUXCNC,
                        MillingDirection.CLIMB,
                        EntryRule.Kind.AUTO,
                        EntryRule.DEFAULT_ANGLE_DEG,
                        false,
                        Optional.empty(),
                        PocketStrategy.DEFAULT)
                .withStrategy(st);
    }

    @Test
    void theStrategyRoundTripsThroughTheJobFile() throws Exception {
        Path contour = Path.of("samples/pocket/rooms-islands.contour").toAbsolutePath();
        for (PocketStrategy st : new PocketStrategy[] {
            new PocketStrategy(PocketStrategy.Kind.ZIGZAG, 37.5, 0.25, PocketStrategy.Order.INSIDE_OUT),
            new PocketStrategy(PocketStrategy.Kind.OFFSET, 0, 0.5, PocketStrategy.Order.OUTSIDE_IN),
            new PocketStrategy(PocketStrategy.Kind.ZIGZAG, -180, 0, PocketStrategy.Order.INSIDE_OUT),
            new PocketStrategy(PocketStrategy.Kind.OFFSET, 0, 0, PocketStrategy.Order.INSIDE_OUT, 2.5),
            new PocketStrategy(PocketStrategy.Kind.ADAPTIVE, 0, 0.3, PocketStrategy.Order.INSIDE_OUT)
        }) {
            Job job = Job.empty(JobTask.POCKET).withPocket(settings(contour, st));
            Path file = dir.resolve("job.xml");
            JobXml.write(job, file);
            assertEquals(st, JobXml.read(file).pocket().orElseThrow().strategy(), Files.readString(file));
        }
    }

    @Test
    void theDefaultStrategyIsNotWritten() throws Exception {
        Path file = dir.resolve("job.xml");
        JobXml.write(
                Job.empty(JobTask.POCKET)
                        .withPocket(settings(
                                Path.of("samples/pocket/cavity01.dad").toAbsolutePath(), PocketStrategy.DEFAULT)),
                file);
        String xml = Files.readString(file);
        assertFalse(
                xml.contains("strategy=")
                        || xml.contains("angleDeg=")
                        || xml.contains("stockToLeaveMm=")
                        || xml.contains("order=")
                        || xml.contains("restToolDiameterMm="),
                xml);
        assertEquals(
                PocketStrategy.DEFAULT, JobXml.read(file).pocket().orElseThrow().strategy());
    }

    @Test
    void anAngleOrAStockOutOfRangeIsRefusedAtTheJobFile() throws Exception {
        for (String attribute : new String[] {
            "angleDeg=\"200\"",
            "stockToLeaveMm=\"11\"",
            "order=\"sideways\"",
            "restToolDiameterMm=\"6\"",
            "restToolDiameterMm=\"5.995\"",
            "restToolDiameterMm=\"0\"",
            "restToolDiameterMm=\"0.001\""
        }) {
            Path file = dir.resolve("bad.xml");
            Files.writeString(
                    file,
                    "<?xml version=\"1.0\"?>\n<job xmlns=\"urn:fresa:job:1\" version=\"1\" task=\"pocket\">"
                            + "<pocket contour=\"c.dad\" toolDiameterMm=\"6\" strategy=\"zigzag\" " + attribute
                            + "/></job>\n");
            assertThrows(CamInputException.class, () -> JobXml.read(file), attribute);
        }
    }

    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.EnumSource(
            value = PocketStrategy.Kind.class,
            names = {"ZIGZAG", "ADAPTIVE"})
    void runningTheSavedJobWritesThePocketCommandsProgram(PocketStrategy.Kind kind) throws Exception {
        PocketSettings s = settings(
                Path.of("samples/pocket/rooms-islands.contour").toAbsolutePath(),
                new PocketStrategy(kind, 30, 0.2, PocketStrategy.Order.INSIDE_OUT));
        Path direct = dir.resolve("direct.ngc");
        Path directSlowed = dir.resolve("direct-slowed.csv");
        java.util.Optional<Path> slowed =
                kind == PocketStrategy.Kind.ADAPTIVE ? java.util.Optional.of(directSlowed) : java.util.Optional.empty();
        assertEquals(
                0,
                PocketService.run(s, direct, java.util.Optional.empty(), slowed, ProgressMonitor.NONE)
                        .exitStatus());
        Path file = dir.resolve("job.xml");
        JobXml.write(Job.empty(JobTask.POCKET).withPocket(s), file);
        Path out = dir.resolve("out");
        Files.createDirectories(out);
        TaskOutcome o = JobRunner.run(JobXml.read(file), new OutputFolder(out), ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        assertTrue(Files.exists(out.resolve("pocket.ngc")));
        assertEquals(Files.readString(direct), Files.readString(out.resolve("pocket.ngc")));
        // an adaptive run also writes the moves it slowed, as fresa pocket --slowed does
        assertEquals(kind == PocketStrategy.Kind.ADAPTIVE, Files.exists(out.resolve("slowed.csv")));
        if (kind == PocketStrategy.Kind.ADAPTIVE) {
            assertEquals(Files.readString(directSlowed), Files.readString(out.resolve("slowed.csv")));
        }
    }

    @Test
    void runningTheSavedJobWithARestToolWritesThePocketCommandsProgram() throws Exception {
        PocketSettings s = settings(
                Path.of("samples/pocket/rooms-islands.contour").toAbsolutePath(),
                new PocketStrategy(PocketStrategy.Kind.OFFSET, 0, 0, PocketStrategy.Order.INSIDE_OUT, 2));
        Path direct = dir.resolve("direct.ngc");
        TaskOutcome d = PocketService.run(s, direct, ProgressMonitor.NONE);
        assertEquals(0, d.exitStatus(), d.problems().toString());
        String nc = Files.readString(direct);
        assertTrue(nc.contains("T2 M6") && nc.contains("S9000 M3"), "a tool change to the 2 mm tool at 9000 rpm");
        assertEquals(2.0, d.summary().get("rest_tool_diameter_mm"));
        Path file = dir.resolve("job.xml");
        JobXml.write(Job.empty(JobTask.POCKET).withPocket(s), file);
        assertTrue(Files.readString(file).contains("restToolDiameterMm=\"2.0\""), Files.readString(file));
        Path out = dir.resolve("out");
        Files.createDirectories(out);
        TaskOutcome o = JobRunner.run(JobXml.read(file), new OutputFolder(out), ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        assertEquals(nc, Files.readString(out.resolve("pocket.ngc")));
    }

    @Test
    void aRestToolWithNothingToCutWritesNoSecondToolAndSaysSo() throws Exception {
        // a round pocket: the 6 mm tool reaches all of it
        Path contour = dir.resolve("round.contour");
        Files.writeString(contour, "contour\nmove 30 0\narc 0 0 30 0 ccw\n");
        PocketSettings s = settings(
                contour, new PocketStrategy(PocketStrategy.Kind.OFFSET, 0, 0, PocketStrategy.Order.INSIDE_OUT, 2));
        Path out = dir.resolve("round.ngc");
        TaskOutcome o = PocketService.run(s, out, ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        assertEquals(java.util.List.of(PocketService.REST_TOOL_IDLE), o.problems());
        assertTrue(o.problems().get(0).contains("the rest tool has nothing to cut"));
        assertFalse(Files.readString(out).contains("T2"));
    }
}
