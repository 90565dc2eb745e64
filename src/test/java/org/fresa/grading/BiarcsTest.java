package org.fresa.grading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class BiarcsTest {

    /**
     * The grading's bound: biarcs within 0.005 mm of the exact affine image, checked by dense
     * sampling both ways. Points of the arcs are pulled back onto the base circle by the inverse
     * map, where the distance is exact, and scaled by the larger factor; points of the exact
     * ellipse are measured against the arcs.
     */
    @ParameterizedTest
    @CsvSource(textBlock = """
            30, 0, 360, 1.10, 0.90
            45, -10, 190, 1.0476, 1.1
            5, 20, 60, 0.8, 1.3
            800, 80, 95, 1.02, 1.06
            29.2, 180, 360, 0.9262, 0.9013
            """)
    void biarcsStayWithin5MicronsOfTheEllipse(double r, double fromDeg, double toDeg, double sx, double sy) {
        Arc2 arc = Arc2.ofAngles(new Vec2(3, 7), r, Math.toRadians(fromDeg), Math.toRadians(toDeg - fromDeg));
        GradingFrame frame = new GradingFrame(new Vec2(-2, 1), Vec2.ofAngle(Math.toRadians(80)));
        PantographMap map = new PantographMap(frame, sx, sy);
        EllipticArc e = EllipticArc.of(arc, map);
        List<Curve2> fit = Biarcs.of(e, 0.005);
        Contour base = new Contour(List.of(arc, arc.reversed()));
        double worst = 0;
        for (Curve2 c : fit) {
            for (int i = 0; i <= 2000; i++) {
                Vec2 back = map.inverse().apply(c.pointAt(i / 2000.0));
                worst = Math.max(worst, Math.max(sx, sy) * base.distanceTo(back));
            }
        }
        for (int i = 0; i <= 20000; i++) {
            Vec2 p = e.pointAt(i / 20000.0);
            double d = Double.POSITIVE_INFINITY;
            for (Curve2 c : fit) {
                d = Math.min(d, c.distanceTo(p));
            }
            worst = Math.max(worst, d);
        }
        assertTrue(worst <= 0.005, "deviation " + worst);
        assertEquals(e.start(), fit.get(0).start());
        assertEquals(e.end(), fit.get(fit.size() - 1).end());
        for (int i = 0; i + 1 < fit.size(); i++) {
            assertEquals(0, fit.get(i).end().distance(fit.get(i + 1).start()), 1e-9);
            assertTrue(fit.get(i).endTangent().dot(fit.get(i + 1).startTangent()) > Math.cos(1e-6));
        }
    }
}
