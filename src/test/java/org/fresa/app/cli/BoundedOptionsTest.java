package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The option values that hung, ate the heap or ended in an internal error, each
 * refused where it is parsed (exit 2, the option and its range named, nothing written), and the
 * limits that were inconsistent (a Tricept's legs, size 0, a Part 21 byte order mark).
 */
class BoundedOptionsTest {

    @TempDir
    Path dir;

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    private int run(List<String> args) {
        return FresaCommand.execute(
                new PrintWriter(out, true), new PrintWriter(err, true), args.toArray(String[]::new));
    }

    private List<String> pocket(String... extra) {
        List<String> a = new ArrayList<>(List.of(
                "pocket",
                "samples/pocket/cavity01.dad",
                "--out",
                dir.resolve("p.ngc").toString(),
                "--tool-diameter",
                "6"));
        for (int i = 0; i < extra.length; i += 2) {
            int at = a.indexOf(extra[i]);
            if (at >= 0) {
                a.set(at + 1, extra[i + 1]);
            } else {
                a.addAll(List.of(extra[i], extra[i + 1]));
            }
        }
        return a;
    }

    private List<String> grade(String sizes, String... extra) {
        List<String> a = new ArrayList<>(List.of(
                "grade",
                "samples/grading/sole-40.contour",
                "--out",
                dir.resolve("g").toString(),
                "--base-size",
                "40",
                "--sizes",
                sizes,
                "--system",
                "br"));
        a.addAll(List.of(extra));
        return a;
    }

    private void refused(int status, String... words) throws Exception {
        String e = err.toString();
        List<String> written;
        try (Stream<Path> s = Files.walk(dir)) {
            written = s.filter(p -> !p.equals(dir)).map(Path::toString).toList();
        }
        assertAll(
                e,
                () -> assertEquals(2, status),
                () -> assertTrue(Stream.of(words).allMatch(e::contains), "says " + List.of(words)),
                () -> assertFalse(e.contains("internal error") || e.contains("Exception")),
                () -> assertEquals(List.of(), written, "nothing written"));
    }

    @ParameterizedTest(name = "pocket {0} {1}")
    @CsvSource(textBlock = """
            --z-top,       1e308,  from -10000 to 10000 mm
            --max-depth,   1e-9,   from 0.001 to 1000 mm
            --rpm,         0,      from 1 to 100000 rpm
            --rpm,         -1,     from 1 to 100000 rpm
            --rpm,         NaN,    from 1 to 100000 rpm
            --rpm,         1e308,  from 1 to 100000 rpm
            --feed,        1e308,  from 0.1 to 100000 mm/min
            --finish-feed, 0,      from 0.1 to 100000 mm/min
            --tool-diameter, Infinity, from 0.01 to 1000 mm
            --angle,       200,    from -180 to 180 deg
            --angle,       NaN,    from -180 to 180 deg
            --stock-to-leave, 11,  from 0 to 10 mm
            --stock-to-leave, -1,  from 0 to 10 mm
            --rest-tool,   6,      at least 0.01 mm and below 5.99 mm
            --rest-tool,   5.995,  at least 0.01 mm and below 5.99 mm
            --rest-tool,   0,      at least 0.01 mm and below 5.99 mm
            --rest-tool,   1e-9,   at least 0.01 mm and below 5.99 mm
            --rest-tool,   -2,     at least 0.01 mm and below 5.99 mm
            --rest-tool,   NaN,    at least 0.01 mm and below 5.99 mm
            """)
    void pocketOptionsOutOfTheirRangeAreRefused(String option, String value, String range) throws Exception {
        refused(run(pocket(option, value)), option, range, "found");
    }

    @ParameterizedTest(name = "pocket --strategy zigzag --post {0}")
    @ValueSource(strings = {"7m", "7m-compat"})
    void zigzagOnTheThesisPostsIsRefused(String post) throws Exception {
        refused(run(pocket("--strategy", "zigzag", "--post", post)), "--strategy", "zigzag needs one of linuxcnc");
        refused(run(pocket("--order", "outside-in", "--post", post)), "--order", "needs one of linuxcnc");
        refused(run(pocket("--rest-tool", "2", "--post", post)), "--rest-tool", "needs one of linuxcnc");
    }

    @ParameterizedTest(name = "cut {0} 1e308")
    @ValueSource(strings = {"--lead-in", "--lead-out", "--overcut", "--kerf"})
    void cuttingLengthsOutOfTheirRangeAreRefused(String option) throws Exception {
        refused(
                run(List.of(
                        "cut",
                        "samples/cutting/plate.dxf",
                        "--out",
                        dir.resolve("c.ngc").toString(),
                        option,
                        "1e308")),
                option,
                "expected a number from 0 to");
    }

    @Test
    void aDepthStepThatMakesMoreThanAMillionLayersIsRefused() throws Exception {
        refused(run(pocket("--z-top", "10000", "--max-depth", "0.001")), "more than 1000000 depth passes");
    }

    @Test
    void aPocketProgramOfMoreThanAMillionMovesIsNotDoable() {
        int status = run(pocket("--z-top", "9000", "--max-depth", "1"));
        assertAll(
                err.toString(),
                () -> assertEquals(1, status),
                () -> assertTrue(err.toString().contains("more than 1000000 in all")),
                () -> assertFalse(Files.exists(dir.resolve("p.ngc"))));
    }

    @Test
    void sizesBeyondTheSystemAreRefused() throws Exception {
        refused(run(grade("2147483647-2147483647")), "size 2147483647 is not a Brazilian size", "at most 148");
    }

    @Test
    void aRangeOfMoreSizesThanALongHoldsIsRefused() throws Exception {
        refused(run(grade("40-1e308")), "size");
    }

    @Test
    void sizeZeroIsRefused() throws Exception {
        refused(run(grade("0-1")), "size 0 is not a Brazilian size");
    }

    @Test
    void aNegativeBaseSizeIsRefused() throws Exception {
        List<String> a = grade("39-40");
        a.set(a.indexOf("--base-size") + 1, "-40");
        refused(run(a), "--base-size", "above 0");
    }

    @Test
    void anAbsurdLengthStepIsRefusedNotAnInternalError() throws Exception {
        refused(run(grade("39-40", "--length-step", "1e308")), "--length-step", "at most 100 mm");
    }

    @Test
    void anOriginOutsideTheMachineIsRefused() throws Exception {
        refused(run(grade("39-40", "--origin", "0,1e308")), "--origin", "from -10000 to 10000 mm");
    }

    @Test
    void aPlacementOutsideTheCellIsRefused() throws Exception {
        refused(
                run(List.of(
                        "robot",
                        "samples/stepnc/example2.stp",
                        "--robot",
                        "irb140",
                        "--out",
                        dir.resolve("r").toString(),
                        "--robot-table",
                        "450,0,1e308")),
                "--robot-table",
                "z: expected");
    }

    @Test
    void aRobotFileWithAnAbsurdLinkLengthIsRefusedAtItsLine() throws Exception {
        Path robot = dir.resolve("robot.xml");
        Files.writeString(
                robot, Files.readString(Path.of("samples/robot/irb140.xml")).replace("a=\"70\" ", "a=\"1e308\""));
        int status = run(List.of(
                "robot",
                "samples/stepnc/example2.stp",
                "--robot",
                robot.toString(),
                "--out",
                dir.resolve("r").toString()));
        Files.delete(robot);
        refused(status, "robot.xml: line 6", "a: expected a number from -100000 to 100000 mm, found 1E308");
    }

    @Test
    void aTriceptLegWithMinAboveMaxIsRefusedLikeASerialJoint() throws Exception {
        Path tricept = dir.resolve("tricept.xml");
        Files.writeString(
                tricept,
                Files.readString(Path.of("samples/robot/tricept806.xml"))
                        .replaceFirst("<leg min=\"900\" max=\"1800\"/>", "<leg min=\"1800\" max=\"900\"/>"));
        Path serial = dir.resolve("serial.xml");
        Files.writeString(
                serial,
                Files.readString(Path.of("samples/robot/irb140.xml"))
                        .replace("min=\"-180\" max=\"180\"", "min=\"180\" max=\"-180\""));
        int t = run(List.of(
                "robot",
                "samples/stepnc/example2.stp",
                "--robot",
                tricept.toString(),
                "--out",
                dir.resolve("t").toString()));
        String tErr = err.toString();
        err.getBuffer().setLength(0);
        int s = run(List.of(
                "robot",
                "samples/stepnc/example2.stp",
                "--robot",
                serial.toString(),
                "--out",
                dir.resolve("s").toString()));
        assertAll(
                () -> assertEquals(2, t, tErr),
                () -> assertTrue(tErr.contains("max > min"), tErr),
                () -> assertEquals(2, s, err.toString()),
                () -> assertTrue(err.toString().contains("max > min")),
                () -> assertFalse(Files.exists(dir.resolve("t"))),
                () -> assertFalse(Files.exists(dir.resolve("s"))));
    }

    @Test
    void aJobFileCannotBringAValueTheOptionRefuses() throws Exception {
        Path job = dir.resolve("job.xml");
        Files.writeString(
                job,
                Files.readString(Path.of("samples/jobs/pocket-cavity01.xml"))
                        .replace(
                                "../pocket/cavity01.dad",
                                Path.of("samples/pocket/cavity01.dad")
                                        .toAbsolutePath()
                                        .toString())
                        .replace("zTopMm=\"30\"", "zTopMm=\"1e300\""));
        int status =
                run(List.of("run", job.toString(), "--out", dir.resolve("out").toString()));
        Files.delete(job);
        refused(status, "job.xml: line 6", "zTopMm: expected a number from -10000 to 10000 mm, found 1E300");
    }

    @Test
    void aPart21FileWithAByteOrderMarkIsRead() throws Exception {
        Path bom = dir.resolve("bom.stp");
        byte[] text = Files.readAllBytes(Path.of("samples/stepnc/example2.stp"));
        byte[] withMark = new byte[text.length + 3];
        withMark[0] = (byte) 0xEF;
        withMark[1] = (byte) 0xBB;
        withMark[2] = (byte) 0xBF;
        System.arraycopy(text, 0, withMark, 3, text.length);
        Files.write(bom, withMark);
        int status = run(List.of("stepnc", bom.toString(), "--json"));
        assertAll(
                () -> assertEquals(0, status, err.toString()),
                () -> assertTrue(out.toString().contains("\"workingsteps\""), out.toString()));
    }
}
