package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.geom.Tolerance;
import org.fresa.stepnc.StepNcReader;
import org.junit.jupiter.api.Test;

/**
 * ISO 14649-10's boss may have a slope: its flanks lean from upright. The planner leaves bosses
 * standing upright, so a leaning boss would have its flanks cut away: such a pocket is refused,
 * naming the slope, and an upright one (slope 0 or unset) is milled as before.
 */
class SlopedBossTest {

    static final Path PART = Path.of("src/test/resources/stepnc/steps-outside-profiles.stp");
    static final String ROUND_BOSS = "#320= BOSS('ROUND BOSS',#4,(),#321,#340,#323,$);";

    static ToolpathPlanner.Plan plan(String slope) throws Exception {
        String text = Files.readString(PART);
        assertTrue(text.contains(ROUND_BOSS));
        text = text.replace(ROUND_BOSS, ROUND_BOSS.replace("#323,$);", "#323," + slope + ");"));
        return ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "boss.stp"), Tolerance.DEFAULT);
    }

    static boolean planned(ToolpathPlanner.Plan p) {
        return p.toolpath().sections().stream().anyMatch(s -> s.label().equals("WS POCKET WITH BOSSES"));
    }

    @Test
    void aBossWhoseFlanksLeanIsNotCutAway() throws Exception {
        ToolpathPlanner.Plan p = plan("10.000");
        assertTrue(!planned(p), "a leaning boss was milled upright: " + p.problems());
        assertTrue(
                p.problems().stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS POCKET WITH BOSSES' (#")
                                && x.endsWith(
                                        "bosses bounded by CIRCULAR_CLOSED_PROFILE with flanks leaning 10 deg from"
                                                + " upright (slope) are not supported yet")),
                p.problems().toString());
    }

    @Test
    void anUprightBossIsMilledRoundAsBefore() throws Exception {
        assertTrue(planned(plan("0.000")));
        assertTrue(planned(plan("$")));
    }
}
