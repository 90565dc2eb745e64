package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fresa.geom.Contour;
import org.fresa.geom.Tolerance;
import org.fresa.model.Toolpath;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Geometry;

/**
 * The men's size-40 sole outline (16 elements, near-tangent junctions, one arc of
 * R 750). Its two near-tangent reflex corners at the ends of the 11 mm heel line used to count as
 * a division at t = 5.5 (their sectors read at t = 0, where a zero-radius arc has no extent), so
 * the recognition reported FURO MAXIMO 11 mm on a 90 mm sole.
 */
class SoleOutlineRecognitionTest {

    static final Tolerance TOL = new Tolerance(1e-4, 1e-9);

    @Test
    void theSoleDividesAtTheWaistAndItsLargestHoleIsItsInscribedCircle() throws Exception {
        Contour sole = RegionPocketTest.read("samples/sole/men40.contour").get(0);
        Recognition.Result r = Recognition.of(PocketProfile.fromContours(List.of(sole.ccw())));
        double inradius = RegionOffsetter.inradius(List.of(sole.ccw()), TOL);
        assertAll(
                () -> assertEquals(2, r.root().children().size(), "heel and forefoot"),
                () -> assertEquals(24.7345, r.root().splitT(), 1e-3),
                () -> assertEquals(2 * inradius, r.maxHoleDiameterMm(), 2e-3),
                () -> assertEquals(89.299, r.maxHoleDiameterMm(), 1e-2));
    }

    @Test
    void theDefaultPassesClearTheSoleCavityWithinItsOutline() throws Exception {
        Contour sole = RegionPocketTest.read("samples/sole/men40.contour").get(0);
        Recognition.Result r = Recognition.of(PocketProfile.fromContours(List.of(sole.ccw())));
        PocketTechnology t = new PocketTechnology(25, 0.6, 0.02, 0, -4, 4, 2000, 280, 250);
        PocketPlan plan = PassPlanner.plan(r, t, false);
        Toolpath path = PocketToolpath.of(plan, true);
        Geometry swept = PocketCoverageTest.swept(path, -4, 12.5);
        Geometry wall = RegionPocketTest.polygon(sole);
        double uncut =
                wall.buffer(-12.5, 64).buffer(12.5 - 0.01, 64).difference(swept).getArea();
        double outside = swept.difference(wall.buffer(0.01, 64)).getArea();
        System.out.printf(
                java.util.Locale.ROOT, "men40 recognition passes: uncut %.5f mm2, outside %.5f mm2%n", uncut, outside);
        assertTrue(outside < 1e-3, "beyond the outline " + outside + " mm2");
        assertTrue(uncut < 1e-3, "uncut " + uncut + " mm2");
    }
}
