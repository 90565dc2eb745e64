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
 * A cutter whose corner is rounded clears a floor only under its flat end: passes farther apart
 * leave ridges between them, which the planner reports with the stepover that would not.
 */
class FloorRidgesTest {

    static final Path EXAMPLE1 = Path.of("samples/stepnc/iso14649-11-example1.stp");

    @Test
    void theRidgeIsWhereTheCornersOfTwoNeighbouringPassesMeet() {
        // the FDIS example 1's face: a 20 mm cutter with a 1.5 mm corner, passes 19 mm apart
        assertEquals(1.5 - Math.sqrt(1.5 * 1.5 - 1), ToolpathPlanner.floorRidgeMm(10, 1.5, 19), 1e-12);
        // a 10 mm bull-nose with a 4 mm corner, passes 5 mm apart
        assertEquals(4 - Math.sqrt(16 - 1.5 * 1.5), ToolpathPlanner.floorRidgeMm(5, 4, 5), 1e-12);
        // a ball end mill
        assertEquals(5 - Math.sqrt(25 - 1), ToolpathPlanner.floorRidgeMm(5, 5, 2), 1e-12);
        // passes within the flat end, and a flat end mill, leave none
        assertEquals(0, ToolpathPlanner.floorRidgeMm(10, 1.5, 17));
        assertEquals(0, ToolpathPlanner.floorRidgeMm(5, 0, 9.5));
        // passes farther apart than the corners reach leave the corner's height
        assertEquals(2, ToolpathPlanner.floorRidgeMm(5, 2, 20));
    }

    @Test
    void aFaceMilledWithABullNoseWhosePassesOutreachItsFlatIsReported() throws Exception {
        String text = Files.readString(EXAMPLE1)
                .replace(
                        "#30= MILLING_TOOL_DIMENSION(18.000, $,$, 30.0, 0.0, $,$);",
                        "#30= MILLING_TOOL_DIMENSION(18.000, $,$, 30.0, 4.0, $,$);");
        ToolpathPlanner.Plan p =
                ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "bull.stp"), Tolerance.DEFAULT);
        // passes 0.95 x 18 = 17.1 mm apart; the flat end is 10 mm across
        double ridge = 4 - Math.sqrt(16 - (17.1 / 2 - 5) * (17.1 / 2 - 5));
        assertTrue(
                p.problems().stream()
                        .anyMatch(x -> x.startsWith("workingstep 'WS FINISH PLANAR FACE1': passes up to 17.1 mm apart"
                                        + " leave ridges up to " + ToolpathPlanner.mm(ridge) + " mm high")
                                && x.contains("a flat end 10 mm across")),
                p.problems().toString());
        // the flat end mill of the file as it is leaves none
        ToolpathPlanner.Plan flat = ToolpathPlanner.plan(StepNcReader.read(EXAMPLE1), Tolerance.DEFAULT);
        assertTrue(
                flat.problems().stream().noneMatch(x -> x.contains("leave ridges")),
                flat.problems().toString());
    }
}
