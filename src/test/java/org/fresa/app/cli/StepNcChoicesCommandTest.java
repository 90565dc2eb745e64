package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code fresa toolpath} on workingsteps whose technology is missing or contradictory:
 * exit 1 with each refused workingstep's name and reason, the rest written; {@code
 * --trust-cutting-speed} plans from the cutting speed; {@code --breakthrough} is bounded.
 */
class StepNcChoicesCommandTest {

    static final String TECHNOLOGY = "src/test/resources/org/fresa/toolpath/technology.stp";
    static final String HOLES = "src/test/resources/org/fresa/toolpath/holes.stp";

    @TempDir
    Path dir;

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    private int run(String... args) {
        return FresaCommand.execute(new PrintWriter(out, true), new PrintWriter(err, true), args);
    }

    @Test
    void aRefusedWorkingstepExitsOneNamingItAndTheRestIsWritten() throws Exception {
        int status = run("toolpath", TECHNOLOGY, "--out", dir.toString());
        String e = err.toString();
        assertAll(
                e,
                () -> assertEquals(1, status),
                () -> assertTrue(e.contains("workingstep 'WS NO SPEED' (#11): no spindle speed and no cutting speed")),
                () -> assertTrue(e.contains("'WS SPINDLE 100 TIMES TOO SLOW' (#12): spindle 5.84 rpm and cutting speed"
                        + " 0.1835 m/s (584.0986 rpm for the 6 mm tool)")),
                () -> assertTrue(
                        e.contains("'WS SPEED FROM CUTTING SPEED': no spindle speed in the file: 5729.578 rpm")),
                () -> assertFalse(e.contains("Exception")),
                () -> assertTrue(Files.readString(dir.resolve("program.ngc")).contains("S5730 M3")));
    }

    @Test
    void trustingTheCuttingSpeedPlansTheContradictoryWorkingstepAtIt() throws Exception {
        int status = run("toolpath", TECHNOLOGY, "--out", dir.toString(), "--trust-cutting-speed");
        assertAll(
                err.toString(),
                () -> assertEquals(1, status),
                () -> assertTrue(err.toString().contains("planned at 584.0986 rpm from the cutting speed")),
                () -> assertTrue(Files.readString(dir.resolve("program.ngc")).contains("S584 M3")));
    }

    @Test
    void aFileWhoseTechnologyAndHolesAreWholeExitsZeroWithTheBreakthroughAskedFor() throws Exception {
        int status = run("toolpath", HOLES, "--out", dir.toString(), "--breakthrough", "2.5");
        assertAll(
                err.toString(),
                () -> assertEquals(0, status),
                () -> assertTrue(Files.readString(dir.resolve("program.ngc")).contains("Z-4.303")));
    }

    @ParameterizedTest
    @ValueSource(strings = {"-1", "NaN", "1e308", "101"})
    void aBreakthroughOutOfItsRangeIsRefusedBeforeAnyWork(String value) {
        for (String command : new String[] {"toolpath", "robot"}) {
            Path o = dir.resolve(command);
            int status = command.equals("robot")
                    ? run("robot", HOLES, "--robot", "irb140", "--out", o.toString(), "--breakthrough", value)
                    : run("toolpath", HOLES, "--out", o.toString(), "--breakthrough", value);
            assertAll(
                    err.toString(),
                    () -> assertEquals(2, status),
                    () -> assertTrue(err.toString().contains("--breakthrough: expected a number from 0 to 100 mm")),
                    () -> assertFalse(Files.exists(o)));
        }
    }
}
