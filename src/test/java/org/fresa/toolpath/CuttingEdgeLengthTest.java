package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import org.fresa.geom.Tolerance;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.StepNcReader;
import org.junit.jupiter.api.Test;

/**
 * A tool cuts no deeper than its cutting edge: the 6 mm end mill of
 * src/test/resources/stepnc/steps-outside-profiles.stp mills a 6 mm deep pocket (#15) and a 5 mm
 * deep step (#12); the 6 mm drill of src/test/resources/org/fresa/toolpath/technology.stp drills a
 * 10 mm blind hole (#10 and #14, the workingsteps whose technology holds).
 */
class CuttingEdgeLengthTest {

    static final String SIX_MM_MILL = "#50= MILLING_TOOL_DIMENSION(6.000,$,$,15.0,0.0,$,$);";
    static final String SIX_MM_DRILL = "#32= MILLING_TOOL_DIMENSION(6.000,31.000,$,30.000,$,$,$);";

    static ToolpathPlanner.Plan millWithEdge(String edge) throws Exception {
        String part = Files.readString(StepsAndOutsideProfilesTest.PART);
        assertTrue(part.contains(SIX_MM_MILL));
        return plan(part.replace(SIX_MM_MILL, "#50= MILLING_TOOL_DIMENSION(6.000,$,$," + edge + ",0.0,$,$);"));
    }

    static ToolpathPlanner.Plan drillWithEdge(String edge) throws Exception {
        String part = Files.readString(CuttingDataTest.TECHNOLOGY);
        assertTrue(part.contains(SIX_MM_DRILL));
        return plan(part.replace(SIX_MM_DRILL, "#32= MILLING_TOOL_DIMENSION(6.000,31.000,$," + edge + ",$,$,$);"));
    }

    static ToolpathPlanner.Plan plan(String part) throws Exception {
        StepNcProgram program = StepNcReader.read(new StringReader(part), "edge.stp");
        return ToolpathPlanner.plan(program, Tolerance.DEFAULT);
    }

    @Test
    void aPocketOneMillimetreDeeperThanTheEdgeIsRefusedWithTheEdgeItNeeds() throws Exception {
        ToolpathPlanner.Plan p = millWithEdge("5.0");
        assertTrue(p.sectionOf(15).isEmpty(), "the 6 mm pocket was planned with a 5 mm edge");
        assertEquals(
                "the tool cuts 6 mm below the feature's top but its cutting edge is 5 mm long: its shank would rub"
                        + " the wall it has just cut; a tool with at least 6 mm of cutting edge cuts it",
                p.refusals().get(15L));
        assertTrue(
                p.problems()
                        .contains("workingstep 'WS POCKET WITH BOSSES' (#15): the tool cuts 6 mm below the feature's"
                                + " top but its cutting edge is 5 mm long: its shank would rub the wall it has just"
                                + " cut; a tool with at least 6 mm of cutting edge cuts it"),
                p.problems().toString());
        // the 5 mm step with the same tool: exactly at its edge, planned
        assertTrue(p.sectionOf(12).isPresent(), p.problems().toString());
    }

    @Test
    void aPocketExactlyAsDeepAsTheEdgeIsPlanned() throws Exception {
        ToolpathPlanner.Plan p = millWithEdge("6.0");
        assertTrue(p.sectionOf(15).isPresent(), p.problems().toString());
        assertFalse(p.refusals().containsKey(15L));
    }

    @Test
    void aHoleDeeperThanTheDrillsFlutesIsRefusedAndOneAsDeepIsDrilled() throws Exception {
        ToolpathPlanner.Plan shortDrill = drillWithEdge("9.000");
        for (long ws : new long[] {10, 14}) {
            assertTrue(shortDrill.sectionOf(ws).isEmpty(), "#" + ws + " was drilled 10 mm with 9 mm of flutes");
            assertEquals(
                    "the tool cuts 10 mm below the feature's top but its cutting edge is 9 mm long: its chips could"
                            + " not clear the hole; a tool with at least 10 mm of cutting edge cuts it",
                    shortDrill.refusals().get(ws));
        }
        ToolpathPlanner.Plan drill = drillWithEdge("10.000");
        assertTrue(drill.sectionOf(10).isPresent(), drill.problems().toString());
        assertTrue(drill.sectionOf(14).isPresent(), drill.problems().toString());
    }

    @Test
    void aToolWithoutAnEdgeLengthIsNotChecked() throws Exception {
        ToolpathPlanner.Plan p = millWithEdge("$");
        assertTrue(p.sectionOf(15).isPresent(), p.problems().toString());
        assertTrue(
                p.problems().stream().noneMatch(s -> s.contains("cutting edge")),
                p.problems().toString());
    }
}
