package org.fresa.robustness;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fresa.app.cli.FresaCommand;
import org.fresa.model.FileChecks;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Paths that are not regular files: {@code --out} naming a named pipe or a device is
 * refused with exit 2 before any work and the node is left as it was (it used to be replaced by a
 * G-code file, /dev/full too when run as root); an input that is a directory or a pipe is refused
 * with exit 2 and a sentence saying what it is, without waiting on the pipe.
 */
class OutputAndInputPathsTest {

    @TempDir
    Path dir;

    private Path fifo;
    private Path device;

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    @BeforeEach
    void makeNodes() throws Exception {
        fifo = dir.resolve("pipe");
        assumeTrue(exec("mkfifo", fifo.toString()), "mkfifo is needed");
        device = dir.resolve("null-device");
        // a character device of our own (the same as /dev/null), so that a failure replaces no system node
        if (!exec("mknod", device.toString(), "c", "1", "3")) {
            device = null;
        }
    }

    private static boolean exec(String... cmd) throws Exception {
        try {
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
            return p.waitFor(10, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (java.io.IOException e) {
            return false;
        }
    }

    private int run(List<String> args) {
        return FresaCommand.execute(
                new PrintWriter(out, true), new PrintWriter(err, true), args.toArray(String[]::new));
    }

    private static List<String> command(String name, Path target) {
        String t = target.toString();
        return switch (name) {
            case "pocket" -> List.of("pocket", "samples/pocket/cavity01.dad", "--out", t, "--tool-diameter", "6");
            case "cut" -> List.of("cut", "samples/cutting/plate.dxf", "--out", t);
            case "grade" ->
                List.of(
                        "grade",
                        "samples/grading/sole-40.contour",
                        "--out",
                        t,
                        "--base-size",
                        "40",
                        "--sizes",
                        "40",
                        "--system",
                        "br");
            case "toolpath" -> List.of("toolpath", "samples/stepnc/example2.stp", "--out", t);
            case "robot" -> List.of("robot", "samples/stepnc/example2.stp", "--robot", "irb140", "--out", t);
            case "run" -> List.of("run", "samples/jobs/grade-sole40.xml", "--out", t);
            case "sole" -> List.of("sole", "samples/jobs/sole-men40.xml", "--out", t);
            default -> throw new IllegalArgumentException(name);
        };
    }

    private void assertRefusedAndUnchanged(int status, Path node, String kind) throws Exception {
        FileTime before = Files.getLastModifiedTime(node);
        String e = err.toString();
        assertAll(
                e,
                () -> assertEquals(2, status),
                () -> assertTrue(e.contains("--out") && e.contains("is " + kind), "names --out and " + kind),
                () -> assertEquals(kind, FileChecks.kind(node), "the node is still " + kind),
                () -> assertEquals(before, Files.getLastModifiedTime(node)),
                () -> assertEquals(List.of(), others(node), "nothing else written"));
    }

    private List<String> others(Path node) throws Exception {
        List<String> l = new ArrayList<>();
        try (var s = Files.list(dir)) {
            s.filter(p -> !p.equals(fifo) && !p.equals(device))
                    .forEach(p -> l.add(p.getFileName().toString()));
        }
        return l;
    }

    @ParameterizedTest(name = "{0} --out FIFO")
    @ValueSource(strings = {"pocket", "cut", "grade", "toolpath", "robot", "run", "sole"})
    void anOutputThatIsANamedPipeIsRefusedAndLeftAsItIs(String name) throws Exception {
        int status = assertTimeoutPreemptively(Duration.ofSeconds(60), () -> run(command(name, fifo)));
        assertRefusedAndUnchanged(status, fifo, "a named pipe (FIFO)");
    }

    @ParameterizedTest(name = "{0} --out DEVICE")
    @ValueSource(strings = {"pocket", "cut", "grade", "run"})
    void anOutputThatIsADeviceIsRefusedAndLeftAsItIs(String name) throws Exception {
        assumeTrue(device != null, "mknod is not allowed here");
        int status = assertTimeoutPreemptively(Duration.ofSeconds(60), () -> run(command(name, device)));
        assertRefusedAndUnchanged(status, device, "a character device");
    }

    @ParameterizedTest(name = "{0} on a directory")
    @CsvSource(textBlock = """
            cut,      a.dxf,      is a directory, not a DXF drawing
            pocket,   a.contour,  is a directory, not a contour file
            pocket,   a.dad,      is a directory, not a pocket contour
            stepnc,   a.stp,      is a directory, not a Part 21 file
            grade,    a.contour,  is a directory, not a sole outline
            run,      a.xml,      is a directory, not a job file
            """)
    void anInputThatIsADirectoryIsRefusedWithASentence(String name, String input, String sentence) throws Exception {
        Path in = Files.createDirectory(dir.resolve(input));
        int status = run(input(name, in));
        assertAll(
                err.toString(),
                () -> assertEquals(2, status),
                () -> assertTrue(err.toString().contains(sentence)),
                () -> assertFalse(err.toString().contains("Exception")));
    }

    @ParameterizedTest(name = "{0} on a named pipe")
    @ValueSource(strings = {"cut", "pocket", "stepnc", "grade", "run"})
    void anInputThatIsANamedPipeIsRefusedWithoutWaitingForAWriter(String name) {
        int status = assertTimeoutPreemptively(Duration.ofSeconds(30), () -> run(input(name, fifo)));
        assertAll(
                err.toString(),
                () -> assertEquals(2, status),
                () -> assertTrue(err.toString().contains("is a named pipe (FIFO), not a")));
    }

    @org.junit.jupiter.api.Test
    void aRobotFileThatIsADirectoryIsRefusedWithASentence() throws Exception {
        Path robot = Files.createDirectory(dir.resolve("robot.xml"));
        int status = run(List.of(
                "robot",
                "samples/stepnc/example2.stp",
                "--robot",
                robot.toString(),
                "--out",
                dir.resolve("r").toString()));
        assertAll(
                err.toString(),
                () -> assertEquals(2, status),
                () -> assertTrue(err.toString().contains("is a directory, not a robot file")));
    }

    private List<String> input(String name, Path in) {
        String i = in.toString();
        Path o = dir.resolve("out");
        return switch (name) {
            case "cut" -> List.of("cut", i, "--out", o.resolve("c.ngc").toString());
            case "pocket" -> List.of("pocket", i, "--out", o.resolve("p.ngc").toString(), "--tool-diameter", "6");
            case "stepnc" -> List.of("stepnc", i);
            case "grade" ->
                List.of("grade", i, "--out", o.toString(), "--base-size", "40", "--sizes", "40", "--system", "br");
            case "run" -> List.of("run", i, "--out", o.toString());
            default -> throw new IllegalArgumentException(name);
        };
    }
}
