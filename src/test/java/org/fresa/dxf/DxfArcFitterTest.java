package org.fresa.dxf;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.function.DoubleFunction;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Property tests of the biarc fitting of ellipses and splines: the arcs stay within
 * the tolerance of the exact curve both ways, consecutive arcs are tangent (G1), and the ends are
 * exact.
 */
class DxfArcFitterTest {

    /** Tangent directions at a joint between arcs agree to this (radians). */
    static final double G1_RAD = 1e-6;

    /** The largest distance between the curve and the arcs, both ways, from dense samples refined locally. */
    static double deviation(List<DxfArcFitter.Piece> pieces, List<Curve2> arcs) {
        double worst = 0;
        for (DxfArcFitter.Piece p : pieces) {
            for (int k = 0; k <= 1000; k++) {
                double u = p.u0() + (p.u1() - p.u0()) * k / 1000;
                Vec2 q = p.f().apply(u);
                double d = Double.POSITIVE_INFINITY;
                for (Curve2 c : arcs) {
                    d = Math.min(d, c.distanceTo(q));
                }
                worst = Math.max(worst, d);
            }
        }
        int n = 400;
        double[][] us = new double[pieces.size()][n + 1];
        Vec2[][] ss = new Vec2[pieces.size()][n + 1];
        for (int j = 0; j < pieces.size(); j++) {
            DxfArcFitter.Piece p = pieces.get(j);
            for (int i = 0; i <= n; i++) {
                us[j][i] = p.u0() + (p.u1() - p.u0()) * i / n;
                ss[j][i] = p.f().apply(us[j][i]);
            }
        }
        for (Curve2 c : arcs) {
            for (int k = 0; k <= 20; k++) {
                Vec2 q = c.pointAt(k / 20.0);
                double d = Double.POSITIVE_INFINITY;
                for (int j = 0; j < pieces.size(); j++) {
                    d = Math.min(d, DxfArcFitter.distanceToCurve(pieces.get(j), us[j], ss[j], q));
                }
                worst = Math.max(worst, d);
            }
        }
        return worst;
    }

    static double turn(Vec2 a, Vec2 b) {
        return Math.abs(Math.atan2(a.cross(b), a.dot(b)));
    }

    static void checkG1AndJoints(List<Curve2> arcs, boolean closed) {
        for (int i = 0; i + 1 < arcs.size() + (closed ? 1 : 0); i++) {
            Curve2 a = arcs.get(i);
            Curve2 b = arcs.get((i + 1) % arcs.size());
            int at = i;
            assertAll(
                    () -> assertEquals(a.end(), b.start(), "joint " + at + " is not exact"),
                    () -> assertTrue(
                            turn(a.endTangent(), b.startTangent()) < G1_RAD,
                            "joint " + at + " turns " + turn(a.endTangent(), b.startTangent()) + " rad"));
        }
    }

    static DxfArcFitter.Piece ellipse(Vec2 c, Vec2 major, double ratio, double u0, double u1) {
        Vec2 minor = major.leftNormal().times(ratio);
        return new DxfArcFitter.Piece(u -> c.plus(major.times(Math.cos(u))).plus(minor.times(Math.sin(u))), u0, u1);
    }

    @ParameterizedTest(name = "tolerance {0} mm")
    @ValueSource(doubles = {0.01, 0.001})
    void randomEllipseArcsAreMatchedWithinTheToleranceByTangentBiarcs(double tol) {
        Random rnd = new Random(8);
        for (int trial = 0; trial < 15; trial++) {
            Vec2 c = new Vec2(rnd.nextDouble() * 400 - 200, rnd.nextDouble() * 400 - 200);
            Vec2 major = Vec2.ofAngle(rnd.nextDouble() * 7).times(1 + rnd.nextDouble() * 150);
            double ratio = 0.05 + rnd.nextDouble() * 0.95;
            double u0 = rnd.nextDouble() * 6;
            double u1 = u0 + 0.1 + rnd.nextDouble() * 6;
            List<DxfArcFitter.Piece> pieces = List.of(ellipse(c, major, ratio, u0, u1));
            List<Curve2> arcs = DxfArcFitter.fit(pieces, false, tol);
            double dev = deviation(pieces, arcs);
            int t = trial;
            assertAll(
                    () -> assertTrue(dev <= tol * (1 + 1e-6), "trial " + t + ": deviation " + dev),
                    () -> assertEquals(pieces.get(0).f().apply(u0), arcs.get(0).start()),
                    () -> assertEquals(
                            pieces.get(0).f().apply(u1),
                            arcs.get(arcs.size() - 1).end()));
            checkG1AndJoints(arcs, false);
        }
    }

    @Test
    void aFullEllipseClosesExactlyAndSmoothly() {
        DxfArcFitter.Piece e = ellipse(Vec2.ZERO, new Vec2(20, 0), 0.5, 0, 2 * Math.PI);
        List<DxfArcFitter.Piece> quarters = new ArrayList<>();
        for (int k = 0; k < 4; k++) {
            quarters.add(new DxfArcFitter.Piece(e.f(), k * Math.PI / 2, (k + 1) * Math.PI / 2));
        }
        List<Curve2> arcs = DxfArcFitter.fit(quarters, true, 0.01);
        assertEquals(arcs.get(arcs.size() - 1).end(), arcs.get(0).start());
        checkG1AndJoints(arcs, true);
        assertTrue(deviation(quarters, arcs) <= 0.01 * (1 + 1e-6));
        // far fewer pieces than a polygon at the same tolerance: 2 pi sqrt(20 / (8 * 0.01)) ~ 99 sides
        assertTrue(arcs.size() <= 48, arcs.size() + " arcs");
    }

    /** A random cubic NURBS (clamped knots, positive weights) as its knot spans. */
    static List<DxfArcFitter.Piece> randomSpline(Random rnd, boolean rational) {
        int p = 3;
        int n = 5 + rnd.nextInt(6);
        double[] px = new double[n];
        double[] py = new double[n];
        double[] w = rational ? new double[n] : null;
        for (int i = 0; i < n; i++) {
            px[i] = i * 20 + rnd.nextDouble() * 30;
            py[i] = rnd.nextDouble() * 80 - 40;
            if (rational) {
                w[i] = 0.5 + rnd.nextDouble() * 1.5;
            }
        }
        double[] u = new double[n + p + 1];
        for (int i = 0; i < u.length; i++) {
            u[i] = i <= p ? 0 : i >= n ? n - p : i - p + rnd.nextDouble() * 0.6 - 0.3;
        }
        List<DxfArcFitter.Piece> pieces = new ArrayList<>();
        for (int k = p; k < n; k++) {
            int span = k;
            DoubleFunction<Vec2> f = s -> DxfReader.deBoor(span, s, p, u, px, py, w);
            pieces.add(new DxfArcFitter.Piece(f, u[k], u[k + 1]));
        }
        return pieces;
    }

    @ParameterizedTest(name = "rational {0}")
    @ValueSource(booleans = {false, true})
    void randomSplinesAreMatchedWithinTheToleranceByTangentBiarcs(boolean rational) {
        Random rnd = new Random(2010);
        double tol = 0.01;
        double worst = 0;
        for (int trial = 0; trial < 12; trial++) {
            List<DxfArcFitter.Piece> pieces = randomSpline(rnd, rational);
            List<Curve2> arcs = DxfArcFitter.fit(pieces, false, tol);
            double dev = deviation(pieces, arcs);
            worst = Math.max(worst, dev);
            DxfArcFitter.Piece first = pieces.get(0);
            DxfArcFitter.Piece last = pieces.get(pieces.size() - 1);
            int t = trial;
            assertAll(
                    () -> assertTrue(dev <= tol * (1 + 1e-6), "trial " + t + ": deviation " + dev),
                    () -> assertEquals(first.f().apply(first.u0()), arcs.get(0).start()),
                    () -> assertEquals(
                            last.f().apply(last.u1()), arcs.get(arcs.size() - 1).end()));
            checkG1AndJoints(arcs, false);
        }
        System.out.printf(
                Locale.ROOT,
                "biarc spline deviation (rational %b): max %.6f mm at tolerance %.3f%n",
                rational,
                worst,
                tol);
    }

    @Test
    void aKinkAtAKnotOfFullMultiplicityIsKept() {
        // two straight-ish quadratic pieces meeting at a right angle
        DxfArcFitter.Piece a = new DxfArcFitter.Piece(s -> new Vec2(10 * s, s * s), 0, 1);
        DxfArcFitter.Piece b = new DxfArcFitter.Piece(s -> new Vec2(10 - s * s, 1 + 10 * s), 0, 1);
        List<Curve2> arcs = DxfArcFitter.fit(List.of(a, b), false, 0.01);
        boolean kink = false;
        for (int i = 0; i + 1 < arcs.size(); i++) {
            kink |= turn(arcs.get(i).endTangent(), arcs.get(i + 1).startTangent()) > 1;
            assertEquals(arcs.get(i).end(), arcs.get(i + 1).start());
        }
        assertTrue(kink, "the corner between the pieces was smoothed away");
        assertTrue(deviation(List.of(a, b), arcs) <= 0.01 * (1 + 1e-6));
    }

    @Test
    void aDxfSplineIsReadAsTangentArcsWithinTheCurveTolerance() throws Exception {
        String spline = "0\nSPLINE\n5\n2A\n100\nAcDbEntity\n8\n0\n100\nAcDbSpline\n70\n8\n71\n3\n72\n8\n73\n4\n"
                + "40\n0\n40\n0\n40\n0\n40\n0\n40\n1\n40\n1\n40\n1\n40\n1\n"
                + "10\n0\n20\n0\n30\n0\n10\n30\n20\n40\n30\n0\n10\n70\n20\n-40\n30\n0\n10\n100\n20\n0\n30\n0\n";
        String text = "0\nSECTION\n2\nENTITIES\n" + spline + "0\nENDSEC\n0\nEOF\n";
        DxfDrawing d = DxfReader.read(text.getBytes(StandardCharsets.US_ASCII), "s.dxf", DxfReadOptions.DEFAULT);
        List<Curve2> c = d.curves();
        assertFalse(c.isEmpty());
        assertTrue(c.stream().allMatch(x -> x instanceof Arc2 || x.length() > 0));
        assertEquals(new Vec2(0, 0), c.get(0).start());
        assertEquals(new Vec2(100, 0), c.get(c.size() - 1).end());
        checkG1AndJoints(c, false);
        double[] u = {0, 0, 0, 0, 1, 1, 1, 1};
        double[] px = {0, 30, 70, 100};
        double[] py = {0, 40, -40, 0};
        DxfArcFitter.Piece exact = new DxfArcFitter.Piece(s -> DxfReader.deBoor(3, s, 3, u, px, py, null), 0, 1);
        double dev = deviation(List.of(exact), c);
        assertTrue(
                dev <= DxfReadOptions.DEFAULT.curveToleranceMm() * (1 + 1e-6),
                dev + " mm from " + c.size() + " curves");
    }
}
