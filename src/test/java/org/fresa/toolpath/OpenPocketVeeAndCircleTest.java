package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.geom.Tolerance;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.util.AffineTransformation;

/**
 * Open pockets bounded by a vee and by a partial circle: src/test/resources/stepnc/open-pockets-vee-circle.stp
 * (a 120 x 150 x 30 block, both 10 deep, a 10 mm cutter, open to the block's x 0 side). The vee
 * (60 deg, a 3 mm blend) has its bottom at (40, 40) and opens along the block's -x; its point is
 * narrower than the cutter, which stops short of it and says so. The partial circle (25 mm about
 * (60, 110), 120 deg) has its middle towards +x and its ends carried out along -x. The checks of
 * {@link StepsAndOutsideProfilesTest}: within the pocket at every 0.5 mm of height by 0.01 mm,
 * the floor cleared where the tool reaches, descents only outside the block, a cutter 0.05 mm
 * wider seen leaving, the program check and rs274.
 */
class OpenPocketVeeAndCircleTest {

    static final Path PART = Path.of("src/test/resources/stepnc/open-pockets-vee-circle.stp");
    static String part;
    static ToolpathPlanner.Plan plan;

    @BeforeAll
    static void planThePart() throws Exception {
        part = Files.readString(PART);
        plan = plan(part);
    }

    static ToolpathPlanner.Plan plan(String text) throws Exception {
        return ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "vee.stp"), Tolerance.DEFAULT);
    }

    static ToolpathSection section(ToolpathPlanner.Plan p, String label) {
        return p.toolpath().sections().stream()
                .filter(x -> x.label().equals(label))
                .findFirst()
                .orElseThrow(() -> new AssertionError(label + " not planned: " + p.problems()));
    }

    // the sharp vee's point at (43, 40), 3 / sin 30 deg - 3 beyond the bottom, its walls 30 deg
    // either side of -x out past the block's side, the point rounded by the 3 mm blend
    static final double TAN30 = Math.tan(Math.toRadians(30));
    static final Geometry VEE = Swept.GF
            .createPolygon(new Coordinate[] {
                new Coordinate(43, 40),
                new Coordinate(-57, 40 + 100 * TAN30),
                new Coordinate(-57, 40 - 100 * TAN30),
                new Coordinate(43, 40)
            })
            .buffer(-3, 64)
            .buffer(3, 64);
    // x from beyond the block's side to the arc's ends at x 72.5, and the arc's segment beyond
    static final double HALF_CHORD = 25 * Math.sqrt(3) / 2;
    static final Geometry CIRCLE = SlotProfilesTest.box(-50, 110 - HALF_CHORD, 72.5, 110 + HALF_CHORD)
            .union(SlotProfilesTest.disc(60, 110, 25).intersection(SlotProfilesTest.box(72.5, 50, 100, 150)));

    static void check(ToolpathSection sec, Geometry pocket) {
        StepsAndOutsideProfilesTest.check(sec, 5, pocket, -10, pocket.intersection(StepsAndOutsideProfilesTest.BLOCK));
        assertTrue(StepsAndOutsideProfilesTest.outsideAt(sec, 5.05, pocket, -10) > 1e-6);
    }

    @Test
    void aVeeIsMilledOutToItsWallsAndItsPointTooNarrowForTheCutterIsReported() {
        check(section(plan, "WS VEE POCKET"), VEE);
        // the cutter touches both walls with its centre 5 / sin 30 deg from the point: 2 mm short of the bottom
        assertTrue(
                plan.problems()
                        .contains("workingstep 'WS VEE POCKET': the 10 mm cutter cannot reach into the 60 deg vee's"
                                + " point (3 mm blend): it stops 2 mm short of its bottom, leaving the material"
                                + " there"),
                plan.problems().toString());
    }

    @Test
    void aVeeTiltedFromUprightIsTurnedAboutItsBottom() throws Exception {
        // tilt 45 deg instead of 60: the vee turned 15 deg clockwise about (40, 40)
        ToolpathPlanner.Plan p =
                plan(part.replace("VEE_PROFILE(#23,3.000,60.000,60.000)", "VEE_PROFILE(#23,3.000,60.000,45.000)"));
        Geometry turned = AffineTransformation.rotationInstance(Math.toRadians(-15), 40, 40)
                .transform(VEE);
        check(section(p, "WS VEE POCKET"), turned);
        assertTrue(StepsAndOutsideProfilesTest.outsideAt(section(p, "WS VEE POCKET"), 5, VEE, -10) > 1e-6);
    }

    @Test
    void aPartialCircleIsMilledAsItsArcWithItsEndsCarriedOutToTheOpenSide() {
        check(section(plan, "WS PARTIAL CIRCLE POCKET"), CIRCLE);
    }

    @Test
    void aPartialCircleOfMoreThanAHalfCircleIsRefused() throws Exception {
        ToolpathPlanner.Plan p = plan(part.replace(
                "PARTIAL_CIRCULAR_PROFILE(#27,25.000,120.000)", "PARTIAL_CIRCULAR_PROFILE(#27,25.000,240.000)"));
        assertTrue(
                p.problems().stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS PARTIAL CIRCLE POCKET' (#")
                                && x.contains("sweeps 240 deg: more than a half circle is wider inside")),
                p.problems().toString());
    }

    @Test
    @InterpreterCheck
    void theProgramPassesTheProgramCheckAndLinuxCncAcceptsIt(@TempDir Path dir) throws Exception {
        FeatureVolumeCheck.assertProgramAccepted(PART, dir);
    }
}
