package org.fresa.robustness;

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
import java.util.concurrent.TimeUnit;
import org.fresa.app.cli.FresaCommand;
import org.fresa.io.FolderLock;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Two commands writing into the same folder at once with real processes: while a
 * long {@code fresa grade} holds the folder, a second run into it (here a job) is refused
 * with exit 1 naming the first one's process, and writes nothing. The first run is then killed:
 * SIGTERM leaves neither a temporary file nor the lock file; after SIGKILL the lock file may be
 * left, and the next run takes it over. Either way the next run completes.
 */
class FolderLockProcessTest {

    @TempDir
    Path dir;

    private static String[] grade(Path out, String sizes) {
        return new String[] {
            "grade",
            "samples/grading/sole-40.contour",
            "--out",
            out.toString(),
            "--base-size",
            "40",
            "--sizes",
            sizes,
            "--half-sizes",
            "--system",
            "br"
        };
    }

    private static int run(StringWriter err, String... args) {
        return FresaCommand.execute(new PrintWriter(new StringWriter(), true), new PrintWriter(err, true), args);
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"SIGTERM", "SIGKILL"})
    void aSecondRunIntoABusyFolderIsRefusedAndTheFolderIsFreeAfterTheFirstIsKilled(String signal) throws Exception {
        Path out = Files.createDirectories(dir.resolve("out"));
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(List.of(
                java,
                "-Xmx256m",
                "-Djava.awt.headless=true",
                "-cp",
                System.getProperty("java.class.path"),
                "org.fresa.app.Main"));
        cmd.addAll(List.of(grade(out, "17-50")));
        Process first = new ProcessBuilder(cmd)
                .redirectErrorStream(true)
                .redirectOutput(dir.resolve("log").toFile())
                .start();
        Path lock = out.resolve(FolderLock.FILE_NAME);
        StringWriter err = new StringWriter();
        int second;
        try {
            long until = System.currentTimeMillis() + 120_000;
            while (first.isAlive()
                    && System.currentTimeMillis() < until
                    && !(Files.exists(lock) && InterruptionTest.names(out).size() >= 4)) {
                Thread.sleep(5);
            }
            assertTrue(first.isAlive(), "the first run ended too soon: " + Files.readString(dir.resolve("log")));
            // a job whose files the grading never writes
            second = run(err, "run", "samples/jobs/cut-plate.xml", "--out", out.toString());
            if (signal.equals("SIGKILL")) {
                first.destroyForcibly();
            } else {
                first.destroy();
            }
            assertTrue(first.waitFor(60, TimeUnit.SECONDS), "the first run ends on " + signal);
        } finally {
            first.destroyForcibly();
        }
        String e = err.toString();
        List<String> afterKill = InterruptionTest.names(out);
        assertAll(
                e,
                () -> assertEquals(1, second, "the second run is refused"),
                () -> assertTrue(e.contains("another Fresa run (process " + first.pid()), "names the first run"),
                () -> assertFalse(
                        afterKill.contains("program.ngc") || afterKill.contains("summary.json"),
                        "the refused job wrote nothing: " + afterKill),
                () -> assertEquals(List.of(), CompleteOutputs.incomplete(out), "final-named files are complete"),
                () -> assertTrue(
                        signal.equals("SIGKILL") || !afterKill.contains(FolderLock.FILE_NAME),
                        "SIGTERM removes the lock file: " + afterKill),
                () -> assertTrue(
                        signal.equals("SIGKILL")
                                || InterruptionTest.temporaries(out).isEmpty(),
                        "SIGTERM leaves no temporary file: " + afterKill));

        // the folder is free again: a SIGKILL's leftover lock file is taken over
        StringWriter err2 = new StringWriter();
        int third = run(err2, grade(out, "40-40"));
        assertAll(
                () -> assertEquals(0, third, err2.toString()),
                () -> assertFalse(Files.exists(lock), "the lock file goes with the run"),
                () -> assertTrue(Files.exists(out.resolve("grading.csv"))));
    }
}
