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
 * A drilling-type tool wider than its hole (a boring bar, a reamer, a drill) was taken down the
 * hole as wide as it is, cutting the wall: it is refused with how far it reaches. GRIMA's testBoxy
 * bores its 30 and 24 mm holes with 32 and 26 mm bars.
 */
class HoleWallsTest {

    static final Path EXAMPLE1 = Path.of("samples/stepnc/iso14649-11-example1.stp");
    static final String REAMER = "#34= MILLING_TOOL_DIMENSION(22.000,$,$,40.0,$,$,$);";

    @Test
    void aReamerWiderThanItsHoleIsRefused() throws Exception {
        String text = Files.readString(EXAMPLE1);
        assertTrue(text.contains(REAMER));
        ToolpathPlanner.Plan p = ToolpathPlanner.plan(
                StepNcReader.read(new StringReader(text.replace(REAMER, REAMER.replace("22.000", "23.000"))), "w.stp"),
                Tolerance.DEFAULT);
        assertTrue(
                p.problems().stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS REAM HOLE1' (#")
                                && x.contains("the tool reaches 11.5 mm from the hole's axis: it would cut the 22 mm"
                                        + " hole's wall 0.5 mm deep")),
                p.problems().toString());
    }

    @Test
    void theToolsOfTheSampleFitTheirHole() throws Exception {
        ToolpathPlanner.Plan p = ToolpathPlanner.plan(StepNcReader.read(EXAMPLE1), Tolerance.DEFAULT);
        assertTrue(
                p.problems().stream().noneMatch(x -> x.contains("hole's wall")),
                p.problems().toString());
        assertEquals(5, p.planned(), p.problems().toString());
    }

    @Test
    void aDrillsPointReachesLessThanItsRadius() {
        var reach = HoleWalls.toolReach(10, false, 0, 6);
        assertEquals(0, reach.applyAsDouble(0));
        assertEquals(5, reach.applyAsDouble(3), 1e-12);
        assertEquals(10, reach.applyAsDouble(7));
        var ball = HoleWalls.toolReach(5, true, 0, 0);
        assertEquals(Math.sqrt(25 - 16), ball.applyAsDouble(1), 1e-12);
    }
}
