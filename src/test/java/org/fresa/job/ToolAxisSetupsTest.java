package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fresa.check.Failure;
import org.fresa.check.NcDialect;
import org.fresa.check.ProgramCheck;
import org.fresa.geom.Vec3;
import org.fresa.io.OutputFolder;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.fresa.post.MillingPost;
import org.fresa.post.NcPosts;
import org.fresa.post.Rs274;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.InterpreterCheck;
import org.fresa.testing.TestInputs;
import org.fresa.toolpath.PlanningChoices;
import org.fresa.toolpath.ToolpathPlanner;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Workingsteps on other sides of the part than its top: a 3-axis program holds only those along
 * the machine's +Z (the others are refused with their axis and written nowhere), the robot keeps
 * every side, and the floor is measured along each section's own tool axis.
 */
class ToolAxisSetupsTest {

    /** Drilled from its top, its +X side and its underside: 100 x 60 x 40 mm block. */
    static final Path THREE_SIDES = Path.of("src/test/resources/stepnc/setups-three-sides.stp");

    /** GRIMA's STEP Modeler part: 57 workingsteps in six setups, 100 mm cube. */
    static final Path BOXY = TestInputs.SHARED_CORPUS.resolve("stepnc/grima/testBoxy.p21");

    /** The planner's reason for the underside's workingstep, for every post and the robot. */
    static final String UNDERSIDE_REFUSED = "workingstep 'WS DRILL UNDERSIDE' (#12): tool axis (0, 0, -1) works from"
            + " the far side of the part, against the security plane's normal (0, 0, 1): the link through the"
            + " security plane would cross the part; it needs the part turned over, in another setup";

    @Test
    @InterpreterCheck
    void aThreeAxisProgramHoldsOnlyTheTopsWorkingstepAndSaysWhyTheOthersAreLeftOut(@TempDir Path dir) throws Exception {
        TaskOutcome o =
                ToolpathService.run(THREE_SIDES, MillingPost.LINUXCNC, new OutputFolder(dir), ProgressMonitor.NONE);
        assertEquals(1, o.exitStatus(), o.problems().toString());
        assertTrue(
                o.problems()
                        .contains("tool axis (1, 0, 0): a 3-axis program machines along +Z only; 1 workingstep needs"
                                + " another setup"),
                o.problems().toString());
        assertTrue(o.problems().contains(UNDERSIDE_REFUSED), o.problems().toString());
        assertEquals(1, o.summary().get("planned"));
        // the summary names each workingstep left out with its own reason
        assertEquals(
                List.of(
                        java.util.Map.of(
                                "id",
                                "WS DRILL SIDE X",
                                "instance",
                                11L,
                                "reason",
                                "tool axis (1, 0, 0): a 3-axis program machines along +Z only; it needs another setup"),
                        java.util.Map.of(
                                "id",
                                "WS DRILL UNDERSIDE",
                                "instance",
                                12L,
                                "reason",
                                UNDERSIDE_REFUSED.substring(UNDERSIDE_REFUSED.indexOf("tool axis")))),
                o.summary().get("not_planned"));
        String nc = Files.readString(dir.resolve("program.ngc"));
        assertAll(
                () -> assertTrue(nc.contains("(WS DRILL TOP"), nc),
                () -> assertFalse(nc.contains("SIDE X"), nc),
                () -> assertFalse(nc.contains("UNDERSIDE"), nc),
                () -> assertFalse(nc.contains("is not +Z"), nc));
        assertCsvAlongZOnly(dir.resolve("toolpath.csv"));
        assumeTrue(Rs274.available(), Rs274.whyNot());
        Rs274.Result r = Rs274.run(dir.resolve("program.ngc"), 6);
        assertEquals(0, r.exitStatus(), r.stderr());
        // the deepest point of the program is the top hole's bottom, 10 mm into the 40 mm block
        double lowest = r.motions().stream().mapToDouble(c -> c.end().z()).min().orElseThrow();
        assertEquals(30, lowest, 1e-9);
    }

    /** {@code fresa stepnc} lists what {@code fresa toolpath} leaves out, each with its real reason. */
    @Test
    void theListingGivesEachLeftOutWorkingstepsRealReason() throws Exception {
        List<StepNcService.NotPlanned> np = StepNcService.notPlanned(StepNcReader.read(THREE_SIDES));
        assertEquals(
                List.of(
                        new StepNcService.NotPlanned(
                                11,
                                "WS DRILL SIDE X",
                                "tool axis (1, 0, 0): a 3-axis program machines along +Z only; it needs another setup"),
                        new StepNcService.NotPlanned(
                                12,
                                "WS DRILL UNDERSIDE",
                                UNDERSIDE_REFUSED.substring(UNDERSIDE_REFUSED.indexOf("tool axis")))),
                np);
    }

    @Test
    void theAptProgramLeavesTheOtherSidesOutToo(@TempDir Path dir) throws Exception {
        TaskOutcome o = ToolpathService.run(THREE_SIDES, MillingPost.APT, new OutputFolder(dir), ProgressMonitor.NONE);
        assertEquals(1, o.exitStatus(), o.problems().toString());
        String apt = Files.readString(dir.resolve("program.apt"));
        assertAll(
                () -> assertTrue(apt.contains("WS DRILL TOP"), apt),
                () -> assertFalse(apt.contains("SIDE X"), apt),
                () -> assertFalse(apt.contains("is not +Z"), apt));
    }

    /**
     * The robot's path keeps the sides it can reach from the security plane, and the floor of each
     * section is measured along its own axis: the +X hole reaches 10 mm into the block from x 100,
     * far from the block's other faces along X, though 10 mm below its floor along Z. The
     * underside's hole is refused: its link from the security plane above the part would cross
     * the part (before, the path went straight down through the block to 5 mm under it).
     */
    @Test
    void theRobotsPathKeepsTheSideAndPassesTheFloorAlongEachAxis() throws Exception {
        StepNcProgram program = StepNcReader.read(THREE_SIDES);
        ToolpathPlanner.Plan plan = ToolpathService.plan(program, PlanningChoices.DEFAULT, ProgressMonitor.NONE);
        assertEquals(2, plan.planned(), plan.problems().toString());
        assertEquals(List.of(UNDERSIDE_REFUSED), plan.problems());
        assertEquals(
                List.of(Vec3.UNIT_Z, Vec3.UNIT_X),
                plan.toolpath().sections().stream()
                        .map(ToolpathSection::toolAxis)
                        .toList());
        Optional<Failure> f = pathCheck(program, plan, plan.toolpath());
        assertTrue(f.isEmpty(), f.map(Failure::message).orElse(""));
    }

    /**
     * A section driven past the stock's far side along its own axis is refused, though it stays
     * above the floor along Z: the +X hole made 105 mm deep (through the block and 5 mm beyond,
     * more than the drill's allowance).
     */
    @Test
    void aSectionThroughTheFarSideAlongItsAxisIsRefused() throws Exception {
        StepNcProgram program = StepNcReader.read(THREE_SIDES);
        ToolpathPlanner.Plan plan = ToolpathService.plan(program, PlanningChoices.DEFAULT, ProgressMonitor.NONE);
        List<ToolpathSection> sections = new ArrayList<>(plan.toolpath().sections());
        sections.set(1, deeper(sections.get(1), 95));
        Optional<Failure> f = pathCheck(program, plan, new Toolpath(sections));
        assertTrue(f.isPresent());
        assertEquals(
                "line 18 \"G1 X-5.000 Y30.000 Z20.000\": floor: move to X -5 Y 30 Z 20 mm, 5 mm below the floor along"
                        + " the tool axis (1, 0, 0), the stock's far side at 0 mm along it; the breakthrough allowed is"
                        + " 2.803 mm",
                f.get().message());
    }

    @Test
    @InterpreterCheck
    void testBoxysProgramHoldsItsTopSetupAndNamesEveryOtherSide(@TempDir Path dir) throws Exception {
        assumeTrue(Files.isRegularFile(BOXY), TestInputs.sharedCorpusAbsent(BOXY.getParent()));
        TaskOutcome o = ToolpathService.run(BOXY, MillingPost.LINUXCNC, new OutputFolder(dir), ProgressMonitor.NONE);
        assertEquals(1, o.exitStatus());
        assertTrue(Files.isRegularFile(dir.resolve("program.ngc")), o.problems().toString());
        assertFalse(o.summary().containsKey("program_refused"), o.summary().toString());
        // 9 workingsteps on +Z, less the 50 mm pocket whose end mill has 38 mm of cutting edge
        assertEquals(8, o.summary().get("planned"));
        assertTrue(
                o.problems().stream()
                        .anyMatch(p -> p.startsWith("workingstep 'Pocket_RGH' (#67): the tool cuts 50 mm below the"
                                + " feature's top but its cutting edge is 38 mm long")),
                o.problems().toString());
        // the sides' counts leave out the workingsteps refused for their tools' cutting edges and the
        // boring bars wider than their holes (32 mm in the 30 mm holes, 26 mm in the 24 mm ones)
        for (String p : List.of(
                "tool axis (1, 0, 0): a 3-axis program machines along +Z only; 8 workingsteps need another setup",
                "tool axis (0, -1, 0): a 3-axis program machines along +Z only; 13 workingsteps need another setup",
                "tool axis (-1, 0, 0): a 3-axis program machines along +Z only; 8 workingsteps need another setup",
                "tool axis (0, 1, 0): a 3-axis program machines along +Z only; 8 workingsteps need another setup")) {
            assertTrue(o.problems().contains(p), p + " in " + o.problems());
        }
        // the underside setup's four holes (its 50 mm pocket is refused first, for its tool's edge): a
        // link from the security plane above would cross the part
        assertEquals(
                4,
                o.problems().stream()
                        .filter(p -> p.contains("tool axis (0, 0, -1) works from the far side of the part"))
                        .count(),
                o.problems().toString());
        assertCsvAlongZOnly(dir.resolve("toolpath.csv"));
        assumeTrue(Rs274.available(), Rs274.whyNot());
        Rs274.Result r = Rs274.run(dir.resolve("program.ngc"), 20);
        assertEquals(0, r.exitStatus(), r.stderr());
        double lowest = r.motions().stream().mapToDouble(c -> c.end().z()).min().orElseThrow();
        assertTrue(lowest >= 50 - 1e-9, "nothing below the 50 mm pocket's floor: " + lowest);
    }

    /**
     * testBoxy's robot path keeps its four side setups (43 workingsteps on +Z, +-X, +-Y) and
     * passes the program check with the floor along each axis; before, it was refused at its
     * underside pocket's rapid to Z -5 through the part.
     */
    @Test
    void testBoxysRobotPathKeepsEverySideItCanReachAndPassesTheCheck() throws Exception {
        assumeTrue(Files.isRegularFile(BOXY), TestInputs.sharedCorpusAbsent(BOXY.getParent()));
        StepNcProgram program = StepNcReader.read(BOXY);
        ToolpathPlanner.Plan plan = ToolpathService.plan(program, PlanningChoices.DEFAULT, ProgressMonitor.NONE);
        // 52 workingsteps on the five sides it reaches, less the two 50 mm pockets (38 mm of edge),
        // two of the three 6.5 mm holes (6 mm of flutes) the sides planned hold, and three boring
        // bars wider than their holes (32 mm in 30, 26 mm in 24)
        assertEquals(45, plan.planned(), plan.problems().toString());
        assertEquals(
                5,
                plan.toolpath().sections().stream()
                        .map(ToolpathSection::toolAxis)
                        .distinct()
                        .count());
        Optional<Failure> f = pathCheck(program, plan, plan.toolpath());
        assertTrue(f.isEmpty(), f.map(Failure::message).orElse(""));
    }

    static Optional<Failure> pathCheck(StepNcProgram program, ToolpathPlanner.Plan plan, Toolpath path)
            throws Exception {
        // what the robot's program check does first: the path as linuxcnc writes it, in the part's frame
        StringWriter nc = new StringWriter();
        NcPosts.byName("linuxcnc").orElseThrow().write(path, "robot", nc);
        return ProgramCheck.of(
                        nc.toString(), NcDialect.LINUXCNC, ProgramChecks.stepnc(program, plan, PlanningChoices.DEFAULT))
                .failure();
    }

    /** The section with every feed move's end pushed further against its tool axis. */
    static ToolpathSection deeper(ToolpathSection s, double extraMm) {
        Vec3 down = s.toolAxis().times(-extraMm);
        List<Move> moves = new ArrayList<>();
        for (Move m : s.moves()) {
            moves.add(m instanceof Move.Linear l ? new Move.Linear(l.end().plus(down), l.feedMmPerMin()) : m);
        }
        return new ToolpathSection(
                s.label(), s.toolAxis(), s.toolDiameterMm(), s.toolNumber(), s.spindleRpm(), s.start(), moves);
    }

    static void assertCsvAlongZOnly(Path csv) throws Exception {
        List<String> rows = Files.readAllLines(csv);
        assertTrue(rows.size() > 1);
        for (String row : rows.subList(1, rows.size())) {
            String[] f = row.split(",", -1);
            Vec3 axis = new Vec3(
                    Double.parseDouble(f[f.length - 4]),
                    Double.parseDouble(f[f.length - 3]),
                    Double.parseDouble(f[f.length - 2]));
            assertTrue(axis.distance(Vec3.UNIT_Z) < 1e-9, row);
        }
    }
}
