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
import org.fresa.io.OutputFolder;
import org.fresa.post.ExpectedMotions;
import org.fresa.post.NcPosts;
import org.fresa.post.Rs274;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.CorpusCheck;
import org.fresa.testing.InterpreterCheck;
import org.fresa.testing.TestInputs;
import org.fresa.toolpath.ToolpathCsv;
import org.fresa.toolpath.ToolpathPlanner;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

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
    void annexJ6IsMachinedAsTheArmFileOfTheSamePart() throws Exception {
        assumeTrue(Files.isRegularFile(J6) && Files.isRegularFile(FDIS_EXAMPLE1), TestInputs.sharedCorpusAbsent(AP238));
        ToolpathPlanner.Plan aim = ToolpathPlanner.plan(StepNcReader.read(J6), Tolerance.DEFAULT);
        ToolpathPlanner.Plan arm = ToolpathPlanner.plan(StepNcReader.read(FDIS_EXAMPLE1), Tolerance.DEFAULT);
        assertEquals(5, aim.workingsteps());
        // the same workingsteps planned (and refused, if the planner refuses any) from both forms
        assertEquals(
                arm.steps().stream().map(ToolpathPlanner.PlannedStep::label).toList(),
                aim.steps().stream().map(ToolpathPlanner.PlannedStep::label).toList());
        assertTrue(aim.planned() > 0, aim.problems().toString());
        List<ToolpathCsv.Row> a = ToolpathCsv.rows(aim.toolpath(), NcPosts.CHORD_TOLERANCE_MM);
        List<ToolpathCsv.Row> r = ToolpathCsv.rows(arm.toolpath(), NcPosts.CHORD_TOLERANCE_MM);
        assertEquals(r.size(), a.size());
        int drillPoints = 0;
        double deepestDz = 0;
        int slowFeeds = 0;
        for (int i = 0; i < r.size(); i++) {
            ToolpathCsv.Row x = r.get(i);
            ToolpathCsv.Row y = a.get(i);
            assertEquals(x.workingstep() + " " + x.move(), y.workingstep() + " " + y.move(), "row " + i);
            assertTrue(x.toolAxis().distance(y.toolAxis()) <= 1e-6, "row " + i);
            boolean drillFeed =
                    x.workingstep().equals("WS DRILL HOLE1") && x.move().equals("feed");
            double dz = Math.abs(x.point().z() - y.point().z());
            if (drillFeed && dz > 1e-6) {
                drillPoints++;
                // the AIM gives cutting_depth 30: the tip goes to it; the ARM gives none: its through
                // hole is drilled 30 deep plus its point (its 59 read as the half angle) and the 1 mm breakthrough
                // (the pecks before it are spread over the two depths)
                deepestDz = Math.max(deepestDz, dz);
                assertTrue(Math.hypot(
                                x.point().x() - y.point().x(),
                                x.point().y() - y.point().y())
                        <= 1e-6);
            } else if (x.workingstep().equals("WS REAM HOLE1") && x.move().equals("feed") && dz > 1e-6) {
                // the AIM's reamer stops at its cutting_depth 30, the ARM's passes the exit by the breakthrough
                assertEquals(1, dz, 1e-9, "row " + i);
                assertTrue(Math.hypot(
                                x.point().x() - y.point().x(),
                                x.point().y() - y.point().y())
                        <= 1e-6);
            } else {
                assertTrue(x.point().distance(y.point()) <= 1e-6, "row " + i + ": " + x + " vs " + y);
            }
            if (Math.abs(x.feedMmPerMin() - y.feedMmPerMin()) > 1e-6) {
                slowFeeds++;
                assertEquals(x.feedMmPerMin() / 1000, y.feedMmPerMin(), 1e-9, "row " + i);
            }
        }
        if (aim.steps().stream().anyMatch(s -> s.label().equals("WS DRILL HOLE1"))) {
            assertEquals(3, drillPoints);
            assertEquals(10 * Math.tan(Math.toRadians(59)) + 1, deepestDz, 1e-9);
        }
        assertTrue(slowFeeds > 0);
        StepNcProgram p = StepNcReader.read(J6);
        assertTrue(
                p.warnings().stream().anyMatch(w -> w.contains("#4800 POCKET 'POCKET1'") && w.contains("reversed")),
                p.warnings().toString());
        assertFalse(StepNcService.prose(p).contains("ISO 14649 units"));
    }

    @Test
    @CorpusCheck
    void annexJ6sProgramIsAcceptedByLinuxCnc(@TempDir Path dir) throws Exception {
        assumeTrue(Files.isRegularFile(J6), TestInputs.sharedCorpusAbsent(AP238));
        assumeTrue(Rs274.available(), Rs274.whyNot());
        // the pockets' MILLING_TECHNOLOGY gives no feed: refused (no feed is guessed), the rest written;
        // the drill and the reamer stop at cutting_depth 30, short of a breakthrough, with a warning
        List<String> problems = interpreted(J6, dir, 1);
        assertEquals(
                2,
                problems.stream().filter(x -> x.contains("no feed is guessed")).count(),
                problems.toString());
        assertTrue(
                problems.stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS DRILL HOLE1': cutting_depth 30 mm")
                                && x.contains("less than the breakthrough 1 mm")),
                problems.toString());
    }

    @Test
    @InterpreterCheck
    void anInchFilesProgramIsAcceptedByLinuxCncInMillimetres(@TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        interpreted(INCH, dir);
        // the hole at (1, 2) inch, 0.5 inch deep, drilled at 5 inch/minute
        String[] drill = rows(dir.resolve("toolpath.csv")).stream()
                .filter(x -> x[1].equals("WS DRILL HOLE1") && x[2].equals("feed"))
                .findFirst()
                .orElseThrow();
        double[] expected = {25.4, 50.8, -12.7, 0, 0, 1, 127};
        for (int k = 0; k < expected.length; k++) {
            assertEquals(expected[k], Double.parseDouble(drill[k + 3]), 1e-9, String.join(",", drill));
        }
    }

    private static void interpreted(Path input, Path dir) throws Exception {
        interpreted(input, dir, 0);
    }

    /** Runs the toolpath task, expects its exit status, interprets its program; returns its problems. */
    private static List<String> interpreted(Path input, Path dir, int exitStatus) throws Exception {
        TaskOutcome o = ToolpathService.run(
                input, org.fresa.post.MillingPost.LINUXCNC, new OutputFolder(dir), ProgressMonitor.NONE);
        assertEquals(exitStatus, o.exitStatus(), o.problems().toString());
        Rs274.Result r = Rs274.run(dir.resolve("program.ngc"), 18);
        assertEquals(0, r.exitStatus(), r.stderr());
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(StepNcReader.read(input), Tolerance.DEFAULT);
        List<Rs274.Canon> expected = ExpectedMotions.of(plan.toolpath(), false, NcPosts.CHORD_TOLERANCE_MM);
        assertNull(ExpectedMotions.firstDifference(expected, r.motions(), 0.0011));
        return o.problems();
    }

    static final Path J4 = AP238.resolve("annexJ4-cc1-simple-block.stp");
    static final Path CC1 = Path.of("src/test/resources/stepnc/aim-cc1-toolpaths.stp");

    @Test
    @InterpreterCheck
    void explicitToolpathsAreFollowedWithTheirArcsAndAcceptedByLinuxCnc(@TempDir Path dir) throws Exception {
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(StepNcReader.read(CC1), Tolerance.DEFAULT);
        assertEquals(1, plan.planned(), plan.problems().toString());
        List<org.fresa.model.Move> moves = plan.toolpath().sections().get(0).moves();
        List<org.fresa.model.Move.Circular> arcs = moves.stream()
                .filter(m -> m instanceof org.fresa.model.Move.Circular)
                .map(m -> (org.fresa.model.Move.Circular) m)
                .toList();
        assertEquals(2, arcs.size());
        assertTrue(arcs.get(0).ccw());
        assertFalse(arcs.get(1).ccw());
        assertEquals(
                3,
                moves.stream()
                        .filter(m -> m instanceof org.fresa.model.Move.Rapid)
                        .count());
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
        TaskOutcome o = ToolpathService.run(
                J4, org.fresa.post.MillingPost.LINUXCNC, new OutputFolder(dir), ProgressMonitor.NONE);
        assertEquals(1, o.exitStatus());
        assertTrue(o.problems().get(0).contains("spindle"), o.problems().toString());
        // no program: only summary.json, with the reasons
        assertTrue(
                o.files().stream().allMatch(f -> f.getFileName().toString().equals("summary.json")),
                o.files().toString());
        assertFalse(Files.exists(dir.resolve("program.ngc")));
    }

    /**
     * Annex J.4 with a spindle speed (the annex gives 0 rev/min): one section whose every point
     * lies on the file's curves within 1e-6 mm (an arc's radius is its trimming points' distance
     * from its centre), arcs kept as arcs; its straight-down descent onto the contour refused by the program check.
     */
    @Test
    @CorpusCheck
    void annexJ4WithASpindleSpeedIsFollowedOnItsCurvesAndItsPlungeRefused(@TempDir Path dir) throws Exception {
        assumeTrue(Files.isRegularFile(J4), TestInputs.sharedCorpusAbsent(AP238));
        String text = Files.readString(J4)
                .replace("NUMERIC_MEASURE(0.),\n#483)", "NUMERIC_MEASURE(1000.),\n#483)")
                .replace("NUMERIC_MEASURE(0.),\r\n#483)", "NUMERIC_MEASURE(1000.),\r\n#483)");
        Path input = dir.resolve("j4-spindle.stp");
        Files.writeString(input, text);
        StepNcProgram p = StepNcReader.read(input);
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(p, Tolerance.DEFAULT);
        assertEquals(1, plan.planned(), plan.problems().toString());
        List<org.fresa.stepnc.Profile.Segment> curves = new ArrayList<>();
        p.workingsteps().get(0).operation().toolpaths().forEach(t -> curves.addAll(t.curve()));
        long arcs = curves.stream()
                .filter(c -> c instanceof org.fresa.stepnc.Profile.Arc)
                .count();
        assertEquals(
                arcs,
                plan.toolpath().sections().get(0).moves().stream()
                        .filter(m -> m instanceof org.fresa.model.Move.Circular)
                        .count());
        Path out = dir.resolve("out");
        TaskOutcome o = ToolpathService.run(
                input, org.fresa.post.MillingPost.LINUXCNC, new OutputFolder(out), ProgressMonitor.NONE);
        // the file's own path goes straight down 3 mm onto its contour; the file states no stock (no
        // block, no face), so the descent counts as into material and the program is refused, the
        // toolpath written
        assertEquals(1, o.exitStatus(), o.problems().toString());
        assertTrue(
                o.problems().stream()
                        .anyMatch(x -> x.startsWith("program.ngc not written")
                                && x.contains("line 12")
                                && x.contains("entry angle")
                                && x.contains("(a plunge)")),
                o.problems().toString());
        assertFalse(Files.exists(out.resolve("program.ngc")));
        List<String[]> rows = rows(out.resolve("toolpath.csv"));
        for (String[] r : rows.subList(1, rows.size())) {
            org.fresa.geom.Vec3 q = new org.fresa.geom.Vec3(
                    Double.parseDouble(r[3]), Double.parseDouble(r[4]), Double.parseDouble(r[5]));
            double best = Double.POSITIVE_INFINITY;
            for (org.fresa.stepnc.Profile.Segment c : curves) {
                best = Math.min(best, distance(q, c));
            }
            assertTrue(best <= 1e-6, "row " + r[0] + " is " + best + " mm from the file's curves");
        }
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
            double r0 = Math.hypot(
                    a.start().x() - a.center().x(), a.start().y() - a.center().y());
            double r1 = Math.hypot(
                    a.end().x() - a.center().x(), a.end().y() - a.center().y());
            double r = Math.hypot(dx, dy);
            return r >= Math.min(r0, r1) - 1e-9 && r <= Math.max(r0, r1) + 1e-9
                    ? 0
                    : Math.min(Math.abs(r - r0), Math.abs(r - r1));
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
                .replace(
                        "#420=DRILLING_OPERATION('DRILL HOLE1','drilling','','');",
                        "#420=FACING_TURNING_OPERATION('FACE','roughing','','');")
                .replace(
                        "#520=BOTTOM_AND_SIDE_MILLING_OPERATION('ROUGH POCKET1','roughing','','');",
                        "#520=CONTOURING_TURNING_OPERATION('CONTOUR','roughing','','');");
        Path input = dir.resolve("turning.stp");
        Files.writeString(input, text);
        TaskOutcome o = ToolpathService.run(
                input, org.fresa.post.MillingPost.LINUXCNC, new OutputFolder(dir.resolve("out")), ProgressMonitor.NONE);
        assertEquals(1, o.exitStatus());
        assertEquals(
                2,
                o.problems().stream()
                        .filter(x -> x.contains("turning is not supported"))
                        .count(),
                o.problems().toString());
        // no program: only summary.json, with the reasons
        assertTrue(
                o.files().stream().allMatch(f -> f.getFileName().toString().equals("summary.json")),
                o.files().toString());
        assertFalse(Files.exists(dir.resolve("out/program.ngc")));
    }

    /**
     * A pocket's boss in the AIM is its 'uncut volume' (ISO 10303-113 pocket WR16); one the binder
     * cannot read (here without a description, boss WR1, nor a profile) leaves the pocket refused,
     * not milled through the boss.
     */
    @Test
    void aPocketAroundAnUncutVolumeIsRefusedNotMilledThroughIt() throws Exception {
        String text = Files.readString(INCH)
                .replace(
                        "ENDSEC;\nEND-ISO-10303-21;",
                        "#580=COMPOSITE_SHAPE_ASPECT('uncut volume','',#541,.F.);\n"
                                + "#581=FEATURE_COMPONENT_RELATIONSHIP('','boss usage',#580,#582);\n"
                                + "#582=(BOSS() CHARACTERIZED_OBJECT('','') FEATURE_DEFINITION() INSTANCED_FEATURE()"
                                + " SHAPE_ASPECT('BOSS1','',#113,.T.));\n"
                                + "ENDSEC;\nEND-ISO-10303-21;");
        assertTrue(text.contains("#582="));
        StepNcProgram p = StepNcReader.read(new java.io.StringReader(text), "boss.stp");
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(p, Tolerance.DEFAULT);
        assertEquals(1, plan.planned(), plan.problems().toString());
        String why = plan.refusals().get(p.workingsteps().get(1).instanceId());
        assertTrue(
                why != null
                        && why.contains("around an 'uncut volume' the AIM binder cannot read")
                        && why.contains("BOSS #582 ('BOSS1' described ''")
                        && why.contains("cut away"),
                String.valueOf(why));
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

    // ---- the AIM parts with their ARM twins' block ----

    static final Path PARTS = Path.of("src/test/resources/stepnc");

    /** The toolpath task's program (it must write one) and its toolpath.csv rows. */
    private static List<String> program(Path input, Path dir) throws Exception {
        TaskOutcome o = ToolpathService.run(
                input, org.fresa.post.MillingPost.LINUXCNC, new OutputFolder(dir), ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        return Files.readAllLines(dir.resolve("program.ngc"));
    }

    /**
     * The AIM slot parts carry their ARM twins' block as annex J.6 writes a bounding geometry (a
     * BLOCK_SHAPE_REPRESENTATION placed at its centre): the descents beyond the open ends are in
     * the air as in the ARM parts, and both forms give the same program, line for line but for its
     * name (the part's file name), and the same toolpath.csv within 1e-6 mm.
     */
    @ParameterizedTest
    @CsvSource({"aim-slots.stp, slots-profiles.stp", "aim-slots-general.stp, slots-general.stp"})
    void theAimSlotPartsGetTheirArmTwinsProgram(String aimPart, String armPart, @TempDir Path dir) throws Exception {
        List<String> aim = program(PARTS.resolve(aimPart), dir.resolve("aim"));
        List<String> arm = program(PARTS.resolve(armPart), dir.resolve("arm"));
        assertEquals("(" + aimPart.replace(".stp", "") + ")", aim.get(1));
        assertEquals("(" + armPart.replace(".stp", "") + ")", arm.get(1));
        assertTrue(aim.size() > 300, "lines " + aim.size());
        assertEquals(arm.subList(2, arm.size()), aim.subList(2, aim.size()));
        List<String[]> a = rows(dir.resolve("aim/toolpath.csv"));
        List<String[]> r = rows(dir.resolve("arm/toolpath.csv"));
        assertEquals(r.size(), a.size());
        assertEquals(String.join(",", r.get(0)), String.join(",", a.get(0)));
        for (int i = 1; i < r.size(); i++) {
            String[] x = r.get(i);
            String[] y = a.get(i);
            assertEquals(x.length, y.length, "row " + i);
            assertEquals(List.of(x[0], x[1], x[2]), List.of(y[0], y[1], y[2]), "row " + i);
            for (int k = 3; k < x.length; k++) {
                assertEquals(
                        Double.parseDouble(x[k]),
                        Double.parseDouble(y[k]),
                        1e-6,
                        "row " + i + ": " + String.join(",", x) + " vs " + String.join(",", y));
            }
        }
    }

    /**
     * aim-bosses.stp is the ARM part's pocket with bosses alone: its program is the ARM program's
     * section of that pocket, the last, but for the tool's number (the first tool of the AIM
     * part, the second of the ARM part).
     */
    @Test
    void theAimPocketWithBossesGetsTheArmProgramsSectionOfIt(@TempDir Path dir) throws Exception {
        List<String> aim = program(PARTS.resolve("aim-bosses.stp"), dir.resolve("aim"));
        List<String> arm = program(PARTS.resolve("steps-outside-profiles.stp"), dir.resolve("arm"));
        String head = "(WS POCKET WITH BOSSES tool ";
        int from = 0;
        while (!arm.get(from).startsWith(head)) {
            from++;
        }
        List<String> section = arm.subList(from, arm.size()).stream()
                .map(x -> switch (x) {
                    case "(WS POCKET WITH BOSSES tool 2 D6.000)" -> "(WS POCKET WITH BOSSES tool 1 D6.000)";
                    case "T2 M6" -> "T1 M6";
                    case "G43 H2" -> "G43 H1";
                    default -> x;
                })
                .toList();
        assertEquals("(WS POCKET WITH BOSSES tool 1 D6.000)", aim.get(3));
        assertEquals(arm.get(2), aim.get(2));
        assertTrue(section.size() > 100, "lines " + section.size());
        assertEquals(section, aim.subList(3, aim.size()));
    }

    @ParameterizedTest
    @ValueSource(strings = {"aim-slots.stp", "aim-slots-general.stp", "aim-bosses.stp"})
    @InterpreterCheck
    void theAimPartsWithTheirBlockAreAcceptedByLinuxCnc(String part, @TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        interpreted(PARTS.resolve(part), dir);
    }

    /**
     * Without the block (no bounding geometry, or the block behind a rawpiece as in annex J.6) no
     * stock is guessed: the T-slot mill's descent past the open end counts as into material and
     * the program is refused, the toolpath written.
     */
    @ParameterizedTest
    @ValueSource(
            strings = {
                "",
                "#468=MAKE_FROM_USAGE_OPTION('','','',#9000,#469,0,'',$);\n"
                        + "#9000=PRODUCT_DEFINITION('STOCK','',$,#25);\n"
                        + "#9001=MAKE_FROM_USAGE_OPTION('','','',#28,#9000,0,'',$);\n"
            })
    void anAimSlotPartWithoutItsOwnBlockGetsNoProgram(String instead, @TempDir Path dir) throws Exception {
        String from = "#468=MAKE_FROM_USAGE_OPTION('','','',#28,#469,0,'',$);\n";
        String text = Files.readString(PARTS.resolve("aim-slots.stp"));
        assertTrue(text.contains(from));
        Path input = dir.resolve("no-block.stp");
        Files.writeString(input, text.replace(from, instead));
        assertTrue(StepNcReader.read(input).workpieces().get(0).block().isEmpty());
        TaskOutcome o = ToolpathService.run(
                input, org.fresa.post.MillingPost.LINUXCNC, new OutputFolder(dir.resolve("out")), ProgressMonitor.NONE);
        assertEquals(1, o.exitStatus(), o.problems().toString());
        assertTrue(
                o.problems().stream()
                        .anyMatch(x -> x.startsWith("program.ngc not written")
                                && x.contains("entry angle")
                                && x.contains("(a plunge)")),
                o.problems().toString());
        assertFalse(Files.exists(dir.resolve("out/program.ngc")));
        assertTrue(Files.exists(dir.resolve("out/toolpath.csv")));
    }

    @Test
    void anAimPartsBlockIsShownAsAnArmPartsIs() throws Exception {
        StepNcProgram aim = StepNcReader.read(PARTS.resolve("aim-slots.stp"));
        StepNcProgram arm = StepNcReader.read(PARTS.resolve("slots-profiles.stp"));
        String line = "workpiece 'BLOCK 120 X 150 X 30', block 120 x 150 x 30 mm at (0, 0, -30)\n";
        assertTrue(StepNcService.prose(arm).contains(line), StepNcService.prose(arm));
        assertTrue(StepNcService.prose(aim).contains(line), StepNcService.prose(aim));
        // --json: the same workpiece, block and corner
        String json = org.fresa.io.Json.write(StepNcService.summary(aim).get("workpieces"));
        assertEquals("[{\"id\":\"BLOCK 120 X 150 X 30\",\"block\":[120,150,30],\"block_placement\":[0,0,-30]}]", json);
        assertEquals(org.fresa.io.Json.write(StepNcService.summary(arm).get("workpieces")), json);
    }
}
