package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.geom.Tolerance;
import org.fresa.stepnc.StepNcReader;
import org.junit.jupiter.api.Test;

/**
 * A round hole's change_in_diameter (ISO 14649-10 taper_select) is read: a tool going straight
 * down the axis must be no wider than the hole at any height, or it would cut the cone's wall.
 * Before, the taper was not read and the hole was drilled and reamed straight at its top diameter.
 */
class TaperedHoleTest {

    static final Path EXAMPLE1 = Path.of("samples/stepnc/iso14649-11-example1.stp");
    static final String HOLE = "#17= ROUND_HOLE('HOLE1 D=22MM',#4,(#20,#21),#81,#64,#58,$,#26);";

    static ToolpathPlanner.Plan plan(String taper) throws Exception {
        String text = Files.readString(EXAMPLE1);
        assertTrue(text.contains(HOLE));
        text = text.replace(HOLE, HOLE.replace("#58,$,#26", "#58,#900,#26") + "\n" + taper);
        return ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "taper.stp"), Tolerance.DEFAULT);
    }

    static boolean planned(ToolpathPlanner.Plan p, String ws) {
        return p.toolpath().sections().stream().anyMatch(s -> s.label().equals(ws));
    }

    static String refusal(ToolpathPlanner.Plan p, String ws) {
        return p.problems().stream()
                .filter(x -> x.startsWith("workingstep '" + ws + "' (#"))
                .findFirst()
                .orElseThrow(() -> new AssertionError(ws + " not refused: " + p.problems()));
    }

    @Test
    void aToolWiderThanTheBottomOfANarrowingHoleIsRefused() throws Exception {
        // 22 mm at the top, 21 mm at the bottom: the 20 mm drill fits, the 22 mm reamer would cut the cone
        ToolpathPlanner.Plan p = plan("#900= DIAMETER_TAPER(#901);\n#901= TOLERANCED_LENGTH_MEASURE(21.000,$);");
        assertTrue(planned(p, "WS DRILL HOLE1"), p.problems().toString());
        assertTrue(!planned(p, "WS REAM HOLE1"), p.problems().toString());
        assertTrue(
                refusal(p, "WS REAM HOLE1")
                        .contains("the hole narrows from 22 mm at its top to 21 mm at its bottom (change_in_diameter):"
                                + " the 22 mm tool would cut its wall"),
                p.problems().toString());
    }

    @Test
    void aHoleThatWidensTowardsItsBottomIsRefused() throws Exception {
        ToolpathPlanner.Plan p = plan("#900= DIAMETER_TAPER(#901);\n#901= TOLERANCED_LENGTH_MEASURE(25.000,$);");
        assertTrue(
                refusal(p, "WS DRILL HOLE1").contains("the hole widens from 22 mm at its top to 25 mm at its bottom"),
                p.problems().toString());
    }

    @Test
    void anAngleTaperNarrowsTheHoleByItsLeanOverTheDepth() throws Exception {
        // 22 mm at the top, its wall leaning 1 deg in: the 20 mm drill fits at the bottom, the 22 mm
        // reamer does not
        ToolpathPlanner.Plan p = plan("#900= ANGLE_TAPER(1.000);");
        assertTrue(planned(p, "WS DRILL HOLE1"), p.problems().toString());
        assertTrue(
                refusal(p, "WS REAM HOLE1").contains("the hole narrows from 22 mm at its top to "),
                p.problems().toString());
    }

    @Test
    void aTaperItCannotReadIsRefusedNotDrilledStraight() throws Exception {
        ToolpathPlanner.Plan p = plan("#900= DIAMETER_TAPER($);");
        assertTrue(
                refusal(p, "WS DRILL HOLE1").contains("the hole's change_in_diameter (DIAMETER_TAPER) is not read"),
                p.problems().toString());
    }

    @Test
    void aTaperTheToolsFitIsMadeAsBefore() throws Exception {
        // 22 mm at the top, 22 at the bottom: no change
        ToolpathPlanner.Plan p = plan("#900= DIAMETER_TAPER(#901);\n#901= TOLERANCED_LENGTH_MEASURE(22.000,$);");
        assertTrue(
                planned(p, "WS DRILL HOLE1") && planned(p, "WS REAM HOLE1"),
                p.problems().toString());
    }
}
