package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class GradeCommandTest {

    @TempDir
    Path dir;

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    private int run(String... args) {
        return FresaCommand.execute(new PrintWriter(out, true), new PrintWriter(err, true), args);
    }

    @Test
    void gradingTheSampleWritesTheFilesAndAJsonSummary() throws Exception {
        int rc = run(
                "grade",
                "samples/grading/sole-40.contour",
                "--out",
                dir.toString(),
                "--base-size",
                "40",
                "--sizes",
                "36-44",
                "--system",
                "br",
                "--json");
        assertAll(
                () -> assertEquals(0, rc, err.toString()),
                () -> assertTrue(out.toString().startsWith("{\"outline\":\"sole-40.contour\""), out.toString()),
                () -> assertTrue(out.toString().contains("\"base_length_mm\":270,\"base_width_mm\":90")),
                () -> assertTrue(Files.exists(dir.resolve("size-36.dxf"))),
                () -> assertTrue(Files.exists(dir.resolve("grading.png"))));
    }

    @Test
    void anUnknownShrinkageModeIsBadInputWithExitStatus2() {
        int rc = run(
                "grade",
                "samples/grading/sole-40.contour",
                "--out",
                dir.toString(),
                "--base-size",
                "40",
                "--sizes",
                "36-44",
                "--system",
                "br",
                "--shrinkage-mode",
                "both");
        assertEquals(2, rc);
        assertTrue(
                err.toString().contains("--shrinkage-mode")
                        && err.toString().contains("expected one of additive, multiplicative"),
                err.toString());
    }

    @Test
    void theSavedJobRunsTheSameTask() {
        int rc = run("run", "samples/jobs/grade-sole40.xml", "--out", dir.toString());
        assertEquals(0, rc, err.toString());
        assertTrue(Files.exists(dir.resolve("size-44.csv")));
    }
}
