package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.fresa.geom.Tolerance;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.StepNcReader;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;

/**
 * Square-U slots on linear paths (ISO 14649-10 slot): milled as the rectangle they sweep, the
 * tool inside the slot's volume, its floor cleared where the tool reaches.
 */
class SlotMillingTest {

    static final Path SLOTS = Path.of("src/test/resources/stepnc/slots-square-u.stp");

    private static Geometry rectangle(double x0, double y0, double x1, double y1) {
        return Swept.GF.createPolygon(new Coordinate[] {
            new Coordinate(x0, y0),
            new Coordinate(x1, y0),
            new Coordinate(x1, y1),
            new Coordinate(x0, y1),
            new Coordinate(x0, y0)
        });
    }

    private static void check(ToolpathSection s, Geometry slot, double depth, double radius) {
        double floor = Double.POSITIVE_INFINITY;
        for (Move m : s.moves()) {
            floor = Math.min(floor, m.end().z());
        }
        assertEquals(-depth, floor, 1e-9, s.label() + ": the floor");
        // everything the cutter sweeps below the top stays in the slot; at the floor it clears the slot
        Geometry below = Swept.sweep(s, radius, 0);
        assertTrue(
                Swept.gouge(slot, below) < 1e-6,
                s.label() + " leaves the slot by " + Swept.gouge(slot, below) + " mm2");
        Geometry atFloor = Swept.sweep(s, radius, -depth);
        assertTrue(
                Swept.uncutBeyondResidue(slot, atFloor, radius) < 1e-3,
                s.label() + " leaves " + Swept.uncutBeyondResidue(slot, atFloor, radius) + " mm2 of floor");
    }

    @Test
    void squareUSlotsAreMilledWithinTheirVolumeAndTheirFloorsCleared() throws Exception {
        ToolpathPlanner.Plan plan = ToolpathPlanner.plan(StepNcReader.read(SLOTS), Tolerance.DEFAULT);
        assertEquals(2, plan.planned(), plan.problems().toString());
        // slot 1: x 10..70, y 12..28, 6 deep, wider than the 10 mm cutter
        check(plan.toolpath().sections().get(0), rectangle(10, 12, 70, 28), 6, 5);
        // slot 2: x 85..95, y 10..50, 4 deep, as wide as the cutter: one pass along its middle per layer
        ToolpathSection s2 = plan.toolpath().sections().get(1);
        check(s2, rectangle(85, 10, 95, 50), 4, 5);
        for (Move m : s2.moves()) {
            if (m.end().z() < 0) {
                assertEquals(90, m.end().x(), 1e-9);
            }
        }
    }

    @Test
    void aSlotTheCutterCannotEnterIsRefusedWithTheReason() throws Exception {
        String text = java.nio.file.Files.readString(SLOTS)
                .replace("#28= SQUARE_U_PROFILE($,10.000,$,$,$,$);", "#28= SQUARE_U_PROFILE($,8.000,$,$,$,$);")
                .replace(
                        "#24= LINEAR_PATH($,60.000,#55);",
                        "#24= LINEAR_PATH($,60.000,#55);\n#99= VEE_PROFILE($,$,$,$);")
                .replace("#25= SQUARE_U_PROFILE($,16.000,$,$,$,$);", "#25= VEE_PROFILE($,$,90.000,55.000);");
        ToolpathPlanner.Plan plan =
                ToolpathPlanner.plan(StepNcReader.read(new java.io.StringReader(text), "t.stp"), Tolerance.DEFAULT);
        assertEquals(0, plan.planned());
        assertTrue(
                plan.problems().get(0).contains("the vee leans by 10 deg"),
                plan.problems().toString());
        assertTrue(
                plan.problems().get(1).contains("SLOT2")
                        && plan.problems().get(1).contains("the tool (10 mm) is wider than the slot (8 mm)"),
                plan.problems().toString());
    }
}
