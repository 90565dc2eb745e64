package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

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
 * Bosses left standing on a step, in an open pocket and on a planar face
 * (src/test/resources/stepnc/bosses-on-open-features.stp, the 120 x 150 x 30 block of
 * {@link StepsAndOutsideProfilesTest}): the feature's region less its bosses, carried into the
 * air beyond its open sides, is cleared by the region engine. The checks are those of
 * {@link StepsAndOutsideProfilesTest}: at every 0.5 mm of height the tool stays within the
 * feature less its bosses (or outside the block) by 0.01 mm, the floor is cleared where the tool
 * reaches, a cutter 0.05 mm wider is seen leaving, and the program passes the program check and
 * LinuxCNC's interpreter.
 */
class BossesOnOpenFeaturesTest {

    static final Path PART = Path.of("src/test/resources/stepnc/bosses-on-open-features.stp");

    static ToolpathPlanner.Plan plan;

    @BeforeAll
    static void planThePart() throws Exception {
        plan = ToolpathPlanner.plan(StepNcReader.read(PART), Tolerance.DEFAULT);
    }

    static ToolpathSection section(String label) {
        return plan.toolpath().sections().stream()
                .filter(x -> x.label().equals(label))
                .findFirst()
                .orElseThrow(() -> new AssertionError(label + " not planned: " + plan.problems()));
    }

    // the step x 90..120 over the whole block, 8 deep, less the round boss 12 across at (105, 75)
    static final Geometry STEP = SlotProfilesTest.box(90, 0, 120, 150).difference(SlotProfilesTest.disc(105, 75, 6));
    // the open pocket x 0..40, y 50..100, 10 deep, less the boss x 17..27, y 67..83
    static final Geometry OPEN_POCKET =
            SlotProfilesTest.box(0, 50, 40, 100).difference(SlotProfilesTest.box(17, 67, 27, 83));
    // the face x 0..60, y 110..150, 3 deep, less the round boss 10 across at (30, 130)
    static final Geometry FACE = SlotProfilesTest.box(0, 110, 60, 150).difference(SlotProfilesTest.disc(30, 130, 5));

    @Test
    void everyWorkingstepIsPlanned() {
        assertEquals(3, plan.planned(), plan.problems().toString());
        assertEquals(3, plan.workingsteps());
    }

    @Test
    void aStepLeavesItsBossStandingAndClearsItsFloorRoundIt() {
        ToolpathSection sec = section("WS STEP WITH BOSS");
        StepsAndOutsideProfilesTest.check(sec, 3, STEP, -8, STEP, false);
        assertTrue(sec.moves().stream().anyMatch(m -> m instanceof Move.Circular), "round the boss on arcs");
    }

    @Test
    void anOpenPocketLeavesItsBossStandingAndClearsItsFloorRoundIt() {
        StepsAndOutsideProfilesTest.check(section("WS OPEN POCKET WITH BOSS"), 3, OPEN_POCKET, -10, OPEN_POCKET, false);
    }

    @Test
    void aPlanarFaceLeavesItsBossStandingAndClearsItsFloorRoundIt() {
        StepsAndOutsideProfilesTest.check(section("WS FACE WITH BOSS"), 3, FACE, -3, FACE, false);
    }

    @Test
    void theToolRunsInTheAirBeyondTheOpenSides() {
        // the loops carried past the open sides reach beyond the block by the tool's radius
        assertTrue(section("WS STEP WITH BOSS").moves().stream()
                .anyMatch(m -> m.end().x() >= 120 + 3 - 1e-6));
        assertTrue(section("WS OPEN POCKET WITH BOSS").moves().stream()
                .anyMatch(m -> m.end().x() <= -3 + 1e-6));
        assertTrue(section("WS FACE WITH BOSS").moves().stream()
                .anyMatch(m -> m.end().y() >= 150 + 3 - 1e-6));
        // and the face's sides inside the block keep the tool within them
        assertTrue(section("WS FACE WITH BOSS").moves().stream()
                .allMatch(m -> m.end().x() <= 60 - 3 + 1e-6 && m.end().y() >= 110 + 3 - 1e-6));
    }

    @Test
    void theVolumeCheckCatchesACutterWiderThanPlanned() {
        assertTrue(StepsAndOutsideProfilesTest.outsideAt(section("WS STEP WITH BOSS"), 3.05, STEP, -8) > 1e-6);
        assertTrue(StepsAndOutsideProfilesTest.outsideAt(section("WS OPEN POCKET WITH BOSS"), 3.05, OPEN_POCKET, -10)
                > 1e-6);
        assertTrue(StepsAndOutsideProfilesTest.outsideAt(section("WS FACE WITH BOSS"), 3.05, FACE, -3) > 1e-6);
    }

    @Test
    @InterpreterCheck
    void theProgramPassesTheProgramCheckAndLinuxCncAcceptsIt(@TempDir Path dir) throws Exception {
        FeatureVolumeCheck.assertProgramAccepted(PART, dir);
    }
}
