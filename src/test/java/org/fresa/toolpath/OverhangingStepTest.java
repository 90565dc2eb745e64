package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
import org.locationtech.jts.geom.Geometry;

/**
 * A step whose wall overhangs its floor at 60 deg (a half dovetail): the step open at both ends
 * of src/test/resources/stepnc/steps-outside-profiles.stp (x 105..120 at the top, 8 deep) with its
 * wall boundary a 60 deg vee, so that the wall's foot lies 8 / tan(60 deg) = 4.62 mm under the
 * material, and a third workingstep that cuts the undercut with a 16 mm dovetail mill whose flank
 * leans 30 deg. The end mill mills the step to the wall's top edge and says what it leaves; the
 * dovetail mill stays within the step at every 0.5 mm of height by 0.01 mm (or outside the
 * block), and with the end mill leaves nothing of the step at any height; the program passes the
 * program check and LinuxCNC's interpreter.
 */
class OverhangingStepTest {

    static final double COT = 1 / Math.tan(Math.toRadians(60));
    static String part;
    static ToolpathPlanner.Plan plan;

    @BeforeAll
    static void planThePart() throws Exception {
        part = Files.readString(StepsAndOutsideProfilesTest.PART)
                .replace("(#10,#11,#12,#13,#14,#15)", "(#10,#11,#200,#12,#13,#14,#15)")
                .replace(
                        "#16= STEP('STEP OPEN',#4,(#20,#21),#81,#82,#24,#25,());",
                        "#16= STEP('STEP OPEN',#4,(#20,#21,#201),#81,#82,#24,#29,());\n"
                                + "#29= VEE_PROFILE($,0.000,60.000,60.000);\n"
                                + "#200= MACHINING_WORKINGSTEP('WS STEP UNDERCUT',#62,#16,#201,$);\n"
                                + "#201= BOTTOM_AND_SIDE_FINISH_MILLING($,$,'UNDERCUT STEP',5.000,$,#202,#40,$,$,$,$,$,"
                                + "$,$,$,$);\n"
                                + "#202= MILLING_CUTTING_TOOL('DOVETAIL 16MM 60DEG',#203,(#125),80.000,$,$);\n"
                                + "#203= DOVETAIL_MILL(#204,6,.RIGHT.,.F.,$);\n"
                                + "#204= MILLING_TOOL_DIMENSION(16.000,$,30.000,10.0,0.0,$,$);");
        plan = ToolpathPlanner.plan(StepNcReader.read(new StringReader(part), "overhang.stp"), Tolerance.DEFAULT);
    }

    static ToolpathSection section(String label) {
        return FeatureVolumeCheck.section(plan, label);
    }

    /** The wall at height z: at its top edge x 105, at its foot (z -8) 4.62 mm under the material. */
    static double wallX(double z) {
        return 105 + z * COT;
    }

    static SlotProfilesTest.Shape dovetailMill() {
        return h -> h <= 10 ? 8 - h * Math.tan(Math.toRadians(30)) : 0;
    }

    @Test
    void theEndMillMillsToTheTopEdgeAndSaysWhatItLeaves() {
        ToolpathSection finish = section("WS STEP FINISH");
        FeatureVolumeCheck.assertFloor(finish, -8, 1e-6);
        FeatureVolumeCheck.assertInside(
                finish,
                SlotProfilesTest.flat(5),
                z -> SlotProfilesTest.box(105, 0, 120, 150).union(StepsAndOutsideProfilesTest.OUTSIDE));
        assertTrue(
                plan.problems()
                        .contains("workingstep 'WS STEP FINISH': the wall overhangs the floor at 60 deg: the step is"
                                + " milled to the wall's top edge, and the 4.618802 mm undercut under it needs a"
                                + " DOVETAIL_MILL"),
                plan.problems().toString());
    }

    @Test
    void theDovetailMillCutsTheUndercutWithinTheStepAndLeavesNothing() {
        ToolpathSection finish = section("WS STEP FINISH");
        ToolpathSection under = section("WS STEP UNDERCUT");
        FeatureVolumeCheck.assertFloor(under, -8, 1e-6);
        FeatureVolumeCheck.assertInside(
                under,
                dovetailMill(),
                z -> SlotProfilesTest.box(wallX(z), 0, 120, 150).union(StepsAndOutsideProfilesTest.OUTSIDE));
        for (double z = -8; z <= 0; z += 0.5) {
            Geometry cut = Swept.GF.createPolygon();
            for (Geometry g : SlotProfilesTest.slice(finish, SlotProfilesTest.flat(5), z)) {
                cut = cut.union(g);
            }
            for (Geometry g : SlotProfilesTest.slice(under, dovetailMill(), z)) {
                cut = cut.union(g);
            }
            double left = SlotProfilesTest.box(wallX(z), 0, 120, 150)
                    .difference(cut.buffer(0.01, 64))
                    .getArea();
            assertTrue(left < 1e-6, "at z " + z + " the tools leave " + left + " mm2 of the step");
        }
        // under the wall, its flank on the foot: 4.62 mm under the material less its 8 mm radius
        assertEquals(
                105 - 8 * COT + 8,
                under.moves().stream()
                        .filter(m -> m.end().z() < -7.999)
                        .mapToDouble(m -> m.end().x())
                        .min()
                        .orElseThrow(),
                1e-6);
    }

    @Test
    void aDovetailMillWhoseFlankDoesNotLeanAsTheWallIsRefused() throws Exception {
        String text = part.replace(
                "#204= MILLING_TOOL_DIMENSION(16.000,$,30.000,10.0,0.0,$,$);",
                "#204= MILLING_TOOL_DIMENSION(16.000,$,20.000,10.0,0.0,$,$);");
        ToolpathPlanner.Plan p =
                ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "overhang.stp"), Tolerance.DEFAULT);
        assertTrue(
                p.problems().stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS STEP UNDERCUT' (#")
                                && x.contains("the dovetail mill's flank leans 20 deg from its axis, the step's wall"
                                        + " 30 deg (60 deg to the base)")),
                p.problems().toString());
    }

    @Test
    void aDovetailMillOnAnUprightWallIsRefused() throws Exception {
        String text =
                part.replace("#29= VEE_PROFILE($,0.000,60.000,60.000);", "#29= VEE_PROFILE($,0.000,90.000,90.000);");
        ToolpathPlanner.Plan p =
                ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "upright.stp"), Tolerance.DEFAULT);
        assertTrue(
                p.problems().stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS STEP UNDERCUT' (#")
                                && x.contains("a DOVETAIL_MILL mills a step only under a wall that overhangs its"
                                        + " floor; this wall stands at 90 deg to it")),
                p.problems().toString());
    }

    @Test
    @InterpreterCheck
    void theProgramPassesTheProgramCheckAndLinuxCncAcceptsIt(@TempDir Path dir) throws Exception {
        FeatureVolumeCheck.assertProgramAccepted(part, "overhang.stp", dir);
    }
}
