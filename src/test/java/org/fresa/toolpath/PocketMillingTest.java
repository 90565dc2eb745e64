package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.locationtech.jts.geom.Geometry;

class PocketMillingTest {

    static final Tolerance TOL = Tolerance.DEFAULT;
    static final Tooling D18 = new Tooling(1, 18, 1200, 2400, 600);

    static Profile profile(String name) {
        return switch (name) {
            // example 1's pocket: x 45..95, y 30..110, corner radius 10
            case "rect" -> new Profile.RoundedRectangle(new Vec2(70, 70), 50, 80, 10);
            case "sharp" -> new Profile.RoundedRectangle(new Vec2(0, 0), 60, 45, 0);
            case "circle" -> new Profile.Circle(new Vec2(10, -5), 31);
            case "hexagon" -> new Profile.RegularPolygon(new Vec2(0, 0), 6, 70, true);
            case "triangle" -> new Profile.RegularPolygon(new Vec2(0, 0), 3, 90, false);
            default -> throw new IllegalArgumentException(name);
        };
    }

    /** Largest uncut area accepted beyond the corner residue: the parallel strategies scallop round walls. */
    @ParameterizedTest(name = "{0} {1} overlap {2}")
    @CsvSource(textBlock = """
            rect,     CONTOUR_PARALLEL,      0.1,  0.05
            rect,     CONTOUR_SPIRAL,        0.1,  0.05
            rect,     BIDIRECTIONAL,         0.1,  0.05
            rect,     UNIDIRECTIONAL,        0.1,  0.05
            rect,     BIDIRECTIONAL_CONTOUR, 0.1,  0.05
            rect,     CONTOUR_BIDIRECTIONAL, 0.1,  0.05
            sharp,    CONTOUR_PARALLEL,      0.0,  0.05
            sharp,    CONTOUR_SPIRAL,        0.0,  0.05
            sharp,    BIDIRECTIONAL,         0.0,  0.05
            sharp,    CONTOUR_BIDIRECTIONAL, 0.0,  0.05
            circle,   CONTOUR_PARALLEL,      0.2,  0.05
            circle,   CONTOUR_SPIRAL,        0.2,  0.05
            circle,   BIDIRECTIONAL_CONTOUR, 0.2,  0.05
            circle,   CONTOUR_BIDIRECTIONAL, 0.2,  0.05
            hexagon,  CONTOUR_PARALLEL,      0.0,  0.05
            hexagon,  CONTOUR_SPIRAL,        0.0,  0.05
            hexagon,  BIDIRECTIONAL_CONTOUR, 0.0,  0.05
            hexagon,  CONTOUR_BIDIRECTIONAL, 0.0,  0.05
            triangle, CONTOUR_PARALLEL,      0.0,  0.05
            triangle, CONTOUR_SPIRAL,        0.0,  0.05
            triangle, BIDIRECTIONAL_CONTOUR, 0.0,  0.05
            """)
    void theFloorIsClearedExceptTheCornerResidueAndTheWallsAreNeverCut(
            String shape, Strategy strategy, double overlap, double maxUncutMm2) {
        Profile p = profile(shape);
        Heights h = new Heights(50, 5, 0, -12);
        MillingPlan plan = MillingPlan.simple(strategy, Stepover.nominal(18, overlap), 5);
        ToolpathSection s = PocketMilling.section("ws", p, h, D18, plan, TOL);
        Geometry pocket = Swept.polygon(p.contour(TOL));
        Geometry floor = Swept.sweep(s, 9, -12);
        double uncut = Swept.uncutBeyondResidue(pocket, floor, 9);
        if (strategy == Strategy.UNIDIRECTIONAL || strategy == Strategy.BIDIRECTIONAL) {
            // parallel passes alone leave scallops on walls they end against: at most
            // R - sqrt(R^2 - (d/2)^2) deep for a wall square to them; ISO pairs them with a contour for that
            double d = plan.stepoverMm();
            double band = 9 - Math.sqrt(81 - d * d / 4) + 0.01;
            Geometry inner = pocket.buffer(-band, Swept.QUADRANT_SEGMENTS);
            uncut = Swept.uncutBeyondResidue(inner, floor.intersection(inner), 9 - band);
        }
        assertTrue(uncut <= maxUncutMm2, "uncut beyond the corner residue: " + uncut + " mm^2");
        Geometry all = Swept.sweep(s, 9, 0);
        assertTrue(Swept.gouge(pocket, all) < 1e-3, "gouge " + Swept.gouge(pocket, all));
        assertTrue(lowestZ(s) >= -12 - 1e-9);
        assertEquals(-12, lowestZ(s), 1e-9);
    }

    /** Cutting direction: every loop (corner arcs, helix entries) turns the way the plan says. */
    @ParameterizedTest(name = "clockwise {0}")
    @CsvSource({"true", "false"})
    void loopsTurnInThePlansRotationDirection(boolean clockwise) {
        Profile p = profile("rect");
        MillingPlan simple = MillingPlan.simple(Strategy.CONTOUR_PARALLEL, Stepover.nominal(18, 0.1), 5);
        MillingPlan plan = new MillingPlan(
                simple.strategy(),
                simple.stepoverMm(),
                simple.axialDepthMm(),
                0,
                0,
                simple.feedDirection(),
                clockwise,
                new Approach.Helix(3, 5),
                false);
        ToolpathSection s = PocketMilling.section("ws", p, new Heights(50, 5, 0, -12), D18, plan, TOL);
        List<Move.Circular> arcs = s.moves().stream()
                .filter(m -> m instanceof Move.Circular)
                .map(m -> (Move.Circular) m)
                .toList();
        assertTrue(arcs.size() >= 4, "corner arcs expected: " + arcs.size());
        for (Move.Circular c : arcs) {
            assertEquals(1, c.normal().z(), 1e-12);
            assertEquals(!clockwise, c.ccw(), c.toString());
        }
    }

    /**
     * Center milling: a slot-shaped pocket as wide as the tool (60 x 18, ends of radius 9,
     * D18) is cut by one pass along its centre line, which clears it without touching the walls.
     */
    @org.junit.jupiter.api.Test
    void centerMillingASlotAsWideAsTheToolRunsAlongItsCentreLine() {
        Profile p = new Profile.RoundedRectangle(new Vec2(0, 0), 60, 18, 9);
        ToolpathSection s = PocketMilling.section(
                "ws", p, new Heights(50, 5, 0, -6), D18, MillingPlan.simple(Strategy.CENTER_MILLING, 9, 3), TOL);
        for (Move m : s.moves()) {
            if (m.end().z() < 0) {
                assertEquals(0, m.end().y(), 1e-9, m.toString());
                assertTrue(Math.abs(m.end().x()) <= 21 + 1e-9, m.toString());
            }
        }
        Geometry pocket = Swept.polygon(p.contour(TOL));
        Geometry floor = Swept.sweep(s, 9, -6);
        assertTrue(
                pocket.difference(floor).getArea() < 0.05,
                "uncut " + pocket.difference(floor).getArea());
        assertTrue(Swept.gouge(pocket, Swept.sweep(s, 9, 0)) < 1e-3);
        assertEquals(-6, lowestZ(s), 1e-9);
    }

    static double lowestZ(ToolpathSection s) {
        double z = s.start().z();
        for (Move m : s.moves()) {
            z = Math.min(z, m.end().z());
        }
        return z;
    }
}
