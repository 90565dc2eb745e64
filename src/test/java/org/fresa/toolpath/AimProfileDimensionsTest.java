package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.geom.Tolerance;
import org.fresa.stepnc.StepNcReader;
import org.junit.jupiter.api.Test;

/**
 * An AIM pocket's rectangular outline is read with every dimension it gives: a missing width or
 * length is not taken as 0, and a 'corner radius' (the ARM's rectangle has none) is not dropped,
 * which would mill the corners square, into the part.
 */
class AimProfileDimensionsTest {

    static final Path AIM = Path.of("src/test/resources/stepnc/aim-bosses.stp");
    static final String POCKET_PARAMETERS = "#100=SHAPE_REPRESENTATION_WITH_PARAMETERS('',(#73,#97,#98),#7);";

    static String refusal(String text) throws Exception {
        ToolpathPlanner.Plan p =
                ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "aim.stp"), Tolerance.DEFAULT);
        assertTrue(
                p.toolpath().sections().stream().noneMatch(s -> s.label().equals(AimBossesTest.WS)),
                "planned: " + p.problems());
        return p.problems().stream()
                .filter(x -> x.startsWith("workingstep '" + AimBossesTest.WS + "' (#"))
                .findFirst()
                .orElseThrow(() -> new AssertionError("not refused: " + p.problems()));
    }

    @Test
    void aRectangleWithACornerRadiusIsRefusedNotMilledSquare() throws Exception {
        String text = Files.readString(AIM);
        assertTrue(text.contains(POCKET_PARAMETERS));
        text = text.replace(
                POCKET_PARAMETERS,
                "#100=SHAPE_REPRESENTATION_WITH_PARAMETERS('',(#73,#97,#98,#9000),#7);\n"
                        + "#9000=(LENGTH_MEASURE_WITH_UNIT() MEASURE_REPRESENTATION_ITEM()"
                        + " MEASURE_WITH_UNIT(LENGTH_MEASURE(5.0),#1) REPRESENTATION_ITEM('corner radius'));");
        String why = refusal(text);
        assertTrue(why.contains("with a 'corner radius' of 5.0 mm, which the AIM binder does not read"), why);
    }

    @Test
    void aRectangleWithoutItsWidthIsRefusedNotTakenAsZero() throws Exception {
        String text = Files.readString(AIM)
                .replace(POCKET_PARAMETERS, "#100=SHAPE_REPRESENTATION_WITH_PARAMETERS('',(#73,#98),#7);");
        String why = refusal(text);
        assertTrue(why.contains("RECTANGULAR_CLOSED_PROFILE without its 'width'"), why);
    }

    @Test
    void aPocketWhoseWallsSlopeIsRefusedNotMilledUpright() throws Exception {
        String pocket = "#75=SHAPE_REPRESENTATION_WITH_PARAMETERS('',(#73,#74),#7);";
        String text = Files.readString(AIM);
        assertTrue(text.contains(pocket));
        text = text.replace(
                pocket,
                "#75=SHAPE_REPRESENTATION_WITH_PARAMETERS('',(#73,#74,#9001),#7);\n"
                        + "#9001=(MEASURE_REPRESENTATION_ITEM() MEASURE_WITH_UNIT(PLANE_ANGLE_MEASURE(5.0),#5)"
                        + " PLANE_ANGLE_MEASURE_WITH_UNIT() REPRESENTATION_ITEM('slope'));");
        String why = refusal(text);
        assertTrue(why.contains("with walls sloping 5 deg from upright (slope)"), why);
    }
}
