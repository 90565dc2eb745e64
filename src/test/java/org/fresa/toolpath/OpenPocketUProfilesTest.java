package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.geom.Tolerance;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.locationtech.jts.geom.Geometry;

/**
 * Open pockets bounded by a U: the open pocket of src/test/resources/stepnc/steps-outside-profiles.stp
 * (10 deep, a 10 mm cutter, open to the block's x 0 side) with its open boundary a
 * SQUARE_U_PROFILE 40 wide with 8 mm corners, then a ROUNDED_U_PROFILE 40 wide, each placed with
 * its bottom centred at (45, 80) and its sides running along the profile's +y (the block's -x)
 * out to the block's edge. The checks of {@link StepsAndOutsideProfilesTest}: within the pocket
 * at every 0.5 mm of height by 0.01 mm, the floor cleared, descents only outside the block, a
 * cutter 0.05 mm wider seen leaving, the program check and rs274.
 */
class OpenPocketUProfilesTest {

    static final String OPEN_POCKET = "#19= OPEN_POCKET('OPEN POCKET',#4,(#34),#85,#88,(),$,#257,$,$,#235,$);";

    static String part(String profile) throws Exception {
        return Files.readString(StepsAndOutsideProfilesTest.PART)
                .replace(
                        OPEN_POCKET,
                        "#19= OPEN_POCKET('OPEN POCKET',#4,(#34),#85,#88,(),$,#257,$,$,#400,$);\n" + "#400= " + profile
                                + ";\n#401= AXIS2_PLACEMENT_3D('U BOTTOM',#402,#96,#55);\n"
                                + "#402= CARTESIAN_POINT('U BOTTOM',(45.000,80.000,0.000));");
    }

    static final String SQUARE = "SQUARE_U_PROFILE(#401,40.000,8.000,90.000,8.000,90.000)";
    static final String ROUNDED = "ROUNDED_U_PROFILE(#401,40.000)";

    // x from beyond the block's side to 45, y 60 to 100, the corners at x 45 rounded by 8 mm
    static final Geometry SQUARE_U = SlotProfilesTest.box(-50, 60, 45, 100)
            .buffer(-8, 64)
            .buffer(8, 64)
            .intersection(StepsAndOutsideProfilesTest.BLOCK);
    // the open pocket of the steps part: x 0..25 and the half circle of radius 20 about (25, 80)
    static final Geometry ROUNDED_U = StepsAndOutsideProfilesTest.OPEN_POCKET;

    static ToolpathSection section(String text) throws Exception {
        ToolpathPlanner.Plan plan =
                ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "u.stp"), Tolerance.DEFAULT);
        return plan.toolpath().sections().stream()
                .filter(x -> x.label().equals("WS OPEN POCKET"))
                .findFirst()
                .orElseThrow(() -> new AssertionError("not planned: " + plan.problems()));
    }

    @Test
    void aSquareUIsMilledFromItsOpenSideToItsRoundedCorners() throws Exception {
        ToolpathSection sec = section(part(SQUARE));
        StepsAndOutsideProfilesTest.check(sec, 5, SQUARE_U, -10, SQUARE_U);
        assertTrue(StepsAndOutsideProfilesTest.outsideAt(sec, 5.05, SQUARE_U, -10) > 1e-6);
    }

    @Test
    void aRoundedUIsMilledAsTheSameHalfCircleDrawnAsAGeneralProfile() throws Exception {
        ToolpathSection sec = section(part(ROUNDED));
        StepsAndOutsideProfilesTest.check(sec, 5, ROUNDED_U, -10, ROUNDED_U);
        assertTrue(StepsAndOutsideProfilesTest.outsideAt(sec, 5.05, ROUNDED_U, -10) > 1e-6);
    }

    @Test
    void sidesNotSquareToTheBottomAreRefused() throws Exception {
        String text = part("SQUARE_U_PROFILE(#401,40.000,8.000,80.000,8.000,90.000)");
        ToolpathPlanner.Plan p =
                ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "u.stp"), Tolerance.DEFAULT);
        assertTrue(
                p.problems().stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS OPEN POCKET' (#")
                                && x.endsWith("at 80 deg to its bottom (first_angle): only sides square to it are"
                                        + " milled")),
                p.problems().toString());
    }

    @Test
    @InterpreterCheck
    void theProgramsPassTheProgramCheckAndLinuxCncAcceptsThem(@TempDir Path dir) throws Exception {
        FeatureVolumeCheck.assertProgramAccepted(
                part(SQUARE), "square.stp", Files.createDirectories(dir.resolve("square")));
        FeatureVolumeCheck.assertProgramAccepted(
                part(ROUNDED), "rounded.stp", Files.createDirectories(dir.resolve("rounded")));
    }
}
