package org.fresa.robustness;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.fresa.app.cli.FresaCommand;
import org.fresa.io.AtomicFiles;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code fresa grade} over 67 sizes in its own JVM, killed while it writes. SIGTERM:
 * the shutdown hook removes the temporary file being written, so the folder holds only complete
 * files. SIGKILL: nothing can run, so at most the one hidden temporary file is left, never a
 * truncated file under a final name; the next run into the folder removes such a leftover once
 * it is older than {@link AtomicFiles#STALE}.
 */
class InterruptionTest {

    @TempDir
    Path dir;

    static List<String> names(Path d) throws Exception {
        try (Stream<Path> s = Files.list(d)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    static List<String> temporaries(Path d) throws Exception {
        return names(d).stream()
                .filter(n -> n.startsWith(AtomicFiles.TEMP_PREFIX))
                .toList();
    }

    static String[] grade(Path out, String sizes) {
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

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"SIGKILL", "SIGTERM"})
    void aKilledRunLeavesNoTruncatedFileUnderAFinalName(String signal) throws Exception {
        Path out = Files.createDirectories(dir.resolve("out"));
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new java.util.ArrayList<>(List.of(
                java,
                "-Xmx256m",
                "-Djava.awt.headless=true",
                "-cp",
                System.getProperty("java.class.path"),
                "org.fresa.app.Main"));
        cmd.addAll(List.of(grade(out, "17-50")));
        Process p = new ProcessBuilder(cmd)
                .redirectErrorStream(true)
                .redirectOutput(dir.resolve("log").toFile())
                .start();
        try {
            // kill while it writes: after a few files, preferably while a temporary file exists
            long until = System.currentTimeMillis() + 90_000;
            while (p.isAlive()
                    && System.currentTimeMillis() < until
                    && !(names(out).size() >= 6 && !temporaries(out).isEmpty())
                    && names(out).size() < 20) {
                Thread.sleep(1);
            }
            assertTrue(p.isAlive(), "the run ended before it could be killed: " + Files.readString(dir.resolve("log")));
            if (signal.equals("SIGKILL")) {
                p.destroyForcibly();
            } else {
                p.destroy();
            }
            assertTrue(p.waitFor(30, TimeUnit.SECONDS), "the run ends on " + signal);
        } finally {
            p.destroyForcibly();
        }
        List<String> left = names(out);
        List<String> temps = temporaries(out);
        assertAll(
                signal + " left " + left,
                () -> assertFalse(left.contains("grading.csv"), "killed before the end"),
                () -> assertEquals(List.of(), CompleteOutputs.incomplete(out), "final-named files are complete"),
                () -> assertTrue(
                        signal.equals("SIGKILL") ? temps.size() <= 1 : temps.isEmpty(), "temporary files: " + temps));

        // the next run into the folder: a leftover older than STALE is removed, the run completes
        for (String t : temps) {
            Files.setLastModifiedTime(
                    out.resolve(t),
                    FileTime.from(Instant.now().minus(AtomicFiles.STALE).minusSeconds(1)));
        }
        StringWriter err = new StringWriter();
        int status = FresaCommand.execute(
                new PrintWriter(new StringWriter(), true), new PrintWriter(err, true), grade(out, "40-40"));
        assertAll(
                () -> assertEquals(0, status, err.toString()),
                () -> assertEquals(List.of(), temporaries(out)),
                () -> assertTrue(names(out).contains("grading.csv")),
                () -> assertEquals(List.of(), CompleteOutputs.incomplete(out)));
    }
}
