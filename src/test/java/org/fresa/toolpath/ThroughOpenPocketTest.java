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

/**
 * A through open pocket: the open pocket of src/test/resources/stepnc/steps-outside-profiles.stp
 * (open to the x 0 side, a round end) with a THROUGH_POCKET_BOTTOM_CONDITION, milled through the
 * 30 mm block and 1 mm past its bottom (the breakthrough; the 10 mm cutter has no corner radius, and
 * its cutting edge is lengthened from the file's 25 mm to 35 mm for the 31 mm cut).
 * The checks of {@link StepsAndOutsideProfilesTest}: within the pocket at every 0.5 mm of height,
 * its outline cleared at the lowest layer, descents only outside the block, a cutter 0.05 mm wider
 * seen leaving, the program check (whose floor allows the through allowance) and rs274.
 */
class ThroughOpenPocketTest {

    static String part;
    static ToolpathPlanner.Plan plan;

    @BeforeAll
    static void planThePart() throws Exception {
        part = Files.readString(StepsAndOutsideProfilesTest.PART)
                .replace(
                        "#19= OPEN_POCKET('OPEN POCKET',#4,(#34),#85,#88,(),$,#257,$,$,#235,$);",
                        "#19= OPEN_POCKET('OPEN POCKET',#4,(#34),#85,#88,(),$,#259,$,$,#235,$);\n"
                                + "#259= THROUGH_POCKET_BOTTOM_CONDITION();")
                // a 31 mm cut needs more than the file's 25 mm of cutting edge
                .replace(
                        "#48= MILLING_TOOL_DIMENSION(10.000,$,$,25.0,0.0,$,$);",
                        "#48= MILLING_TOOL_DIMENSION(10.000,$,$,35.0,0.0,$,$);");
        plan = ToolpathPlanner.plan(StepNcReader.read(new StringReader(part), "through.stp"), Tolerance.DEFAULT);
    }

    static ToolpathSection section() {
        return plan.toolpath().sections().stream()
                .filter(x -> x.label().equals("WS OPEN POCKET"))
                .findFirst()
                .orElseThrow(() -> new AssertionError("not planned: " + plan.problems()));
    }

    @Test
    void theOpenPocketIsMilledThroughTheBlockAndPastItsBottom() {
        ToolpathSection sec = section();
        StepsAndOutsideProfilesTest.check(
                sec, 5, StepsAndOutsideProfilesTest.OPEN_POCKET, -31, StepsAndOutsideProfilesTest.OPEN_POCKET);
        assertTrue(
                plan.problems()
                        .contains("workingstep 'WS OPEN POCKET': the through open pocket is cut 31 mm deep: to the"
                                + " bottom of the workpiece's block (30 mm) and 1 mm past it"),
                plan.problems().toString());
    }

    @Test
    void theVolumeCheckCatchesACutterWiderThanPlanned() {
        assertTrue(StepsAndOutsideProfilesTest.outsideAt(section(), 5.05, StepsAndOutsideProfilesTest.OPEN_POCKET, -20)
                > 1e-6);
        assertTrue(StepsAndOutsideProfilesTest.outsideAt(section(), 5, StepsAndOutsideProfilesTest.OPEN_POCKET, -20)
                < 1e-6);
    }

    @Test
    @InterpreterCheck
    void theProgramPassesTheProgramCheckAndLinuxCncAcceptsIt(@TempDir Path dir) throws Exception {
        FeatureVolumeCheck.assertProgramAccepted(part, "through.stp", dir);
    }
}
