package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Geometry;

class ApproachAndHoleTest {

    static final Tolerance TOL = Tolerance.DEFAULT;
    static final Tooling D10 = new Tooling(2, 10, 3000, 800, 300);

    static double lowest(ToolpathSection s) {
        return s.moves().stream().mapToDouble(m -> m.end().z()).min().orElseThrow();
    }

    static long count(ToolpathSection s, Class<? extends Move> kind) {
        return s.moves().stream().filter(kind::isInstance).count();
    }

    @Test
    void rampsAndHelicesEnterEachLayerInsideThePocketWithinTheirAngle() {
        Profile p = new Profile.RoundedRectangle(Vec2.ZERO, 60, 40, 5);
        Geometry pocket = Swept.polygon(p.contour(TOL));
        for (Approach a : List.of(new Approach.Ramp(3), new Approach.Helix(4, 3))) {
            MillingPlan plan =
                    MillingPlan.simple(Strategy.CONTOUR_PARALLEL, 8, 4).withApproach(a);
            ToolpathSection s = PocketMilling.section("ws", p, new Heights(30, 5, 0, -8), D10, plan, TOL);
            assertTrue(Swept.gouge(pocket, Swept.sweep(s, 5, 0.5)) < 1e-3, a + " gouges");
            assertEquals(-8, lowest(s), 1e-12);
            Vec3 at = s.start();
            for (Move m : s.moves()) {
                if (!(m instanceof Move.Rapid) && m.end().z() < at.z() - 1e-9) {
                    double drop = at.z() - m.end().z();
                    double run = m instanceof Move.Circular c
                            ? org.fresa.model.ArcGeometry.of(at, c).lengthMm()
                            : at.xy().distance(m.end().xy());
                    assertTrue(Math.toDegrees(Math.atan2(drop, run)) <= 3 + 1e-6, a + ": entry at " + drop + "/" + run);
                }
                at = m.end();
            }
        }
        MillingPlan helix = MillingPlan.simple(Strategy.CONTOUR_PARALLEL, 8, 4).withApproach(new Approach.Helix(4, 3));
        ToolpathSection s = PocketMilling.section("ws", p, new Heights(30, 5, 0, -8), D10, helix, TOL);
        assertTrue(count(s, Move.Circular.class) > 0);
    }

    @Test
    void roughingLeavesTheAllowancesAndTheFinishPassRemovesThem() {
        Profile p = new Profile.Circle(Vec2.ZERO, 20);
        Geometry pocket = Swept.polygon(p.contour(TOL));
        MillingPlan rough = MillingPlan.simple(Strategy.CONTOUR_SPIRAL, 6, 5).withAllowances(1, 0.5, false);
        ToolpathSection r = PocketMilling.section("ws", p, new Heights(30, 5, 0, -10), D10, rough, TOL);
        assertEquals(-9.5, lowest(r), 1e-12);
        Geometry shrunk = pocket.buffer(-1 + 0.01, Swept.QUADRANT_SEGMENTS);
        assertTrue(Swept.gouge(shrunk, Swept.sweep(r, 5, 0)) < 1e-3, "the side allowance was cut");
        ToolpathSection f = PocketMilling.section(
                "ws", p, new Heights(30, 5, 0, -10), D10, rough.withAllowances(1, 0.5, true), TOL);
        assertEquals(-10, lowest(f), 1e-12);
        Geometry floor = Swept.sweep(f, 5, -10 + 1e-9);
        assertTrue(Swept.uncutBeyondResidue(pocket, floor, 5) < 0.05);
    }

    @Test
    void aSpiralLayerIsOneContinuousCut() {
        Profile p = new Profile.RegularPolygon(Vec2.ZERO, 6, 80, true);
        List<Pass> passes = PlanarPasses.of(Strategy.CONTOUR_SPIRAL, p, 5, 8, Vec2.UNIT_X, true, TOL);
        assertEquals(1, passes.size());
        Vec2 at = passes.get(0).start();
        for (org.fresa.geom.Curve2 c : passes.get(0).curves()) {
            assertTrue(c.start().distance(at) < 1e-9);
            at = c.end();
        }
    }

    @Test
    void aHoleUpToTwiceTheToolIsMilledOnAHelixAndClearedWithoutGouge() {
        Heights h = new Heights(20, 5, 0, -12);
        ToolpathSection s = HoleMaking.mill("hole", new Vec2(3, 4), 18, h, D10, 2, false, TOL);
        Geometry hole = Swept.polygon(new Profile.Circle(new Vec2(3, 4), 9).contour(TOL));
        Geometry floor = Swept.sweep(s, 5, -12 + 1e-9);
        assertTrue(hole.buffer(-0.005).difference(floor).getArea() < 1e-6);
        assertTrue(Swept.gouge(hole, Swept.sweep(s, 5, 0.5)) < 1e-3);
        Move.Circular helix = (Move.Circular) s.moves().stream()
                .filter(m -> m instanceof Move.Circular)
                .findFirst()
                .orElseThrow();
        // 13 mm from 1 mm above the top to -12, no steeper than 3 deg on a radius of 4 mm:
        // 2 pi 4 tan(3 deg) = 1.317 mm a turn, 10 turns, the first 9 extra
        assertEquals(9, helix.turns());
        assertEquals(-12, lowest(s), 1e-12);
    }

    @Test
    void peckDrillingReturnsToTheRetractPlaneBetweenPecksAndReachesTheBottom() {
        Heights h = new Heights(20, 5, 0, -25);
        ToolpathSection s = HoleMaking.drill("drill", new Vec2(20, 60), h, D10, 10, false);
        assertEquals(-25, lowest(s), 1e-12);
        List<Double> feedEnds = s.moves().stream()
                .filter(m -> m instanceof Move.Linear)
                .map(m -> m.end().z())
                .toList();
        assertEquals(List.of(-10.0, -20.0, -25.0), feedEnds);
        ToolpathSection ream = HoleMaking.drill("ream", new Vec2(20, 60), h, D10, 0, true);
        assertEquals(
                List.of(-25.0, 5.0),
                ream.moves().stream()
                        .filter(m -> m instanceof Move.Linear)
                        .map(m -> m.end().z())
                        .toList());
    }

    @Test
    void aSectionOnASideFaceHasItsArcsAboutTheFacesAxis() {
        ToolpathSection local = HoleMaking.mill("side", Vec2.ZERO, 18, new Heights(20, 5, 0, -6), D10, 2, false, TOL);
        Transform3 side = Transform3.ofFrame(new Vec3(60, 0, 150), new Vec3(0, -1, 0), new Vec3(1, 0, 0));
        ToolpathSection placed = Placing.place(local, side);
        assertEquals(new Vec3(0, -1, 0), placed.toolAxis());
        for (Move m : placed.moves()) {
            if (m instanceof Move.Circular c) {
                assertEquals(new Vec3(0, -1, 0), c.normal());
                // on the hole's axis, which runs along -Y through (60, *, 150)
                assertEquals(60, c.center().x(), 1e-9);
                assertEquals(150, c.center().z(), 1e-9);
            }
            assertTrue(
                    m.end().y() >= -20 - 1e-9 && m.end().y() <= 6 + 1e-9,
                    "y " + m.end().y());
        }
    }
}
