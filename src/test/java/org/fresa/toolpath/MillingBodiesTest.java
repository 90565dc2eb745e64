package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A milling operation takes only a tool that cuts sideways and on its end into a feature: the
 * 10 mm end mill of src/test/resources/stepnc/slots-profiles.stp, which mills a rounded-U, a tee's
 * stem and a square-U, written as another body, is refused on all three with the reason; a
 * tapered end mill whose flank does not lean mills as an end mill (ISO 14649-11's example 1 mills
 * its pockets with one), one whose flank leans is refused.
 */
class MillingBodiesTest {

    static final String END_MILL = "#47= ENDMILL(#48,4,.RIGHT.,.F.,$);";

    @ParameterizedTest
    @CsvSource({
        "TWIST_DRILL, a TWIST_DRILL does not mill a slot: it does not cut sideways",
        "TAP, a TAP does not mill a slot: it does not cut sideways",
        "SIDE_MILL, a SIDE_MILL does not mill a slot: it does not cut sideways",
        "BORING_TOOL, a BORING_TOOL does not mill a slot",
        "T_SLOT_MILL, a T_SLOT_MILL does not mill a slot: it mills a tee slot's cross bar only",
        "DOVETAIL_MILL, a DOVETAIL_MILL does not mill a slot: it mills a dovetail's undercut",
    })
    void aBodyThatDoesNotMillSidewaysIsRefusedWhereTheEndMillWorked(String body, String why) throws Exception {
        String part = Files.readString(SlotProfilesTest.PART);
        assertTrue(part.contains(END_MILL));
        ToolpathPlanner.Plan p =
                SlotProfilesTest.planText(part.replace(END_MILL, "#47= " + body + "(#48,4,.RIGHT.,.F.,$);"));
        for (String ws : new String[] {"WS ROUND U FLAT", "WS SQUARE U ENDS"}) {
            assertTrue(SlotProfilesTest.problemOf(p, ws).contains(why), ws + ": " + p.problems());
        }
        // the tee's stem too (the T-slot mill is at home in the tee, where it meets the stem's width)
        if (!body.startsWith("T_SLOT_MILL")) {
            assertTrue(
                    SlotProfilesTest.problemOf(p, "WS TEE STEM").contains(why),
                    p.problems().toString());
        }
        // the workingsteps of the other tools are planned
        assertEquals(
                body.startsWith("T_SLOT_MILL") ? 3 : 3,
                p.planned(),
                p.problems().toString());
    }

    @ParameterizedTest
    @CsvSource({"$, 6", "0.000, 6", "5.000, 3"})
    void aTaperedEndMillMillsAsAnEndMillUnlessItsFlankLeans(String lean, int planned) throws Exception {
        String part = Files.readString(SlotProfilesTest.PART)
                .replace(END_MILL, "#47= TAPERED_ENDMILL(#48,4,.RIGHT.,.F.,$,$);")
                .replace(
                        "#48= MILLING_TOOL_DIMENSION(10.000,$,$,25.0,0.0,$,$);",
                        "#48= MILLING_TOOL_DIMENSION(10.000,$," + lean + ",25.0,0.0,$,$);");
        ToolpathPlanner.Plan p = SlotProfilesTest.planText(part);
        assertEquals(planned, p.planned(), p.problems().toString());
        if (planned < 6) {
            assertTrue(
                    SlotProfilesTest.problemOf(p, "WS SQUARE U ENDS")
                            .contains("the TAPERED_ENDMILL's flank leans 5 deg (tool_circumference_angle): it would"
                                    + " cut the slot's upright walls leaning"),
                    p.problems().toString());
        }
    }

    @ParameterizedTest
    @CsvSource({"SIDE_MILL", "T_SLOT_MILL", "DOVETAIL_MILL", "THREAD_MILL", "FACEMILL"})
    void aDrillingOperationWithABodyThatCannotGoDownAHoleIsRefused(String body) throws Exception {
        java.nio.file.Path holes = java.nio.file.Path.of("src/test/resources/org/fresa/toolpath/holes.stp");
        String drill = "#31= TWIST_DRILL(#32,2,.RIGHT.,.F.,$);";
        String part = Files.readString(holes);
        assertTrue(part.contains(drill));
        ToolpathPlanner.Plan p =
                SlotProfilesTest.planText(part.replace(drill, "#31= " + body + "(#32,2,.RIGHT.,.F.,$);"));
        for (String ws : new String[] {"WS THROUGH NO DEPTH", "WS BLIND"}) {
            assertTrue(
                    SlotProfilesTest.problemOf(p, ws)
                            .contains("a " + body + " does not go down a hole along its axis: a DRILLING takes a"
                                    + " drill, reamer, boring tool, tap, countersink or counterbore"),
                    ws + ": " + p.problems());
        }
        assertEquals(2, p.planned(), p.problems().toString());
    }
}
