package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ProfileTest {

    static final Tolerance TOL = Tolerance.DEFAULT;

    /** Thesis eq. 22: R = sqrt(r^2 + (2 r tan(pi/n) / 2)^2) for a polygon around a circle of radius r. */
    @ParameterizedTest
    @CsvSource(textBlock = """
            6,  70, true,  40.41451884327381
            6,  70, false, 35
            4,  20, true,  14.142135623730951
            40, 80, true,  40.12368793931302
            """)
    void theVertexRadiusFollowsEquation22WhenCircumscribed(
            int n, double diameter, boolean circumscribed, double expected) {
        Profile.RegularPolygon p = new Profile.RegularPolygon(Vec2.ZERO, n, diameter, circumscribed);
        assertEquals(expected, p.vertexRadiusMm(), 1e-9);
        for (Curve2 c : p.contour(TOL).curves()) {
            double r = c.end().norm();
            assertTrue(Math.abs(r - expected) < 1e-9 || Math.abs(r - p.apothemMm()) < 1e-9, "vertex at " + r);
        }
    }

    @Test
    void anNgonHasItsBottomSideParallelToXAcrossTheMinusYAxis() {
        Profile.RegularPolygon hex = new Profile.RegularPolygon(new Vec2(5, 5), 6, 70, true);
        Ring r = hex.inset(0, TOL).orElseThrow();
        assertEquals(new Vec2(5, -30), r.start());
        Curve2 first = r.curves().get(0);
        assertEquals(-30, first.end().y(), 1e-9);
        assertEquals(6 * 35 * 35 * Math.tan(Math.PI / 6), hex.contour(TOL).area(), 1e-9);
    }

    @Test
    void aRoundedRectangleInsetIsARoundedRectangleWithTheRadiusReduced() {
        Profile.RoundedRectangle p = new Profile.RoundedRectangle(new Vec2(70, 70), 80, 50, 10);
        double w = 80 - 2 * 4;
        double h = 50 - 2 * 4;
        double area = w * h - (4 - Math.PI) * 6 * 6;
        assertEquals(
                area, new org.fresa.geom.Contour(p.inset(4, TOL).orElseThrow().curves()).area(), 1e-9);
        // beyond the corner radius the corners are sharp: no arcs left
        assertTrue(p.inset(12, TOL).orElseThrow().curves().stream().noneMatch(c -> c instanceof Arc2));
        // exactly half the width: a segment run there and back; beyond: nothing
        Ring collapsed = p.inset(25, TOL).orElseThrow();
        assertEquals(2 * 30, collapsed.length(), 1e-9);
        assertTrue(p.inset(25.001, TOL).isEmpty());
    }

    @Test
    void aCircleStaysTwoTrueHalfArcs() {
        Ring r = new Profile.Circle(new Vec2(1, 2), 15.5).inset(9, TOL).orElseThrow();
        assertEquals(2, r.curves().size());
        assertTrue(r.curves().stream().allMatch(c -> c instanceof Arc2 a && Math.abs(a.radius() - 6.5) < 1e-12));
        assertEquals(2 * Math.PI * 6.5, r.length(), 1e-9);
    }

    @Test
    void stepoverIsEquation21LimitedByTheCornerRule() {
        // thesis appendix C: D16 with STEP Modeler's overlap 3.2 mm = 0.2 D gives 12.8 mm
        assertEquals(12.8, Stepover.nominal(16, 3.2 / 16), 1e-12);
        // square corners: R (1 + sin 45 deg)
        assertEquals(9 * (1 + Math.sqrt(0.5)), Stepover.cornerLimit(18, Math.PI / 2), 1e-12);
        assertEquals(15.36396, Stepover.forLoops(17.1, 18, Math.PI / 2), 1e-5);
        assertEquals(17.1, Stepover.forLoops(17.1, 18, Math.PI), 1e-12);
    }
}
