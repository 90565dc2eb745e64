package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fresa.geom.Box2;
import org.fresa.geom.Vec2;
import org.junit.jupiter.api.Test;

/** The thesis's conventions one by one, with the figures of its Appendix C. */
class ThesisConventionsTest {

    static void near(Vec2 want, Vec2 got) {
        assertTrue(want.minus(got).norm() < 1e-9, () -> want + " vs " + got);
    }

    @Test
    void aSideIsDividedIntoToolDiametersWithTheRemainderLast() {
        List<Vec2> p = ThesisPaths.divide(new Vec2(110.8, 0), new Vec2(89.2, 0), 16);
        assertEquals(2, p.size());
        near(new Vec2(94.8, 0), p.get(0));
        near(new Vec2(89.2, 0), p.get(1));
        assertEquals(List.of(), ThesisPaths.divide(Vec2.ZERO, Vec2.ZERO, 16));
        // an exact multiple ends on its end point once
        assertEquals(
                5, ThesisPaths.divide(new Vec2(0, 10), new Vec2(0, 110), 20).size());
    }

    @Test
    void layersStartAtTheFaceAndEndAtTheDepth() {
        assertEquals(List.of(0.0, 2.0, 4.0, 6.0, 8.0, 10.0), ThesisPaths.layers(10, 2));
        List<Double> l = ThesisPaths.layers(10, 1.6);
        assertEquals(8, l.size());
        assertEquals(10.0, l.get(7));
        assertEquals(11, ThesisPaths.layers(10, 1).size());
    }

    @Test
    void theHundredMillimetreHoleIsThreeFortyGonsFromTheirBottomSideWithoutTheCentre() {
        // 100 mm hole, 20 mm cutter, overlap 4 mm: apothems 39.846, 23.846, 7.846 (under the 10 mm radius)
        List<Vec2> p = ThesisPaths.circleContours(50, 20, 16);
        assertEquals(3 * 41, p.size());
        double r = (50 * Math.cos(Math.PI / 40) - 10) / Math.cos(Math.PI / 40);
        assertEquals(39.969, r, 5e-4);
        near(new Vec2(r * Math.cos(Math.toRadians(265.5)), r * Math.sin(Math.toRadians(265.5))), p.get(0));
        // Appendix C point 2300 (the Tricept's), the 33rd point of the first polygon
        near(new Vec2(r * Math.cos(Math.toRadians(193.5)), r * Math.sin(Math.toRadians(193.5))), p.get(32));
        // a cutter as wide as the hole: the centre alone
        assertEquals(List.of(Vec2.ZERO), ThesisPaths.circleContours(5, 10, 8));
    }

    @Test
    void aPocketsContoursRunCounterClockwiseFromTheBottomLeftAndEndAtTheCentreOnlyIfItIsUncut() {
        // example 2's top pocket (140 x 140, 16 mm cutter, stepover 12.8): 5 contours, 4 divided links, centre
        List<Vec2> top = ThesisPaths.rectangleContours(70, 70, 16, 12.8);
        near(new Vec2(-62, -62), top.get(0));
        near(new Vec2(-46, -62), top.get(1));
        assertEquals(105 + 4 + 1, top.size());
        near(Vec2.ZERO, top.get(top.size() - 1));
        near(new Vec2(-10.8, -10.8), top.get(top.size() - 2));
        // the front pocket (140 x 50): 2 contours, the second 8.4 mm high covers its centre
        List<Vec2> front = ThesisPaths.rectangleContours(70, 25, 16, 12.8);
        assertEquals(23 + 2 + 16, front.size());
        near(new Vec2(-49.2, -4.2), front.get(front.size() - 1));
        // point 1050: the second contour's top right corner, the 33rd point of the layer
        near(new Vec2(49.2, 4.2), front.get(32));
    }

    @Test
    void aFaceIsMilledBidirectionallyFromItsFarSide() {
        // the thesis's part 1: a 100 x 120 face, 20 mm cutter, overlap 5 mm, course along y
        List<Vec2> p = ThesisPaths.facePasses(new Box2(0, 0, 100, 120), true, 20, 15);
        near(new Vec2(90, 10), p.get(0));
        near(new Vec2(90, 110), p.get(5));
        near(new Vec2(75, 110), p.get(6));
        near(new Vec2(10, 110), p.get(p.size() - 1));
    }
}
