package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.geom.Tolerance;
import org.fresa.stepnc.StepNcReader;
import org.junit.jupiter.api.Test;

/**
 * ISO 14649-10's pocket may give its walls a slope (a mould's draft). The planner mills walls
 * upright, which would cut a drafted wall away below the top: such a pocket is refused, naming the
 * slope; slope 0 or unset is milled as before.
 */
class SlopedPocketWallsTest {

    static final Path PART = Path.of("src/test/resources/stepnc/steps-outside-profiles.stp");
    static final String POCKET =
            "#300= CLOSED_POCKET('POCKET WITH BOSSES',#4,(#310),#301,#340,(#320,#330),$,#257,$,6.000,#302);";

    static ToolpathPlanner.Plan plan(String slope) throws Exception {
        String text = Files.readString(PART);
        assertTrue(text.contains(POCKET));
        text = text.replace(POCKET, POCKET.replace("(#320,#330),$,", "(#320,#330)," + slope + ","));
        return ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "slope.stp"), Tolerance.DEFAULT);
    }

    static boolean planned(ToolpathPlanner.Plan p) {
        return p.toolpath().sections().stream().anyMatch(s -> s.label().equals("WS POCKET WITH BOSSES"));
    }

    @Test
    void aPocketWhoseWallsSlopeIsNotMilledUpright() throws Exception {
        ToolpathPlanner.Plan p = plan("5.000");
        assertTrue(!planned(p), "a drafted pocket was milled upright: " + p.problems());
        assertTrue(
                p.problems().stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS POCKET WITH BOSSES' (#")
                                && x.contains("with walls sloping 5 deg from upright (slope)")),
                p.problems().toString());
    }

    @Test
    void uprightWallsAreMilledAsBefore() throws Exception {
        assertTrue(planned(plan("0.000")));
        assertTrue(planned(plan("$")));
    }
}
