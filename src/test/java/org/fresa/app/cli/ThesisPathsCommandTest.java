package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fresa.geom.Tolerance;
import org.fresa.post.ExpectedMotions;
import org.fresa.post.NcPosts;
import org.fresa.post.Rs274;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.InterpreterCheck;
import org.fresa.toolpath.PathConvention;
import org.fresa.toolpath.PlanningChoices;
import org.fresa.toolpath.ToolpathPlanner;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code --paths thesis} on {@code fresa toolpath} and {@code fresa robot}: the programs pass the
 * program check (the thesis's cutters declared centre-cutting, since its paths plunge into every
 * layer) and LinuxCNC's interpreter; an unknown word is refused before any work.
 */
class ThesisPathsCommandTest {

    static final String EXAMPLE1 = "samples/stepnc/iso14649-11-example1.stp";
    static final String EXAMPLE2 = "samples/stepnc/example2.stp";

    @TempDir
    Path dir;

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    private int run(String... args) {
        return FresaCommand.execute(new PrintWriter(out, true), new PrintWriter(err, true), args);
    }

    @ParameterizedTest
    @ValueSource(strings = {EXAMPLE1, EXAMPLE2})
    @InterpreterCheck
    void theThesissPathsAreWrittenCheckedAndReadByLinuxCncAsPlanned(String input) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        int status = run("toolpath", input, "--paths", "thesis", "--out", dir.toString());
        String summary = Files.readString(dir.resolve("summary.json"));
        assertAll(
                err.toString(),
                // example 2's side faces need the part turned: its 3-axis program holds the top's 9
                // workingsteps (1015 of the robot's 3106 points), exit 1 for the other 17
                () -> assertEquals(input.equals(EXAMPLE2) ? 1 : 0, status),
                () -> assertFalse(summary.contains("program_refused")),
                () -> assertTrue(
                        summary.contains(input.equals(EXAMPLE2) ? "\"points\": 1015" : "\"points\": 531"), summary));
        Rs274.Result r = Rs274.run(dir.resolve("program.ngc"), 20);
        assertEquals(0, r.exitStatus(), r.stderr());
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(
                StepNcReader.read(Path.of(input)),
                Tolerance.DEFAULT,
                PlanningChoices.DEFAULT.withPaths(PathConvention.THESIS));
        List<Rs274.Canon> expected = ExpectedMotions.of(
                org.fresa.job.ToolpathService.alongMachineZ(plan).toolpath(), false, NcPosts.CHORD_TOLERANCE_MM);
        assertNull(ExpectedMotions.firstDifference(expected, r.motions(), 0.0011));
    }

    @Test
    void theRobotProgramsOfTheThesissPathsPassTheCheck() throws Exception {
        int status = run(
                "robot",
                EXAMPLE2,
                "--paths",
                "thesis",
                "--robot",
                "irb140",
                "--robot-table",
                "450,0,350",
                "--table-piece",
                "0,10,0",
                "--formats",
                "csv,xml,rapid,krl",
                "--out",
                dir.toString());
        String summary = Files.readString(dir.resolve("summary.json"));
        // the robot keeps a workingstep's first point (the security point) only where the previous one
        // did not end there with the same tool axis: 3106 points less 23 repeats
        assertAll(
                err.toString(),
                () -> assertEquals(0, status),
                () -> assertTrue(summary.contains("\"targets\": 3083"), summary),
                () -> assertTrue(Files.exists(dir.resolve("program.mod"))),
                () -> assertTrue(Files.exists(dir.resolve("program.src"))),
                () -> assertTrue(Files.exists(dir.resolve("program.xml"))));
    }

    @Test
    void anUnknownPathConventionIsRefusedBeforeAnyWork() {
        for (String command : new String[] {"toolpath", "robot"}) {
            Path o = dir.resolve(command);
            int status = command.equals("robot")
                    ? run("robot", EXAMPLE2, "--robot", "irb140", "--out", o.toString(), "--paths", "nist")
                    : run("toolpath", EXAMPLE2, "--out", o.toString(), "--paths", "nist");
            assertAll(
                    err.toString(),
                    () -> assertEquals(2, status),
                    () -> assertTrue(err.toString()
                            .contains("--paths: unknown path conventions 'nist': expected fresa" + " or thesis")),
                    () -> assertFalse(err.toString().contains("Exception")),
                    () -> assertFalse(Files.exists(o)));
        }
    }
}
