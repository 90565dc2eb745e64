package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Tolerance;
import org.fresa.post.ExpectedMotions;
import org.fresa.post.NcPosts;
import org.fresa.post.Rs274;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.CorpusCheck;
import org.fresa.testing.InterpreterCheck;
import org.fresa.testing.TestInputs;
import org.fresa.toolpath.ToolpathPlanner;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** AP238 files in their integrated form (AIM) machined: toolpaths, programs, the interpreter. */
class Ap238ToolpathTest {

    static final Path AP238 = TestInputs.SHARED_CORPUS.resolve("stepnc/ap238");
    static final Path J6 = AP238.resolve("annexJ6-cc3-iso14649-11-example1-aim.stp");
    static final Path FDIS_EXAMPLE1 = TestInputs.SHARED_CORPUS.resolve("stepnc/fdis/iso14649-11-fdis-example1.p21");
    static final Path INCH = Path.of("src/test/resources/stepnc/aim-inch-hole-and-pocket.stp");

    private static List<String[]> rows(Path csv) throws Exception {
        List<String[]> out = new ArrayList<>();
        for (String line : Files.readAllLines(csv)) {
            out.add(line.split(",", -1));
        }
        return out;
    }

    /**
     * Annex J.6 is ISO 14649-11 example 1 written as AIM: its toolpath is the FDIS ARM file's, point
     * for point within 1e-6 mm, but for what the two files say differently: the drill's point (the
     * AIM gives a 120 deg point angle, the ARM a tool_top_angle of 59) moves the drill's three feed
     * points along the axis, and the feeds (the AIM writes 0.04 mm/s where the ARM has 0.04 m/s) are
     * a thousandth of the ARM's.
     */
    @Test
    @CorpusCheck
    void annexJ6IsMachinedAsTheArmFileOfTheSamePart(@TempDir Path dir) throws Exception {
        assumeTrue(Files.isRegularFile(J6) && Files.isRegularFile(FDIS_EXAMPLE1), TestInputs.sharedCorpusAbsent(AP238));
        TaskOutcome aim = ToolpathService.run(J6, "linuxcnc", new OutputFolder(dir.resolve("aim")), ProgressMonitor.NONE);
        TaskOutcome arm = ToolpathService.run(FDIS_EXAMPLE1, "linuxcnc", new OutputFolder(dir.resolve("arm")),
                ProgressMonitor.NONE);
        assertEquals(0, aim.exitStatus(), aim.problems().toString());
        assertEquals(0, arm.exitStatus(), arm.problems().toString());
        List<String[]> a = rows(dir.resolve("aim/toolpath.csv"));
        List<String[]> r = rows(dir.resolve("arm/toolpath.csv"));
        assertEquals(r.size(), a.size());
        int drillPoints = 0;
        int slowFeeds = 0;
        for (int i = 1; i < r.size(); i++) {
            String[] x = r.get(i);
            String[] y = a.get(i);
            assertEquals(x[1] + " " + x[2], y[1] + " " + y[2], "row " + i);
            boolean drillFeed = x[1].equals("WS DRILL HOLE1") && x[2].equals("feed");
            for (int k = 3; k < 9; k++) {
                double d = Math.abs(Double.parseDouble(x[k]) - Double.parseDouble(y[k]));
                if (drillFeed && k == 5 && d > 1e-6) {
                    drillPoints++;
                    // the tip of a 120 deg point against the ARM's reading of its 59
                    assertEquals(10 * (Math.tan(Math.toRadians(59)) - Math.tan(Math.toRadians(30))), d, 1e-9);
                } else {
                    assertTrue(d <= 1e-6, "row " + i + " column " + k + ": " + x[k] + " vs " + y[k]);
                }
            }
            double fx = Double.parseDouble(x[9]);
            double fy = Double.parseDouble(y[9]);
            if (Math.abs(fx - fy) > 1e-6) {
                slowFeeds++;
                assertEquals(fx / 1000, fy, 1e-9, "row " + i);
            }
        }
        assertEquals(3, drillPoints);
        assertTrue(slowFeeds > 0);
        StepNcProgram p = StepNcReader.read(J6);
        assertTrue(p.warnings().stream().anyMatch(w -> w.contains("#4800 POCKET 'POCKET1'") && w.contains("reversed")),
                p.warnings().toString());
        assertFalse(StepNcService.prose(p).contains("ISO 14649 units"));
    }

    @Test
    @CorpusCheck
    void annexJ6sProgramIsAcceptedByLinuxCnc(@TempDir Path dir) throws Exception {
        assumeTrue(Files.isRegularFile(J6), TestInputs.sharedCorpusAbsent(AP238));
        assumeTrue(Rs274.available(), Rs274.whyNot());
        interpreted(J6, dir);
    }

    @Test
    @InterpreterCheck
    void anInchFilesProgramIsAcceptedByLinuxCncInMillimetres(@TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        interpreted(INCH, dir);
        // the hole at (1, 2) inch, 0.5 inch deep, drilled at 5 inch/minute
        String[] drill = rows(dir.resolve("toolpath.csv")).stream()
                .filter(x -> x[1].equals("WS DRILL HOLE1") && x[2].equals("feed")).findFirst().orElseThrow();
        double[] expected = {25.4, 50.8, -12.7, 0, 0, 1, 127};
        for (int k = 0; k < expected.length; k++) {
            assertEquals(expected[k], Double.parseDouble(drill[k + 3]), 1e-9, String.join(",", drill));
        }
    }

    private static void interpreted(Path input, Path dir) throws Exception {
        TaskOutcome o = ToolpathService.run(input, "linuxcnc", new OutputFolder(dir), ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        Rs274.Result r = Rs274.run(dir.resolve("program.ngc"), 18);
        assertEquals(0, r.exitStatus(), r.stderr());
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(StepNcReader.read(input), Tolerance.DEFAULT);
        List<Rs274.Canon> expected = ExpectedMotions.of(plan.toolpath(), false, NcPosts.CHORD_TOLERANCE_MM);
        assertNull(ExpectedMotions.firstDifference(expected, r.motions(), 0.0011));
    }
}
