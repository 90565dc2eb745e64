package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fresa.job.Job;
import org.fresa.job.JobSettings.StepNcSettings;
import org.fresa.job.JobTask;
import org.fresa.job.JobXml;
import org.fresa.model.CamInputException;
import org.fresa.pocket.EntryRule;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The entry options of {@code fresa toolpath} and {@code fresa robot}, named as {@code fresa
 * pocket}'s ({@code --entry}, {@code --entry-angle}, {@code --centre-cutting}), and the job's
 * {@code <stepnc>} attributes: refused before any work when out of range or when a cutter not said
 * to cut at its centre is asked to plunge; the defaults leave the programs as they were.
 */
class StepNcEntryCommandTest {

    static final String EXAMPLE1 = "samples/stepnc/iso14649-11-example1.stp";
    static final Pattern MOVE = Pattern.compile("^G[0-3] X(\\S+) Y(\\S+) Z(\\S+)");

    @TempDir
    Path dir;

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    private int run(List<String> args) {
        return FresaCommand.execute(
                new PrintWriter(out, true), new PrintWriter(err, true), args.toArray(String[]::new));
    }

    private List<String> command(String command, Path o, String... extra) {
        List<String> a = new java.util.ArrayList<>(
                command.equals("robot")
                        ? List.of(
                                "robot",
                                EXAMPLE1,
                                "--robot",
                                "irb140",
                                "--out",
                                o.toString(),
                                "--robot-table",
                                "450,0,350",
                                "--table-piece",
                                "0,10,0")
                        : List.of("toolpath", EXAMPLE1, "--out", o.toString()));
        a.addAll(List.of(extra));
        return a;
    }

    @ParameterizedTest
    @CsvSource(
            delimiter = ';',
            value = {
                "--entry plunge; --entry plunge: a plunge entry needs a centre-cutting tool",
                "--entry spiral; '--entry': unknown value 'spiral': expected one of auto, helix, ramp, plunge",
                "--entry-angle 0.4; --entry-angle: expected a number from 0.5 to 90 deg",
                "--entry-angle NaN; --entry-angle: expected a number from 0.5 to 90 deg",
                "--entry-angle 91; --entry-angle: expected a number from 0.5 to 90 deg"
            })
    void aBadEntryIsRefusedBeforeAnyWork(String options, String message) {
        for (String c : new String[] {"toolpath", "robot"}) {
            Path o = dir.resolve(c);
            int status = run(command(c, o, options.split(" ")));
            assertAll(
                    c + " " + options + ": " + err,
                    () -> assertEquals(2, status),
                    () -> assertTrue(err.toString().contains(message)),
                    () -> assertFalse(err.toString().contains("Exception")),
                    () -> assertFalse(Files.exists(o)));
        }
    }

    @Test
    void aCentreCuttingCutterAskedToPlungeGoesStraightDownAndItsProgramPassesTheCheck() throws Exception {
        int plain = run(command("toolpath", dir.resolve("plain")));
        int plunged = run(command("toolpath", dir.resolve("plunge"), "--entry", "plunge", "--centre-cutting"));
        String p = Files.readString(dir.resolve("plain/program.ngc"));
        String q = Files.readString(dir.resolve("plunge/program.ngc"));
        assertAll(
                err.toString(),
                () -> assertEquals(0, plain),
                () -> assertEquals(0, plunged),
                // the drills' straight feeds in both; the pockets' plunges besides in the second
                () -> assertTrue(straightDownFeeds(q) > straightDownFeeds(p), q),
                () -> assertTrue(helicalArcs(q) < helicalArcs(p), q));
    }

    @Test
    void aRampAskedForReplacesTheHelixAndTheRobotRunTakesTheOptionsToo() throws Exception {
        int def = run(command("toolpath", dir.resolve("plain")));
        int ramp = run(command("toolpath", dir.resolve("ramp"), "--entry", "ramp", "--entry-angle", "2"));
        int robot = run(
                command("robot", dir.resolve("robot"), "--entry", "ramp", "--entry-angle", "2", "--formats", "csv"));
        String plain = Files.readString(dir.resolve("plain/program.ngc"));
        String r = Files.readString(dir.resolve("ramp/program.ngc"));
        assertAll(
                err.toString(),
                () -> assertEquals(0, def),
                () -> assertEquals(0, ramp),
                () -> assertEquals(0, robot),
                () -> assertTrue(helicalArcs(r) < helicalArcs(plain), r),
                () -> assertTrue(Files.exists(dir.resolve("robot/trajectory.csv"))));
    }

    @Test
    void theJobsStepncElementCarriesTheEntryAndSavesItOnlyWhenNotTheDefault() throws Exception {
        Path file = dir.resolve("job.xml");
        Path stp = Path.of(EXAMPLE1).toAbsolutePath();
        JobXml.write(
                Job.empty(JobTask.TOOLPATH).withStepnc(new StepNcSettings(stp, org.fresa.post.MillingPost.LINUXCNC)),
                file);
        String plain = Files.readString(file);
        Job chosen = Job.empty(JobTask.TOOLPATH)
                .withStepnc(new StepNcSettings(
                        stp,
                        org.fresa.post.MillingPost.LINUXCNC,
                        false,
                        1,
                        new EntryRule(EntryRule.Kind.RAMP, 2, false)));
        JobXml.write(chosen, file);
        String saved = Files.readString(file);
        Path bad = dir.resolve("bad.xml");
        Files.writeString(
                bad,
                "<?xml version=\"1.0\"?>\n<job xmlns=\"urn:fresa:job:1\" version=\"1\" task=\"toolpath\">"
                        + "<stepnc file=\"" + stp + "\" entry=\"plunge\"/></job>\n");
        Path angle = dir.resolve("angle.xml");
        Files.writeString(
                angle,
                "<?xml version=\"1.0\"?>\n<job xmlns=\"urn:fresa:job:1\" version=\"1\" task=\"toolpath\">"
                        + "<stepnc file=\"" + stp + "\" entryAngleDeg=\"95\"/></job>\n");
        assertAll(
                () -> assertFalse(plain.contains("entry"), plain),
                () -> assertTrue(saved.contains("entry=\"ramp\"") && saved.contains("entryAngleDeg=\"2.0\""), saved),
                () -> assertEquals(chosen, JobXml.read(file)),
                () -> assertTrue(assertThrows(CamInputException.class, () -> JobXml.read(bad))
                        .getMessage()
                        .contains("entry=\"plunge\" needs centreCutting=\"true\"")),
                () -> assertTrue(assertThrows(CamInputException.class, () -> JobXml.read(angle))
                        .getMessage()
                        .contains("entryAngleDeg")));
    }

    /** Feed moves that change only Z, downwards. */
    static int straightDownFeeds(String program) {
        int n = 0;
        String[] last = null;
        for (String line : program.split("\n")) {
            Matcher m = MOVE.matcher(line);
            if (!m.find()) {
                continue;
            }
            String[] at = {m.group(1), m.group(2), m.group(3)};
            if (line.startsWith("G1")
                    && last != null
                    && at[0].equals(last[0])
                    && at[1].equals(last[1])
                    && Double.parseDouble(at[2]) < Double.parseDouble(last[2])) {
                n++;
            }
            last = at;
        }
        return n;
    }

    /** Arcs that change Z (helices). */
    static long helicalArcs(String program) {
        return program.lines().filter(l -> l.matches("^G[23] .*Z.*")).count();
    }
}
