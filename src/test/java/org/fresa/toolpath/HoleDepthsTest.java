package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fresa.geom.Tolerance;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.StepNcReader;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Hole depths: src/test/resources/org/fresa/toolpath/holes.stp is a 100 x 80 x 40 mm
 * block, top at z 40, with a Ø6 through hole without depth (118 deg drill), a Ø6 through hole
 * 40 deep whose drilling's cutting_depth 41.092 already holds its 140 deg point (3 / tan 70 deg
 * = 1.0919 mm), a Ø12 through hole 40 deep milled with a Ø8 end mill, and a Ø6 blind hole 10
 * deep. Depths are the lowest z of each workingstep's moves, in the workpiece frame.
 */
class HoleDepthsTest {

    static final Path HOLES = Path.of("src/test/resources/org/fresa/toolpath/holes.stp");
    static final double EPS = 1e-9;
    /** The 118 deg drill's point: r tan(31 deg). */
    static final double TIP_118 = 3 * Math.tan(Math.toRadians(31));

    static ToolpathPlanner.Plan plan(Path file, PlanningChoices choices) throws Exception {
        return ToolpathPlanner.plan(StepNcReader.read(file), Tolerance.DEFAULT, choices);
    }

    static double lowest(ToolpathPlanner.Plan p, String workingstep) {
        ToolpathSection s = p.toolpath().sections().stream()
                .filter(x -> x.label().equals(workingstep))
                .findFirst()
                .orElseThrow(() -> new AssertionError(workingstep + " not planned: " + p.problems()));
        return s.moves().stream().mapToDouble(m -> m.end().z()).min().orElseThrow();
    }

    @Test
    void aThroughHoleWithoutDepthIsDrilledThroughTheBlockPlusTheTipAndTheBreakthrough() throws Exception {
        ToolpathPlanner.Plan p = plan(HOLES, PlanningChoices.DEFAULT);
        // block bottom z 0, then the point (1.8026 mm) and 1 mm: the full diameter leaves 1 mm below the block
        assertEquals(-(TIP_118 + 1), lowest(p, "WS THROUGH NO DEPTH"), EPS);
        assertEquals(-2.8025818570826786, lowest(p, "WS THROUGH NO DEPTH"), EPS);
        assertTrue(
                p.problems()
                        .contains("workingstep 'WS THROUGH NO DEPTH': the through hole has no depth: 40 mm to"
                                + " the bottom of the workpiece's block"),
                p.problems().toString());
    }

    @Test
    void cuttingDepthIsTheDepthTheTipReachesWithNothingAdded() throws Exception {
        ToolpathPlanner.Plan p = plan(HOLES, PlanningChoices.DEFAULT);
        // 40 - 41.092; the tip added again (the old planner) would have gone 1.0919 mm deeper, to -2.1839
        assertEquals(40 - 41.092, lowest(p, "WS THROUGH CUTTING DEPTH"), EPS);
        assertTrue(
                p.problems().stream()
                        .anyMatch(q -> q.startsWith("workingstep 'WS THROUGH CUTTING DEPTH':"
                                + " cutting_depth 41.092 mm takes the full diameter 0.000089 mm past the exit")),
                p.problems().toString());
    }

    @Test
    void aMilledThroughHoleGoesTheBreakthroughBelowTheExit() throws Exception {
        ToolpathPlanner.Plan p = plan(HOLES, PlanningChoices.DEFAULT);
        assertEquals(-1, lowest(p, "WS MILLED THROUGH"), EPS);
    }

    @Test
    void aBlindHoleIsDrilledToItsDepth() throws Exception {
        ToolpathPlanner.Plan p = plan(HOLES, PlanningChoices.DEFAULT);
        assertAll(
                () -> assertEquals(30, lowest(p, "WS BLIND"), EPS),
                () -> assertEquals(4, p.planned(), p.problems().toString()));
    }

    @Test
    void theBreakthroughAskedForMovesEveryThroughExitButNotCuttingDepthNorBlindHoles() throws Exception {
        ToolpathPlanner.Plan p = plan(HOLES, new PlanningChoices(false, 2.5));
        ToolpathPlanner.Plan none = plan(HOLES, new PlanningChoices(false, 0));
        assertAll(
                () -> assertEquals(-(TIP_118 + 2.5), lowest(p, "WS THROUGH NO DEPTH"), EPS),
                () -> assertEquals(-2.5, lowest(p, "WS MILLED THROUGH"), EPS),
                () -> assertEquals(40 - 41.092, lowest(p, "WS THROUGH CUTTING DEPTH"), EPS),
                () -> assertEquals(30, lowest(p, "WS BLIND"), EPS),
                () -> assertEquals(-TIP_118, lowest(none, "WS THROUGH NO DEPTH"), EPS),
                () -> assertEquals(0, lowest(none, "WS MILLED THROUGH"), EPS));
    }

    @Test
    void aThroughHoleWithoutDepthInAFileWithoutBlockIsRefusedAndTheOthersPlanned(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("no-block.stp");
        Files.writeString(
                file,
                Files.readString(HOLES)
                        .replace(
                                "#4= WORKPIECE('BLOCK 100X80X40',#6,0.010,$,$,#5,());",
                                "#4= WORKPIECE('BLOCK 100X80X40',#6,0.010,$,$,$,());"));
        ToolpathPlanner.Plan p = plan(file, PlanningChoices.DEFAULT);
        assertAll(
                () -> assertEquals(3, p.planned()),
                () -> assertTrue(
                        p.problems()
                                .contains(
                                        "workingstep 'WS THROUGH NO DEPTH' (#10): the through hole has no"
                                                + " depth and the file gives no workpiece BLOCK to find the bottom of the stock"),
                        p.problems().toString()));
    }

    @Test
    void aThroughHoleWhoseAxisMissesTheBlockIsRefused(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("outside.stp");
        Files.writeString(
                file,
                Files.readString(HOLES)
                        .replace(
                                "#110= CARTESIAN_POINT('HOLE A',(20.000,20.000,40.000));",
                                "#110= CARTESIAN_POINT('HOLE A',(120.000,20.000,40.000));"));
        ToolpathPlanner.Plan p = plan(file, PlanningChoices.DEFAULT);
        assertTrue(
                p.problems().stream()
                        .anyMatch(
                                q -> q.startsWith(
                                        "workingstep 'WS THROUGH NO DEPTH' (#10): the"
                                                + " through hole has no depth and its axis does not pass through the workpiece BLOCK (100 x 80 x 40")),
                p.problems().toString());
    }

    @Test
    void aThroughHoleOnATiltedFaceGoesToWhereItsAxisLeavesTheBlock(@TempDir Path dir) throws Exception {
        // hole A turned to drill along +x from the block's side x 0 (axis -x out of the material): 100 mm
        Path file = dir.resolve("side.stp");
        Files.writeString(
                file,
                Files.readString(HOLES)
                        .replace(
                                "#81= AXIS2_PLACEMENT_3D('HOLE A',#110,#96,#97);",
                                "#81= AXIS2_PLACEMENT_3D('HOLE A',#110,#130,#131);")
                        .replace(
                                "#110= CARTESIAN_POINT('HOLE A',(20.000,20.000,40.000));",
                                "#110= CARTESIAN_POINT('HOLE A',(0.000,20.000,20.000));\n#130= DIRECTION('AXIS',(-1.000,0.000,0.000));\n"
                                        + "#131= DIRECTION('REF_DIRECTION',(0.000,0.000,1.000));")
                        // 100 mm of block along the axis: a drill with flutes for it
                        .replace(
                                "#32= MILLING_TOOL_DIMENSION(6.000,31.000,$,50.000,$,$,$);",
                                "#32= MILLING_TOOL_DIMENSION(6.000,31.000,$,110.000,$,$,$);"));
        ToolpathPlanner.Plan p = plan(file, PlanningChoices.DEFAULT);
        ToolpathSection s = p.toolpath().sections().get(0);
        double deepest = s.moves().stream()
                .filter(m -> m instanceof Move.Linear)
                .mapToDouble(m -> m.end().x())
                .max()
                .orElseThrow();
        assertEquals(100 + TIP_118 + 1, deepest, EPS);
    }

    @Test
    void everyHoleOfTheFileIsCutWithTheSpindleOn() throws Exception {
        ToolpathPlanner.Plan p = plan(HOLES, PlanningChoices.DEFAULT);
        List<Double> speeds = p.toolpath().sections().stream()
                .map(ToolpathSection::spindleRpm)
                .toList();
        assertEquals(List.of(1200.0, 1200.0, 2400.0, 1200.0), speeds);
    }
}
