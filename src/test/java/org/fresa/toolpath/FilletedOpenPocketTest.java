package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.function.DoubleFunction;
import org.fresa.geom.Tolerance;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.locationtech.jts.geom.Geometry;

/**
 * An open pocket whose floor meets its walls in a 3 mm fillet (planar_radius), milled by a 6 mm
 * flat end mill (src/test/resources/stepnc/filleted-open-pocket.stp: the steps part's open pocket,
 * 10 deep, open to the block's x 0 side). The fillet runs along the walls, not along the open
 * side: every 0.1 mm through the fillet the tool stays within the pocket less the fillet there
 * (and the air beyond the open side), by 0.01 mm (JTS); what it leaves on the fillet lies at most
 * 0.01 mm from it, measured square to it; the floor is cleared to the fillet's foot; the tool goes
 * down only beyond the block; the program check and LinuxCNC's interpreter accept the program.
 */
class FilletedOpenPocketTest {

    static final Path PART = Path.of("src/test/resources/stepnc/filleted-open-pocket.stp");

    static final double RHO = 3;

    static final double DEPTH = 10;

    /** The pocket carried past its open side into the air: the walls' offsets stop at no open side. */
    static final Geometry CARRIED =
            StepsAndOutsideProfilesTest.OPEN_POCKET.union(SlotProfilesTest.box(-50, 60, 0, 100));

    static ToolpathPlanner.Plan plan;

    @BeforeAll
    static void planThePart() throws Exception {
        plan = ToolpathPlanner.plan(StepNcReader.read(PART), Tolerance.DEFAULT);
    }

    static ToolpathSection section(ToolpathPlanner.Plan p) {
        return p.toolpath().sections().stream()
                .filter(x -> x.label().equals("WS FILLET OPEN POCKET"))
                .findFirst()
                .orElseThrow(() -> new AssertionError("not planned: " + p.problems()));
    }

    /** The pocket's cross-section at height z (top 0): less the fillet along its walls, the air round the block. */
    static Geometry pocketAt(double z) {
        double in = FilletedPocketsTest.filletAt(RHO, z + DEPTH);
        Geometry walls = in > 0 ? CARRIED.buffer(-in, 64) : CARRIED;
        return walls.intersection(StepsAndOutsideProfilesTest.BLOCK).union(StepsAndOutsideProfilesTest.OUTSIDE);
    }

    @Test
    void thePocketIsPlannedWithoutProblems() {
        assertEquals(1, plan.planned(), plan.problems().toString());
        assertEquals(List.of(), plan.problems());
    }

    @Test
    void theFlatEndMillKeepsOutOfTheFilletAndClearsTheFloorToItsFoot() {
        ToolpathSection sec = section(plan);
        FeatureVolumeCheck.assertFloor(sec, -DEPTH, 1e-6);
        DoubleFunction<Geometry> at = FilletedOpenPocketTest::pocketAt;
        FeatureVolumeCheck.assertInside(sec, SlotProfilesTest.flat(3), at);
        for (double u = 0; u <= RHO + 1e-9; u += 0.1) {
            double z = -DEPTH + u;
            double out = FeatureVolumeCheck.outsideAt(sec, SlotProfilesTest.flat(3), z, at.apply(z));
            assertTrue(out < 1e-6, "cuts into the fillet at z " + z + " by " + out + " mm2");
        }
        // the cutter's flat bottom reaches the fillet's foot, 3 mm off the walls
        FeatureVolumeCheck.assertFloorCleared(
                sec, 3, CARRIED.buffer(-RHO - 0.005, 64).intersection(StepsAndOutsideProfilesTest.BLOCK));
    }

    /**
     * The material standing at height u above the floor farther than {@code far(u)} off the walls
     * (mm2): nothing of the pocket nearer than that to the walls is asked to be cut.
     */
    static double leftBeyond(ToolpathSection sec, double u, double farMm) {
        Geometry mustGo = CARRIED.buffer(-farMm, 64).intersection(StepsAndOutsideProfilesTest.BLOCK);
        return mustGo.difference(Swept.sweep(sec, 3, -DEPTH + u)).getArea();
    }

    /** How far off the walls a point at height u lies when it is s inside the fillet, measured square to it. */
    static double offWalls(double u, double s) {
        return RHO - Math.sqrt(Math.pow(RHO - s, 2) - (RHO - u) * (RHO - u));
    }

    @Test
    void theZLevelsLeaveAtMostTheScallopOnTheFillet() {
        ToolpathSection sec = section(plan);
        double near = 0;
        for (double u = 0.25; u < RHO; u += 0.25) {
            // 5 um more off the walls: the tool's polygons and the arcs' chords fall short of a round wall by up to 2
            // um
            double left = leftBeyond(sec, u, offWalls(u, FilletedFloor.SCALLOP_MM) + 0.005);
            assertTrue(left < 1e-3, "leaves " + left + " mm2 more than the scallop at " + u + " mm up the fillet");
            near += leftBeyond(sec, u, offWalls(u, 0.002));
        }
        // the check sees the staircase: material stands nearer than the scallop to the fillet
        assertTrue(near > 1, near + " mm2");
    }

    @Test
    void theToolGoesDownOnlyBeyondTheBlock() {
        StepsAndOutsideProfilesTest.check(
                section(plan),
                3,
                CARRIED.intersection(StepsAndOutsideProfilesTest.BLOCK),
                -DEPTH,
                CARRIED.buffer(-RHO, 64).intersection(StepsAndOutsideProfilesTest.BLOCK));
    }

    @Test
    void theVolumeCheckSeesACutterWiderThanPlannedCutIntoTheFillet() {
        double z = -DEPTH + 1.5;
        assertTrue(FeatureVolumeCheck.outsideAt(section(plan), SlotProfilesTest.flat(3.05), z, pocketAt(z)) > 1e-6);
    }

    @Test
    void aCutterWhoseCornerIsLargerThanTheFilletIsRefused() throws Exception {
        String text = Files.readString(PART)
                .replace(
                        "MILLING_TOOL_DIMENSION(6.000,$,$,15.0,0.0,$,$)",
                        "MILLING_TOOL_DIMENSION(6.000,$,$,15.0,3.5,$,$)");
        ToolpathPlanner.Plan p =
                ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "open.stp"), Tolerance.DEFAULT);
        assertTrue(
                p.problems().stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS FILLET OPEN POCKET' (#")
                                && x.endsWith("the open pocket's floor meets its walls in a 3 mm radius; a cutter"
                                        + " with a 3.5 mm corner would leave a 3.5 mm one, material the drawing takes"
                                        + " away: a cutter whose corner is at most 3 mm mills it")),
                p.problems().toString());
    }

    @Test
    void aCutterWhoseCornerIsTheFilletFollowsItAsBefore() throws Exception {
        String exact = Files.readString(PART)
                .replace(
                        "MILLING_TOOL_DIMENSION(6.000,$,$,15.0,0.0,$,$)",
                        "MILLING_TOOL_DIMENSION(6.000,$,$,15.0,3.0,$,$)");
        String none = exact.replace(",#257,3.000,$,#235,$);", ",#257,$,$,#235,$);");
        ToolpathSection a =
                section(ToolpathPlanner.plan(StepNcReader.read(new StringReader(exact), "a.stp"), Tolerance.DEFAULT));
        ToolpathSection b =
                section(ToolpathPlanner.plan(StepNcReader.read(new StringReader(none), "b.stp"), Tolerance.DEFAULT));
        assertEquals(b.moves(), a.moves());
        assertTrue(section(plan).moves().size() > 2 * b.moves().size());
    }

    @Test
    @InterpreterCheck
    void theProgramPassesTheProgramCheckAndLinuxCncAcceptsIt(@TempDir Path dir) throws Exception {
        FeatureVolumeCheck.assertProgramAccepted(PART, dir);
    }
}
