package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.model.ToolpathSection;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.locationtech.jts.geom.Geometry;

/** General line/arc pockets through the pocket module's exact offsetter. */
class GeneralProfileTest {

    static final Tolerance TOL = Tolerance.DEFAULT;
    static final Tooling D8 = new Tooling(1, 8, 3000, 800, 300);

    static Vec2 v(double x, double y) {
        return new Vec2(x, y);
    }

    /** A "D": three sides and a half circle, convex. */
    static Contour dShape() {
        return Contour.of(
                List.of(
                        new Segment2(v(0, 0), v(40, 0)),
                        new Arc2(v(40, 20), v(40, 0), v(40, 40), true),
                        new Segment2(v(40, 40), v(0, 40)),
                        new Segment2(v(0, 40), v(0, 0))),
                TOL);
    }

    /** An L with a concave fillet of radius 6 in its inner corner. */
    static Contour lShape() {
        return Contour.of(
                List.of(
                        new Segment2(v(0, 0), v(60, 0)),
                        new Segment2(v(60, 0), v(60, 24)),
                        new Segment2(v(60, 24), v(30, 24)),
                        new Arc2(v(30, 30), v(30, 24), v(24, 30), false),
                        new Segment2(v(24, 30), v(24, 50)),
                        new Segment2(v(24, 50), v(0, 50)),
                        new Segment2(v(0, 50), v(0, 0))),
                TOL);
    }

    @ParameterizedTest(name = "{0} {1}")
    @CsvSource(textBlock = """
            D, CONTOUR_PARALLEL,      0.05
            D, CONTOUR_SPIRAL,        0.05
            D, BIDIRECTIONAL_CONTOUR, 0.05
            L, CONTOUR_PARALLEL,      0.05
            L, BIDIRECTIONAL_CONTOUR, 0.05
            L, CONTOUR_BIDIRECTIONAL, 0.05
            """)
    void generalPocketsAreClearedWithoutGouge(String shape, Strategy strategy, double maxUncutMm2) {
        Contour c = shape.equals("D") ? dShape() : lShape();
        Profile p = new Profile.General(c, ContourOffsetter.EXACT);
        assertTrue(shape.equals("D") == p.convex());
        ToolpathSection s =
                PocketMilling.section("ws", p, new Heights(30, 5, 0, -6), D8, MillingPlan.simple(strategy, 6, 3), TOL);
        Geometry pocket = Swept.polygon(c);
        double gouge = Swept.gouge(pocket, Swept.sweep(s, 4, 0));
        assertTrue(gouge < 1e-3, "gouge " + gouge);
        double uncut = Swept.uncutBeyondResidue(pocket, Swept.sweep(s, 4, -6 + 1e-9), 4);
        Geometry left = pocket.difference(Swept.sweep(s, 4, -6 + 1e-9))
                .difference(Swept.cornerResidue(pocket, 4).buffer(0.01));
        assertTrue(uncut <= maxUncutMm2, "uncut " + uncut + " around " + left.getEnvelopeInternal());
        assertFalse(s.moves().isEmpty());
    }
}
