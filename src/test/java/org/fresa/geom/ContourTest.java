package org.fresa.geom;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class ContourTest {

    static final Tolerance TOL = Tolerance.DEFAULT;

    /** A 100 x 60 rectangle with corner radius 10, counter-clockwise, as lines and quarter arcs. */
    static Contour roundedRectangle() {
        double w = 100;
        double h = 60;
        double r = 10;
        return Contour.of(
                List.of(
                        Segment2.of(r, 0, w - r, 0),
                        Arc2.ccw(Vec2.of(w - r, r), Vec2.of(w - r, 0), Vec2.of(w, r), TOL),
                        Segment2.of(w, r, w, h - r),
                        Arc2.ccw(Vec2.of(w - r, h - r), Vec2.of(w, h - r), Vec2.of(w - r, h), TOL),
                        Segment2.of(w - r, h, r, h),
                        Arc2.ccw(Vec2.of(r, h - r), Vec2.of(r, h), Vec2.of(0, h - r), TOL),
                        Segment2.of(0, h - r, 0, r),
                        Arc2.ccw(Vec2.of(r, r), Vec2.of(0, r), Vec2.of(r, 0), TOL)),
                TOL);
    }

    @Test
    void areaOfRoundedRectangleIsExact() {
        Contour c = roundedRectangle();
        double expected = 100 * 60 - (4 - Math.PI) * 100;
        assertAll(
                () -> assertEquals(expected, c.signedArea(), 1e-9),
                () -> assertTrue(c.isCcw()),
                () -> assertEquals(-expected, c.reversed().signedArea(), 1e-9),
                () -> assertEquals(2 * (80 + 40) + 2 * Math.PI * 10, c.length(), 1e-9));
    }

    @Test
    void fullCircleAreaAndBounds() {
        Contour c = new Contour(List.of(Arc2.circle(Vec2.of(5, -3), 2, false)));
        assertAll(
                () -> assertEquals(-Math.PI * 4, c.signedArea(), 1e-12),
                () -> assertEquals(new Box2(3, -5, 7, -1), c.bounds()));
    }

    @Test
    void containmentRespectsArcsAtTheCorners() {
        Contour c = roundedRectangle();
        assertAll(
                () -> assertTrue(c.contains(Vec2.of(50, 30), TOL)),
                () -> assertFalse(c.contains(Vec2.of(0.5, 0.5), TOL), "outside the rounded corner"),
                () -> assertTrue(c.contains(Vec2.of(3, 3), TOL), "inside the rounded corner"),
                () -> assertFalse(c.contains(Vec2.of(50, 0), TOL), "on the contour is not inside"),
                () -> assertFalse(c.contains(Vec2.of(150, 30), TOL)));
    }

    @Test
    void containmentAgreesWithDistanceToCircleForRandomPoints() {
        Random rnd = new Random(42);
        Contour c = new Contour(List.of(Arc2.circle(Vec2.of(0, 0), 10, true)));
        for (int i = 0; i < 2000; i++) {
            Vec2 p = Vec2.of(rnd.nextDouble() * 30 - 15, rnd.nextDouble() * 30 - 15);
            if (Math.abs(p.norm() - 10) > 1e-6) {
                assertEquals(p.norm() < 10, c.contains(p, TOL), p.toString());
            }
        }
    }

    @Test
    void openChainIsRefusedWithTheGap() {
        IllegalArgumentException e = assertThrows(
                IllegalArgumentException.class,
                () -> Contour.of(
                        List.of(Segment2.of(0, 0, 10, 0), Segment2.of(10, 0, 10, 10), Segment2.of(10, 10, 0, 0.5)),
                        TOL));
        assertTrue(e.getMessage().contains("gap 0.5"), e.getMessage());
    }

    @Test
    void arcSweepFollowsItsSense() {
        Arc2 quarter = Arc2.ccw(Vec2.ZERO, Vec2.of(1, 0), Vec2.of(0, 1), TOL);
        assertAll(
                () -> assertEquals(Math.PI / 2, quarter.sweepRad(), 1e-15),
                () -> assertEquals(-Math.PI / 2, quarter.reversed().sweepRad(), 1e-15),
                () -> assertTrue(Vec2.of(0, 1).eq(quarter.startTangent(), TOL)),
                () -> assertTrue(quarter.containsAngle(Math.PI / 4)),
                () -> assertFalse(quarter.containsAngle(Math.PI)));
    }

    @Test
    void nanIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> Vec2.of(Double.NaN, 0));
        assertThrows(IllegalArgumentException.class, () -> Vec3.of(0, Double.POSITIVE_INFINITY, 0));
    }
}
