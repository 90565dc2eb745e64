package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.operation.buffer.BufferOp;
import org.locationtech.jts.operation.buffer.BufferParameters;

class LineArcOffsetterTest {

    static final Tolerance TOL = Tolerance.DEFAULT;

    static Contour rect(double w, double h) {
        return Contour.polygon(List.of(Vec2.of(0, 0), Vec2.of(w, 0), Vec2.of(w, h), Vec2.of(0, h)));
    }

    static void everyPointIsAtTheDistance(Contour original, List<Contour> result, double t) {
        for (Contour c : result) {
            for (Curve2 cv : c.curves()) {
                for (int k = 0; k <= 16; k++) {
                    Vec2 p = cv.pointAt(k / 16.0);
                    assertEquals(Math.abs(t), original.distanceTo(p), 1e-9, () -> "point " + p + " of " + cv);
                }
            }
        }
    }

    @ParameterizedTest(name = "rectangle {0} x {1} offset by {2}")
    @CsvSource(textBlock = """
            100, 50, 1
            100, 50, 7.5
            100, 50, -1
            100, 50, -20
            10, 10, 0.001
            """)
    void rectangleOffsetAreaIsAnalytic(double w, double h, double t) {
        for (Contour c : List.of(rect(w, h), rect(w, h).reversed())) {
            List<Contour> r = LineArcOffsetter.offset(c, t, TOL);
            assertEquals(1, r.size());
            double want = t > 0 ? w * h + 2 * t * (w + h) + Math.PI * t * t : (w + 2 * t) * (h + 2 * t);
            assertEquals(want, r.get(0).area(), 1e-9 * want);
            assertEquals(c.isCcw(), r.get(0).isCcw());
            everyPointIsAtTheDistance(c, r, t);
        }
    }

    @ParameterizedTest(name = "circle r {0} offset by {1}")
    @CsvSource(textBlock = """
            15, 1
            15, -1
            15, -14.5
            0.8, 2
            """)
    void circleOffsetIsACircleOfRadiusRPlusT(double r, double t) {
        Contour c = new Contour(List.of(Arc2.circle(Vec2.of(3, 4), r, false)));
        List<Contour> out = LineArcOffsetter.offset(c, t, TOL);
        assertEquals(1, out.size());
        assertEquals(Math.PI * (r + t) * (r + t), out.get(0).area(), 1e-9);
        for (Curve2 cv : out.get(0).curves()) {
            assertTrue(cv instanceof Arc2);
        }
        everyPointIsAtTheDistance(c, out, t);
    }

    @Test
    void aHoleSmallerThanTheKerfVanishes() {
        Contour c = new Contour(List.of(Arc2.circle(Vec2.ZERO, 0.8, true)));
        assertTrue(LineArcOffsetter.offset(c, -1, TOL).isEmpty());
        assertTrue(LineArcOffsetter.offset(rect(1.5, 10), -1, TOL).isEmpty());
    }

    @Test
    void aDumbbellShrunkBeyondItsWaistSplitsInTwo() {
        // two 20x20 squares joined by a 20 x 2 bridge
        Contour c = Contour.polygon(List.of(
                Vec2.of(0, 0),
                Vec2.of(20, 0),
                Vec2.of(20, 9),
                Vec2.of(40, 9),
                Vec2.of(40, 0),
                Vec2.of(60, 0),
                Vec2.of(60, 20),
                Vec2.of(40, 20),
                Vec2.of(40, 11),
                Vec2.of(20, 11),
                Vec2.of(20, 20),
                Vec2.of(0, 20)));
        List<Contour> r = LineArcOffsetter.offset(c, -2, TOL);
        assertEquals(2, r.size());
        // each half is the 16 x 16 square plus the sliver the mouth's rounded corners leave
        assertEquals(r.get(0).area(), r.get(1).area(), 1e-9);
        assertEquals(buffer(jts(c), -2).getArea(), r.get(0).area() * 2, 1e-3);
        everyPointIsAtTheDistance(c, r, -2);
    }

    @Test
    void slotRoundedEndsAndArcsAgreeWithJtsBuffer() {
        // a slot: two lines and two half circles, plus a random wobbly polygon with bulges
        Random rnd = new Random(8);
        for (int tr = 0; tr < 30; tr++) {
            int trial = tr;
            List<Curve2> cs = new ArrayList<>();
            int n = 5 + rnd.nextInt(8);
            List<Vec2> pts = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                double a = 2 * Math.PI * i / n;
                double r = 30 + rnd.nextDouble() * 20;
                pts.add(Vec2.of(r * Math.cos(a), r * Math.sin(a)));
            }
            for (int i = 0; i < n; i++) {
                Vec2 a = pts.get(i);
                Vec2 b = pts.get((i + 1) % n);
                if (rnd.nextBoolean()) {
                    double bulge = (rnd.nextDouble() - 0.5) * 0.8;
                    Vec2 chord = b.minus(a);
                    Vec2 ctr = a.interpolate(b, 0.5).plus(chord.leftNormal().times((1 - bulge * bulge) / (4 * bulge)));
                    cs.add(new Arc2(ctr, a, b, bulge > 0));
                } else {
                    cs.add(new Segment2(a, b));
                }
            }
            Contour c = new Contour(cs);
            for (double t : new double[] {3, -3, 8}) {
                List<Contour> r = LineArcOffsetter.offset(c, t, TOL);
                everyPointIsAtTheDistance(c, r, t);
                Geometry g = buffer(jts(c), t);
                double area = 0;
                for (Contour x : r) {
                    area += x.isCcw() == c.isCcw() ? x.area() : -x.area();
                }
                double fa = area;
                assertEquals(
                        g.getArea(),
                        area,
                        2e-4 * g.getArea(),
                        () -> "trial " + trial + " t " + t + " loops " + r.size() + " " + c + " got " + fa);
            }
        }
    }

    /** JTS's buffer without its input simplification, which cuts reflex corners on large distances. */
    static Geometry buffer(Geometry g, double t) {
        BufferParameters bp = new BufferParameters(256);
        bp.setSimplifyFactor(0);
        return BufferOp.bufferOp(g, t, bp);
    }

    static Geometry jts(Contour c) {
        List<Coordinate> coords = new ArrayList<>();
        for (Curve2 cv : c.curves()) {
            int k = cv instanceof Arc2 ? 400 : 1;
            for (int i = 0; i < k; i++) {
                Vec2 p = cv.pointAt((double) i / k);
                coords.add(new Coordinate(p.x(), p.y()));
            }
        }
        coords.add(coords.get(0));
        GeometryFactory f = new GeometryFactory();
        return f.createPolygon(coords.toArray(new Coordinate[0])).buffer(0);
    }
}
