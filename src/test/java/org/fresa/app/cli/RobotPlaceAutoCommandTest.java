package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code fresa robot --place auto}: the placement found is printed, and typed back it reaches every point. */
class RobotPlaceAutoCommandTest {

    @TempDir
    Path dir;

    private StringWriter out = new StringWriter();
    private StringWriter err = new StringWriter();

    private int run(String... args) {
        out = new StringWriter();
        err = new StringWriter();
        return FresaCommand.execute(new PrintWriter(out, true), new PrintWriter(err, true), args);
    }

    @Test
    void thePlacementPrintedIsTheOneThatReachesEveryPoint() throws Exception {
        assertEquals(
                0,
                run(
                        "robot",
                        "samples/stepnc/iso14649-11-example1.stp",
                        "--robot",
                        "tricept806",
                        "--out",
                        dir.resolve("a").toString(),
                        "--place",
                        "auto",
                        "--formats",
                        "csv"),
                err::toString);
        Matcher m = Pattern.compile("placement found: --robot-table (\\S+) reaches all (\\d+) targets")
                .matcher(out.toString());
        assertTrue(m.find(), out::toString);
        String summary = Files.readString(dir.resolve("a/summary.json"));
        assertTrue(summary.contains("\"unreachable\": 0"), summary);
        assertEquals(
                0,
                run(
                        "robot",
                        "samples/stepnc/iso14649-11-example1.stp",
                        "--robot",
                        "tricept806",
                        "--out",
                        dir.resolve("b").toString(),
                        "--robot-table",
                        m.group(1),
                        "--formats",
                        "csv"),
                err::toString);
        assertTrue(Files.readString(dir.resolve("b/summary.json")).contains("\"unreachable\": 0"));
    }

    /**
     * GRIMA's testBoxy: a placement reaches every target, and the run exits 1 (a workingstep is not
     * planned, the robot program is refused): the placement is printed all the same.
     */
    @Test
    void thePlacementFoundIsPrintedAlsoWhenTheRunExitsWith1() {
        Path boxy = Path.of("../shared/corpus/stepnc/grima/testBoxy.p21");
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.exists(boxy), "the corpus is not beside the checkout");
        assertEquals(
                1,
                run(
                        "robot",
                        boxy.toString(),
                        "--robot",
                        "irb140",
                        "--out",
                        dir.resolve("boxy").toString(),
                        "--place",
                        "auto",
                        "--formats",
                        "csv"),
                err::toString);
        assertTrue(out.toString().contains("placement found: --robot-table "), out + "\n" + err);
    }

    @Test
    void anotherWordThanAutoIsRefusedWithNothingWritten() {
        assertEquals(
                2,
                run(
                        "robot",
                        "samples/stepnc/iso14649-11-example1.stp",
                        "--robot",
                        "tricept806",
                        "--out",
                        dir.resolve("c").toString(),
                        "--place",
                        "anywhere"));
        assertTrue(
                err.toString().contains("--place") && err.toString().contains("expected auto or given"), err::toString);
        assertTrue(!Files.exists(dir.resolve("c")));
    }
}
