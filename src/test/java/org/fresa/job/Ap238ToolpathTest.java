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

    static final Path J4 = AP238.resolve("annexJ4-cc1-simple-block.stp");
    static final Path CC1 = Path.of("src/test/resources/stepnc/aim-cc1-toolpaths.stp");

    @Test
    @InterpreterCheck
    void explicitToolpathsAreFollowedWithTheirArcsAndAcceptedByLinuxCnc(@TempDir Path dir) throws Exception {
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(StepNcReader.read(CC1), Tolerance.DEFAULT);
        assertEquals(1, plan.planned(), plan.problems().toString());
        List<org.fresa.model.Move> moves = plan.toolpath().sections().get(0).moves();
        List<org.fresa.model.Move.Circular> arcs = moves.stream().filter(m -> m instanceof org.fresa.model.Move.Circular)
                .map(m -> (org.fresa.model.Move.Circular) m).toList();
        assertEquals(2, arcs.size());
        assertTrue(arcs.get(0).ccw());
        assertFalse(arcs.get(1).ccw());
        assertEquals(3, moves.stream().filter(m -> m instanceof org.fresa.model.Move.Rapid).count());
        assumeTrue(Rs274.available(), Rs274.whyNot());
        interpreted(CC1, dir);
    }

    @Test
    @CorpusCheck
    void annexJ4sToolpathsAreReadAndItsSpindleAtZeroIsRefusedWithNoProgram(@TempDir Path dir) throws Exception {
        assumeTrue(Files.isRegularFile(J4), TestInputs.sharedCorpusAbsent(AP238));
        StepNcProgram p = StepNcReader.read(J4);
        assertEquals(1, p.workingsteps().size());
        assertEquals(12, p.workingsteps().get(0).operation().toolpaths().size());
        TaskOutcome o = ToolpathService.run(J4, "linuxcnc", new OutputFolder(dir), ProgressMonitor.NONE);
        assertEquals(1, o.exitStatus());
        assertTrue(o.problems().get(0).contains("with the spindle at 0 rpm"), o.problems().toString());
        assertTrue(o.files().isEmpty());
        assertFalse(Files.exists(dir.resolve("program.ngc")));
    }

    /**
     * Annex J.4 with a spindle speed (the annex gives 0 rev/min): one section whose every point
     * lies on the file's curves within 1e-6 mm (an arc's radius is its trimming points' distance
     * from its centre), arcs kept as arcs, accepted by LinuxCNC.
     */
    @Test
    @CorpusCheck
    void annexJ4WithASpindleSpeedIsFollowedOnItsCurves(@TempDir Path dir) throws Exception {
        assumeTrue(Files.isRegularFile(J4), TestInputs.sharedCorpusAbsent(AP238));
        String text = Files.readString(J4).replace("NUMERIC_MEASURE(0.),\n#483)", "NUMERIC_MEASURE(1000.),\n#483)")
                .replace("NUMERIC_MEASURE(0.),\r\n#483)", "NUMERIC_MEASURE(1000.),\r\n#483)");
        Path input = dir.resolve("j4-spindle.stp");
        Files.writeString(input, text);
        StepNcProgram p = StepNcReader.read(input);
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(p, Tolerance.DEFAULT);
        assertEquals(1, plan.planned(), plan.problems().toString());
        List<org.fresa.stepnc.Profile.Segment> curves = new ArrayList<>();
        p.workingsteps().get(0).operation().toolpaths().forEach(t -> curves.addAll(t.curve()));
        long arcs = curves.stream().filter(c -> c instanceof org.fresa.stepnc.Profile.Arc).count();
        assertEquals(arcs, plan.toolpath().sections().get(0).moves().stream()
                .filter(m -> m instanceof org.fresa.model.Move.Circular).count());
        Path out = dir.resolve("out");
        TaskOutcome o = ToolpathService.run(input, "linuxcnc", new OutputFolder(out), ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        List<String[]> rows = rows(out.resolve("toolpath.csv"));
        for (String[] r : rows.subList(1, rows.size())) {
            org.fresa.geom.Vec3 q = new org.fresa.geom.Vec3(Double.parseDouble(r[3]), Double.parseDouble(r[4]),
                    Double.parseDouble(r[5]));
            double best = Double.POSITIVE_INFINITY;
            for (org.fresa.stepnc.Profile.Segment c : curves) {
                best = Math.min(best, distance(q, c));
            }
            assertTrue(best <= 1e-6, "row " + r[0] + " is " + best + " mm from the file's curves");
        }
        assumeTrue(Rs274.available(), Rs274.whyNot());
        Rs274.Result r = Rs274.run(out.resolve("program.ngc"), 18);
        assertEquals(0, r.exitStatus(), r.stderr());
    }

    private static double distance(org.fresa.geom.Vec3 q, org.fresa.stepnc.Profile.Segment c) {
        if (c instanceof org.fresa.stepnc.Profile.Arc a) {
            if (Math.abs(q.z() - a.center().z()) > 1e-6) {
                return Double.POSITIVE_INFINITY;
            }
            // master_representation .CARTESIAN.: the trimming points, not the circle's written radius
            // (rounded to 0.1 um in the annex), say where the arc runs
            double dx = q.x() - a.center().x();
            double dy = q.y() - a.center().y();
            double r0 = Math.hypot(a.start().x() - a.center().x(), a.start().y() - a.center().y());
            double r1 = Math.hypot(a.end().x() - a.center().x(), a.end().y() - a.center().y());
            double r = Math.hypot(dx, dy);
            return r >= Math.min(r0, r1) - 1e-9 && r <= Math.max(r0, r1) + 1e-9 ? 0 : Math.min(Math.abs(r - r0),
                    Math.abs(r - r1));
        }
        org.fresa.geom.Vec3 d = c.end().minus(c.start());
        double len2 = d.dot(d);
        double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, q.minus(c.start()).dot(d) / len2));
        return q.distance(c.start().plus(d.times(t)));
    }

    @Test
    @InterpreterCheck
    void squareUSlotsAreAcceptedByLinuxCnc(@TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        interpreted(Path.of("src/test/resources/stepnc/slots-square-u.stp"), dir);
    }

    @Test
    void turningIsRefusedByNameWithExitOne(@TempDir Path dir) throws Exception {
        String text = Files.readString(INCH)
                .replace("#420=DRILLING_OPERATION('DRILL HOLE1','drilling','','');",
                        "#420=FACING_TURNING_OPERATION('FACE','roughing','','');")
                .replace("#520=BOTTOM_AND_SIDE_MILLING_OPERATION('ROUGH POCKET1','roughing','','');",
                        "#520=CONTOURING_TURNING_OPERATION('CONTOUR','roughing','','');");
        Path input = dir.resolve("turning.stp");
        Files.writeString(input, text);
        TaskOutcome o = ToolpathService.run(input, "linuxcnc", new OutputFolder(dir.resolve("out")),
                ProgressMonitor.NONE);
        assertEquals(1, o.exitStatus());
        assertEquals(2, o.problems().stream().filter(x -> x.contains("turning is not supported")).count(),
                o.problems().toString());
        assertTrue(o.files().isEmpty());
        assertFalse(Files.exists(dir.resolve("out/program.ngc")));
    }

    @Test
    void anInchFileIsDescribedWithItsOwnUnitsNeverAsIso14649Units() throws Exception {
        StepNcProgram p = StepNcReader.read(INCH);
        String prose = StepNcService.prose(p);
        assertFalse(prose.contains("ISO 14649 units"), prose);
        assertTrue(prose.contains("AP238 AIM"), prose);
        assertTrue(prose.contains("lengths in INCH (25.4 mm), converted to mm"), prose);
        assertEquals("AIM", StepNcService.summary(p).get("form"));
    }
}
