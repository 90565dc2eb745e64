package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A stepover asked below half the tool's diameter is planned at half, and the planner is told:
 * the same program as --cut 0.5, and a warning naming both.
 */
class LeastStepoverTest {

    @TempDir
    Path dir;

    private String program(String cut, List<String> err) throws Exception {
        Path out = dir.resolve("cut" + cut + ".ngc");
        FresaCommandTest.Run r = FresaCommandTest.fresa(
                "pocket",
                "samples/pocket/cavity01.dad",
                "--tool-diameter",
                "10",
                "--cut",
                cut,
                "--out",
                out.toString());
        assertEquals(0, r.status(), r.out() + r.err());
        err.add(r.err());
        // the first lines name the file
        return String.join(
                "\n", Files.readAllLines(out).subList(3, Files.readAllLines(out).size()));
    }

    @Test
    void aStepoverBelowHalfIsPlannedAtHalfAndSaidSo() throws Exception {
        List<String> err = new java.util.ArrayList<>();
        assertEquals(program("0.5", err), program("0.3", err));
        assertFalse(err.get(0).contains("is planned as"), err.get(0));
        assertTrue(
                err.get(1).contains("--cut 0.3 is planned as 0.5: the passes step at least half the tool's diameter"),
                err.get(1));
    }
}
