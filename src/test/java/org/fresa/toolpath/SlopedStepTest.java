package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.geom.Tolerance;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.locationtech.jts.geom.Geometry;

/**
 * A step whose wall slopes back at 120 deg to its floor: the step open at both ends of
 * src/test/resources/stepnc/steps-outside-profiles.stp (x 105..120 at the top, 8 deep) with its
 * wall boundary a 120 deg vee, so that the wall's foot lies 8 / tan(60 deg) = 4.62 mm out from the
 * open boundary. At every 0.5 mm of height the tool stays within the step as wide as it is at
 * that height (or outside the block) by 0.01 mm; the floor is cleared; a cutter 0.05 mm wider is
 * seen leaving it; the program passes the program check and LinuxCNC's interpreter.
 */
class SlopedStepTest {

    static final double COT = 1 / Math.tan(Math.toRadians(60));
    static String part;
    static ToolpathPlanner.Plan plan;

    @BeforeAll
    static void planThePart() throws Exception {
        part = Files.readString(StepsAndOutsideProfilesTest.PART)
                .replace(
                        "#16= STEP('STEP OPEN',#4,(#20,#21),#81,#82,#24,#25,());",
                        "#16= STEP('STEP OPEN',#4,(#20,#21),#81,#82,#24,#29,());\n"
                                + "#29= VEE_PROFILE($,0.000,120.000,120.000);");
        plan = ToolpathPlanner.plan(StepNcReader.read(new StringReader(part), "sloped.stp"), Tolerance.DEFAULT);
    }

    static ToolpathSection section(String label) {
        return plan.toolpath().sections().stream()
                .filter(x -> x.label().equals(label))
                .findFirst()
                .orElseThrow(() -> new AssertionError(label + " not planned: " + plan.problems()));
    }

    /** The step at height z (top 0): from the wall, 105 + (-z) cot 60 deg, out to the block's side. */
    static Geometry stepAt(double z) {
        return SlotProfilesTest.box(105 + (-z) * COT, 0, 120, 150);
    }

    static double outsideAt(ToolpathSection sec, double radius, double z) {
        return FeatureVolumeCheck.outsideAt(
                sec, SlotProfilesTest.flat(radius), z, stepAt(z).union(StepsAndOutsideProfilesTest.OUTSIDE));
    }

    static void check(ToolpathSection sec, double radius, double floorZ, double allowanceMm) {
        FeatureVolumeCheck.assertFloor(sec, floorZ, 1e-6);
        FeatureVolumeCheck.assertInside(
                sec, SlotProfilesTest.flat(radius), z -> stepAt(z).union(StepsAndOutsideProfilesTest.OUTSIDE));
        Geometry floor = SlotProfilesTest.box(105 + 8 * COT + allowanceMm, 0, 120, 150);
        FeatureVolumeCheck.assertFloorCleared(sec, radius, floor.buffer(-0.005, 64));
    }

    @Test
    void theLayersFollowTheSlopedWallAndTheStepsLeftAreReported() {
        // roughed with 0.5 mm on the wall and 0.2 mm on the floor: the tool 0.5 mm farther out
        check(section("WS STEP ROUGH"), 5.5, -7.8, 0.5);
        check(section("WS STEP FINISH"), 5, -8, 0);
        // 1 mm layers, as a vee slot's: eight of them to the floor, each deeper pass farther out
        long layers = section("WS STEP FINISH").moves().stream()
                .filter(m -> m instanceof Move.Linear)
                .mapToDouble(m -> m.end().z())
                .filter(z -> z < 0)
                .distinct()
                .count();
        assertEquals(8, layers);
        assertTrue(
                plan.problems()
                        .contains("workingstep 'WS STEP FINISH': the wall sloped at 120 deg is cut in 1 mm layers:"
                                + " steps up to 1 mm high and 0.57735 mm wide are left on it"),
                plan.problems().toString());
    }

    @Test
    void theVolumeCheckCatchesACutterWiderThanPlanned() {
        assertTrue(outsideAt(section("WS STEP FINISH"), 5.05, -8) > 1e-6);
        assertTrue(outsideAt(section("WS STEP FINISH"), 5, -8) < 1e-6);
    }

    @Test
    void aWallOverhangingItsFloorIsMilledToItsTopEdgeAndSaidAndOneReachingTheBlocksSideIsRefused() throws Exception {
        for (String[] c : new String[][] {
            {"60.000", "the wall overhangs the floor at 60 deg: the step is milled to the wall's top edge"},
            {"170.000", "the step has no floor"}
        }) {
            String text = part.replace(
                    "#29= VEE_PROFILE($,0.000,120.000,120.000);",
                    "#29= VEE_PROFILE($,0.000," + c[0] + "," + c[0] + ");");
            ToolpathPlanner.Plan p =
                    ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "sloped.stp"), Tolerance.DEFAULT);
            assertTrue(
                    p.problems().stream()
                            .anyMatch(x -> x.startsWith("workingstep 'WS STEP FINISH'") && x.contains(c[1])),
                    p.problems().toString());
        }
    }

    static ToolpathPlanner.Plan withTilt(String tilt) throws Exception {
        String text = part.replace(
                "#29= VEE_PROFILE($,0.000,120.000,120.000);", "#29= VEE_PROFILE($,0.000,120.000," + tilt + ");");
        return ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "tilted.stp"), Tolerance.DEFAULT);
    }

    @Test
    void aTiltReadOnTheAirSideOfTheWallDrawsTheSameStep() throws Exception {
        // 60 deg between the wall and the block's top above the step is the same wall as 120 deg
        // under the top in the material
        ToolpathPlanner.Plan p = withTilt("60.000");
        ToolpathSection sec = p.toolpath().sections().stream()
                .filter(x -> x.label().equals("WS STEP FINISH"))
                .findFirst()
                .orElseThrow(() -> new AssertionError(p.problems().toString()));
        assertEquals(section("WS STEP FINISH").moves(), sec.moves());
    }

    @Test
    void aTiltThatWouldTiltTheFloorIsRefusedNamingBothAngles() throws Exception {
        ToolpathPlanner.Plan p = withTilt("75.000");
        assertTrue(
                p.problems().stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS STEP FINISH' (#")
                                && x.contains("profile_angle 120 and tilt_angle 75")
                                && x.contains("would tilt the floor by 15 deg")),
                p.problems().toString());
        assertTrue(p.toolpath().sections().stream().noneMatch(x -> x.label().equals("WS STEP FINISH")));
    }

    @Test
    @InterpreterCheck
    void theProgramPassesTheProgramCheckAndLinuxCncAcceptsIt(@TempDir Path dir) throws Exception {
        FeatureVolumeCheck.assertProgramAccepted(part, "sloped.stp", dir);
    }
}
