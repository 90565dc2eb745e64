package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.geom.Tolerance;
import org.fresa.stepnc.StepNcReader;
import org.junit.jupiter.api.Test;

/**
 * ISO 14649-10 lets a slot give no end_conditions, or one: the planner says how it reads them
 * (both ends square, or the one for both) instead of choosing in silence.
 */
class SlotEndsUnstatedTest {

    static final Path PART = Path.of("src/test/resources/stepnc/slots-square-u.stp");
    static final String SLOT1 = "#16= SLOT('SLOT1',#4,(#20),#81,#82,#24,#25,(#26,#26));";

    static ToolpathPlanner.Plan plan(String ends) throws Exception {
        String text = Files.readString(PART);
        assertTrue(text.contains(SLOT1));
        text = text.replace(SLOT1, SLOT1.replace("(#26,#26)", ends));
        return ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "ends.stp"), Tolerance.DEFAULT);
    }

    @Test
    void aSlotWithNoEndConditionsIsCutSquareAndSaysSo() throws Exception {
        ToolpathPlanner.Plan p = plan("()");
        assertEquals(2, p.planned(), p.problems().toString());
        assertTrue(
                p.problems()
                        .contains("workingstep 'WS ROUGH SLOT1': the slot gives no end_conditions: both its ends are"
                                + " cut square, the tool kept within its course of travel"),
                p.problems().toString());
    }

    @Test
    void aSlotWithOneEndConditionTakesItForBothEnds() throws Exception {
        ToolpathPlanner.Plan p = plan("(#26)");
        assertTrue(
                p.problems()
                        .contains("workingstep 'WS ROUGH SLOT1': the slot gives one end condition"
                                + " (OPEN_SLOT_END_TYPE): taken for both its ends"),
                p.problems().toString());
    }

    @Test
    void twoEndConditionsAreReadAsGiven() throws Exception {
        assertTrue(plan("(#26,#26)").problems().stream().noneMatch(x -> x.contains("end_conditions")));
    }
}
