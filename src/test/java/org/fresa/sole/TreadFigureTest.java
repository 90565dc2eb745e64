package org.fresa.sole;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.model.CamInputException;
import org.junit.jupiter.api.Test;

/** Each DESCOM macro with the parameters of one of the thesis's test programs (seed 004-listings, App. E/F). */
class TreadFigureTest {

    private static final Tolerance TOL = Tolerance.DEFAULT;
    private static final double EPS = 1e-9;

    static TreadFigure call(String macro, String params) throws CamInputException {
        return TreadFigures.of(macro, TreadFigures.parseParams(params, "test"), "test");
    }

    static void assertPoint(double x, double y, Vec2 p) {
        assertEquals(x, p.x(), 1e-6, "x of " + p);
        assertEquals(y, p.y(), 1e-6, "y of " + p);
    }

    static void assertLine(double x1, double y1, double x2, double y2, Curve2 c) {
        Segment2 s = assertInstanceOf(Segment2.class, c);
        assertPoint(x1, y1, s.start());
        assertPoint(x2, y2, s.end());
    }

    static void assertArc(double x1, double y1, double x2, double y2, double cx, double cy, boolean ccw, Curve2 c) {
        Arc2 a = assertInstanceOf(Arc2.class, c);
        assertPoint(x1, y1, a.start());
        assertPoint(x2, y2, a.end());
        assertPoint(cx, cy, a.center());
        assertEquals(ccw, a.ccw(), "sense of " + a);
    }

    @Test
    void sub1aCutsTheBoustrophedonPairOfTest01() throws Exception {
        FigurePath p = call("SUB1A", "XA1=-40,YA1=-41,XB1=40,XC1=40,YC1=-31,XD1=-40,PROF=7,AVAN=150,CTM=0")
                .path(Vec2.of(-34, -46), TOL);
        assertFalse(p.joinsPrevious());
        assertFalse(p.staysDown());
        assertEquals(2, p.strokes().size());
        assertLine(-40, -41, 40, -41, p.strokes().get(0).curves().get(0));
        assertLine(40, -31, -40, -31, p.strokes().get(1).curves().get(0));
    }

    @Test
    void sub1bCutsTheVerticalPairOfTheInsertProgram() throws Exception {
        FigurePath p = call("SUB1B", "XA1=-45,YA1=210.6,YB1=181,XC1=-30,YC1=184,YD1=220")
                .path(Vec2.ZERO, TOL);
        assertLine(-45, 210.6, -45, 181, p.strokes().get(0).curves().get(0));
        assertLine(-30, 184, -30, 220, p.strokes().get(1).curves().get(0));
    }

    @Test
    void sub2CutsOneBrickDashOfTest01() throws Exception {
        FigurePath p = call("SUB2", "XA2=-40,YA2=10,XB2=10,YB2=0").path(Vec2.ZERO, TOL);
        assertEquals(1, p.strokes().size());
        assertLine(-40, 10, -30, 10, p.strokes().get(0).curves().get(0));
    }

    @Test
    void sub3aCutsTheHalfCircleScallopOfTest04OverTheTop() throws Exception {
        FigurePath p = call("SUB3A", "XC=-30,YC=-35,RA=5,XA3=-35,XB3=-25").path(Vec2.of(-30, -40), TOL);
        Curve2 c = p.strokes().get(0).curves().get(0);
        assertArc(-35, -35, -25, -35, -30, -35, false, c);
        assertPoint(-30, -30, c.pointAt(0.5));
    }

    @Test
    void sub3bJoinsFromPrimOfTest05() throws Exception {
        Vec2 at = call("PRIM", "XI=-40,YI=-40,XA1=0,YA1=0").path(Vec2.ZERO, TOL).end();
        FigurePath p = call("SUB3B", "XC=-30,YC=-40,RA=5,XA3=-35,XB3=-25,I=1").path(at, TOL);
        assertTrue(p.joinsPrevious());
        assertTrue(p.staysDown());
        List<Curve2> c = p.strokes().get(0).curves();
        assertLine(-40, -40, -35, -40, c.get(0));
        assertArc(-35, -40, -25, -40, -30, -40, false, c.get(1));
        assertPoint(-30, -35, c.get(1).pointAt(0.5));
    }

    @Test
    void sub3eCutsFourSuccessiveArcsOfTest02EndingOnMinus20Plus20I() throws Exception {
        FigurePath p =
                call("SUB3E", "XC=-30,YC=20,RA=10,XA3=-40,XB3=-20,AFAS=20,N=3").path(Vec2.of(-35, 15), TOL);
        List<Curve2> c = p.strokes().get(0).curves();
        assertEquals(4, c.size());
        assertPoint(-40, 20, c.get(0).start());
        for (int i = 0; i < 4; i++) {
            Arc2 a = (Arc2) c.get(i);
            assertPoint(-20 + 20 * i, 20, a.end());
            assertPoint(-30 + 20 * i, 30, a.pointAt(0.5));
            assertFalse(a.ccw());
        }
    }

    @Test
    void sub4CutsTheThreeRingsOfTest01InTwoHalves() throws Exception {
        double[][] rings = {{16, 10, 42}, {10, 16, 36}, {5, 21, 31}};
        for (double[] r : rings) {
            FigurePath p = call(
                            "SUB4",
                            String.format(
                                    java.util.Locale.ROOT,
                                    "XC=26,YC=24,RA=%s,XA4=%s,YA4=24,XB4=%s,YB4=24",
                                    r[0],
                                    r[1],
                                    r[2]))
                    .path(Vec2.ZERO, TOL);
            List<Curve2> c = p.strokes().get(0).curves();
            assertEquals(2, c.size());
            assertArc(r[1], 24, r[2], 24, 26, 24, false, c.get(0));
            assertArc(r[2], 24, r[1], 24, 26, 24, false, c.get(1));
            assertPoint(26, 24 + r[0], c.get(0).pointAt(0.5));
        }
    }

    @Test
    void sub4FromAPointOutsideStartsOnTheLeftTangent() throws Exception {
        // PTA below the circle: seen from PTA towards the centre, the left tangent touches at x < XC
        FigurePath p = call("SUB4", "XC=0,YC=0,RA=5,XA4=0,YA4=-10,XB4=0,YB4=10").path(Vec2.ZERO, TOL);
        Vec2 t = p.strokes().get(0).start();
        assertEquals(5, t.distance(Vec2.ZERO), EPS);
        assertTrue(t.x() < 0, "left tangent point " + t);
        assertEquals(0, t.minus(Vec2.of(0, -10)).dot(t), 1e-6);
    }

    @Test
    void sub5aCutsTheSWaveOfTest02() throws Exception {
        FigurePath p = call("SUB5A", "XC1=-35,YC1=-35,XA5=-40,XB5=-20,XC2=-25,YC2=-35,XT=-30,YT=-35")
                .path(Vec2.of(-35, -40), TOL);
        List<Curve2> c = p.strokes().get(0).curves();
        assertArc(-40, -35, -30, -35, -35, -35, false, c.get(0));
        assertArc(-30, -35, -20, -35, -25, -35, true, c.get(1));
        assertPoint(-35, -30, c.get(0).pointAt(0.5));
        assertPoint(-25, -40, c.get(1).pointAt(0.5));
    }

    @Test
    void sub5bJoinsFromNovoOfTest04() throws Exception {
        Vec2 at = call("NOVO", "XF1=-27.5,YF1=-25,XF2=-40,YF2=-10")
                .path(Vec2.ZERO, TOL)
                .end();
        FigurePath p = call("SUB5B", "XC1=-30,YC1=-10,XC2=-20,YC2=-10,XT=-25,YT=-10,XA5=-35,XB5=-15")
                .path(at, TOL);
        List<Curve2> c = p.strokes().get(0).curves();
        assertLine(-40, -10, -35, -10, c.get(0));
        assertArc(-35, -10, -25, -10, -30, -10, false, c.get(1));
        assertArc(-25, -10, -15, -10, -20, -10, true, c.get(2));
    }

    @Test
    void sub5eCutsTheQuarterArcWaveOfTest03FromMinus40To40() throws Exception {
        FigurePath p = call("SUB5E", "XC1=-35,YC1=-45,XA5=-40,XB5=-20,XC2=-25,YC2=-35,XT=-30,YT=-40,AFAS=20,N=3")
                .path(Vec2.of(-38, -44), TOL);
        List<Curve2> c = p.strokes().get(0).curves();
        assertEquals(8, c.size());
        assertPoint(-40, -40, c.get(0).start());
        for (int i = 0; i < 8; i++) {
            Arc2 a = (Arc2) c.get(i);
            assertPoint(-30 + 10 * i, -40, a.end());
            assertEquals(Math.sqrt(50), a.radius(), 1e-9);
            assertEquals(Math.PI / 2, Math.abs(a.sweepRad()), 1e-9);
            assertEquals(i % 2 == 1, a.ccw());
        }
    }

    @Test
    void sub7aCutsTheVOfTest04() throws Exception {
        List<Curve2> c = call("SUB7A", "XA7=-40,YA7=20,XB7=10,YB7=5,XC7=10,YC7=-5")
                .path(Vec2.ZERO, TOL)
                .strokes()
                .get(0)
                .curves();
        assertLine(-40, 20, -30, 25, c.get(0));
        assertLine(-30, 25, -20, 20, c.get(1));
    }

    @Test
    void sub7bCarriesTheZigZagOfTest02OnFromPrim() throws Exception {
        FigurePath p = call("SUB7B", "XB7=10,YB7=8,XC7=10,YC7=-8").path(Vec2.of(-40, -10), TOL);
        assertTrue(p.joinsPrevious());
        List<Curve2> c = p.strokes().get(0).curves();
        assertLine(-40, -10, -30, -2, c.get(0));
        assertLine(-30, -2, -20, -10, c.get(1));
    }

    @Test
    void sub8aCutsTheSteppedZOfTest03() throws Exception {
        List<Curve2> c = call("SUB8A", "XA8=-39,YA8=20,XB8=4,YB8=0,XC8=5,YC8=-10,XD8=4,YD8=0")
                .path(Vec2.ZERO, TOL)
                .strokes()
                .get(0)
                .curves();
        assertLine(-39, 20, -35, 20, c.get(0));
        assertLine(-35, 20, -30, 10, c.get(1));
        assertLine(-30, 10, -26, 10, c.get(2));
    }

    @Test
    void sub8bCutsOneTrapezoidOfTest03FromNovo() throws Exception {
        Vec2 at = call("NOVO", "XF1=-40,YF1=-25,XF2=-40,YF2=-15")
                .path(Vec2.ZERO, TOL)
                .end();
        List<Curve2> c = call("SUB8B", "XB8=5,YB8=5,XC8=10,YC8=0,XD8=5,YD8=-5")
                .path(at, TOL)
                .strokes()
                .get(0)
                .curves();
        assertLine(-40, -15, -35, -10, c.get(0));
        assertLine(-35, -10, -25, -10, c.get(1));
        assertLine(-25, -10, -20, -15, c.get(2));
    }

    @Test
    void sub9aClosesTheParallelogramOfTest05() throws Exception {
        List<Curve2> c = call("SUB9A", "XA9=15,YA9=15,XB9=5,YB9=0,XC9=-5,YC9=10,XD9=-5,YD9=0,XE9=5,YE9=-10")
                .path(Vec2.ZERO, TOL)
                .strokes()
                .get(0)
                .curves();
        assertLine(15, 15, 20, 15, c.get(0));
        assertLine(20, 15, 15, 25, c.get(1));
        assertLine(15, 25, 10, 25, c.get(2));
        assertLine(10, 25, 15, 15, c.get(3));
    }

    @Test
    void sub9bCutsOneTrapezoidPeriodOfTest05() throws Exception {
        Vec2 at = call("NOVO", "XF1=-35,YF1=-30,XF2=-40,YF2=-20")
                .path(Vec2.ZERO, TOL)
                .end();
        List<Curve2> c = call("SUB9B", "XB9=5,YB9=0,XC9=5,YC9=8,XD9=5,YD9=0,XE9=5,YE9=-8")
                .path(at, TOL)
                .strokes()
                .get(0)
                .curves();
        assertLine(-40, -20, -35, -20, c.get(0));
        assertLine(-35, -20, -30, -12, c.get(1));
        assertLine(-30, -12, -25, -12, c.get(2));
        assertLine(-25, -12, -20, -20, c.get(3));
    }

    @Test
    void primPlungesAtItsPointAndStaysDown() throws Exception {
        FigurePath p = call("PRIM", "XI=-40,YI=-10,XA1=0,YA1=0,PROF=7,AVAN=150,CTM=0,I=1")
                .path(Vec2.ZERO, TOL);
        assertTrue(p.staysDown());
        assertPoint(-40, -10, p.strokes().get(0).start());
        assertTrue(p.strokes().get(0).via().isEmpty());
        assertTrue(p.strokes().get(0).curves().isEmpty());
    }

    @Test
    void novoLiftsOverItsFirstPointAndPlungesAtTheSecond() throws Exception {
        FigurePath p = call("NOVO", "XF1=40,YF1=-10,XF2=40,YF2=-5").path(Vec2.ZERO, TOL);
        assertFalse(p.joinsPrevious());
        assertTrue(p.staysDown());
        assertPoint(40, -10, p.strokes().get(0).via().get(0));
        assertPoint(40, -5, p.strokes().get(0).start());
    }

    @Test
    void aMissingParameterIsReportedByItsThesisName() {
        CamInputException e = org.junit.jupiter.api.Assertions.assertThrows(
                CamInputException.class, () -> call("SUB2", "XA2=-40,YA2=10,XB2=10"));
        assertTrue(e.getMessage().contains("YB2"), e.getMessage());
    }

    @Test
    void anArcWhoseStartLineMissesTheCircleIsBadInput() {
        CamInputException e = org.junit.jupiter.api.Assertions.assertThrows(
                CamInputException.class, () -> call("SUB3A", "XC=0,YC=0,RA=5,XA3=-9,XB3=5"));
        assertTrue(e.getMessage().contains("misses"), e.getMessage());
    }
}
