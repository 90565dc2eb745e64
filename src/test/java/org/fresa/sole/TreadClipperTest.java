package org.fresa.sole;

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

class TreadClipperTest {

    private static final Tolerance TOL = Tolerance.DEFAULT;

    @Test
    void aLineAcrossASquareKeepsTheChordInsideTheMargin() {
        Contour square = Contour.polygon(List.of(Vec2.of(0, 0), Vec2.of(100, 0), Vec2.of(100, 100), Vec2.of(0, 100)));
        List<Stroke> out = TreadClipper.clip(
                List.of(Stroke.of(Vec2.of(-20, 50), List.of(Segment2.of(-20, 50, 120, 50)))), square, 5, TOL);
        assertEquals(1, out.size());
        Curve2 c = out.get(0).curves().get(0);
        assertEquals(5, c.start().x(), 1e-9);
        assertEquals(95, c.end().x(), 1e-9);
    }

    @Test
    void aStrokeThatLeavesAndReentersBecomesTwoStrokes() {
        // a U-shaped outline: a straight cut across the mouth leaves through the gap
        Contour u = Contour.polygon(List.of(
                Vec2.of(0, 0),
                Vec2.of(60, 0),
                Vec2.of(60, 60),
                Vec2.of(40, 60),
                Vec2.of(40, 20),
                Vec2.of(20, 20),
                Vec2.of(20, 60),
                Vec2.of(0, 60)));
        List<Stroke> out = TreadClipper.clip(
                List.of(Stroke.of(Vec2.of(-10, 40), List.of(Segment2.of(-10, 40, 70, 40)))), u, 2, TOL);
        assertEquals(2, out.size());
        assertEquals(2, out.get(0).start().x(), 1e-9);
        assertEquals(18, out.get(0).end().x(), 1e-9);
        assertEquals(42, out.get(1).start().x(), 1e-9);
        assertEquals(58, out.get(1).end().x(), 1e-9);
    }

    @Test
    void aRingCrossingAnArcOutlineStaysArcs() {
        Contour disc = Contour.of(List.of(Arc2.circle(Vec2.ZERO, 30, true)), TOL);
        Stroke ring = Stroke.of(Vec2.of(5, 0), List.of(Arc2.circle(Vec2.of(25, 0), 20, false)));
        List<Stroke> out = TreadClipper.clip(List.of(ring), disc, 3, TOL);
        assertEquals(1, out.size());
        for (Curve2 c : out.get(0).curves()) {
            assertTrue(c instanceof Arc2);
            assertTrue(disc.distanceTo(c.pointAt(0.5)) >= 3 - 1e-9);
        }
    }

    @ParameterizedTest
    @CsvSource(textBlock = """
            convex, 1
            convex, 2
            star, 3
            star, 4
            rounded, 5
            rounded, 6
            """)
    void noKeptPointLeavesTheShrunkOutlineAndNothingInsideIsLost(String kind, long seed) {
        Random rnd = new Random(seed);
        for (int trial = 0; trial < 25; trial++) {
            Contour outline = switch (kind) {
                case "convex" -> convex(rnd);
                case "star" -> star(rnd);
                default -> rounded(rnd);
            };
            if (rnd.nextBoolean()) {
                outline = outline.reversed();
            }
            double margin = rnd.nextInt(3) == 0 ? 0 : 0.5 + 4 * rnd.nextDouble();
            List<Stroke> figure = randomStrokes(rnd);
            List<Stroke> kept = TreadClipper.clip(figure, outline, margin, TOL);
            for (Stroke s : kept) {
                assertTrue(s.start().eq(s.curves().get(0).start(), TOL));
                for (int i = 0; i < s.curves().size(); i++) {
                    Curve2 c = s.curves().get(i);
                    if (i > 0) {
                        assertTrue(s.curves().get(i - 1).end().eq(c.start(), TOL), "stroke chains");
                    }
                    for (int k = 0; k <= 16; k++) {
                        Vec2 p = c.pointAt(k / 16.0);
                        double d = outline.distanceTo(p);
                        assertTrue(
                                d >= margin - 1e-6,
                                kind + " trial " + trial + ": kept point " + p + " at " + d
                                        + " from the outline, margin " + margin);
                        assertTrue(d <= 1e-6 || outline.windingNumber(p) != 0, "kept point outside: " + p);
                    }
                }
            }
            for (Stroke s : figure) {
                for (Curve2 c : s.curves()) {
                    for (int k = 1; k < 40; k++) {
                        Vec2 p = c.pointAt(k / 40.0);
                        if (outline.contains(p, TOL) && outline.distanceTo(p) > margin + 1e-3) {
                            assertTrue(covered(kept, p), kind + " trial " + trial + ": inside point lost " + p);
                        }
                    }
                }
            }
        }
    }

    private static boolean covered(List<Stroke> kept, Vec2 p) {
        for (Stroke s : kept) {
            for (Curve2 c : s.curves()) {
                if (c.distanceTo(p) < 1e-6) {
                    return true;
                }
            }
        }
        return false;
    }

    static List<Stroke> randomStrokes(Random rnd) {
        List<Stroke> out = new ArrayList<>();
        int n = 1 + rnd.nextInt(4);
        for (int i = 0; i < n; i++) {
            Vec2 p = Vec2.of(-70 + 140 * rnd.nextDouble(), -70 + 140 * rnd.nextDouble());
            Vec2 start = p;
            List<Curve2> cs = new ArrayList<>();
            int m = 1 + rnd.nextInt(4);
            for (int j = 0; j < m; j++) {
                if (rnd.nextBoolean()) {
                    Vec2 q = Vec2.of(-70 + 140 * rnd.nextDouble(), -70 + 140 * rnd.nextDouble());
                    cs.add(new Segment2(p, q));
                    p = q;
                } else if (rnd.nextInt(5) == 0) {
                    Vec2 c = p.plus(Vec2.ofAngle(rnd.nextDouble() * 6.28).times(3 + 30 * rnd.nextDouble()));
                    cs.add(new Arc2(c, p, p, rnd.nextBoolean()));
                } else {
                    double r = 3 + 40 * rnd.nextDouble();
                    Vec2 c = p.plus(Vec2.ofAngle(rnd.nextDouble() * 6.28).times(r));
                    double sweep = (rnd.nextBoolean() ? 1 : -1) * (0.2 + 5 * rnd.nextDouble());
                    Arc2 a = Arc2.ofAngles(c, r, p.minus(c).angleRad(), sweep);
                    a = new Arc2(c, p, a.end(), a.ccw());
                    cs.add(a);
                    p = a.end();
                }
            }
            out.add(Stroke.of(start, cs));
        }
        return out;
    }

    static Contour convex(Random rnd) {
        int n = 3 + rnd.nextInt(7);
        double[] a = new double[n];
        for (int i = 0; i < n; i++) {
            a[i] = rnd.nextDouble() * 2 * Math.PI;
        }
        java.util.Arrays.sort(a);
        double rx = 30 + 30 * rnd.nextDouble();
        double ry = 30 + 30 * rnd.nextDouble();
        List<Vec2> pts = new ArrayList<>();
        for (double t : a) {
            pts.add(Vec2.of(rx * Math.cos(t), ry * Math.sin(t)));
        }
        return dedupe(pts);
    }

    static Contour star(Random rnd) {
        int n = 5 + rnd.nextInt(12);
        List<Vec2> pts = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            double t = 2 * Math.PI * i / n;
            double r = 15 + 45 * rnd.nextDouble();
            pts.add(Vec2.of(r * Math.cos(t), r * Math.sin(t)));
        }
        return dedupe(pts);
    }

    private static Contour dedupe(List<Vec2> pts) {
        List<Vec2> out = new ArrayList<>();
        for (Vec2 p : pts) {
            if (out.isEmpty() || out.get(out.size() - 1).distance(p) > 1) {
                out.add(p);
            }
        }
        if (out.size() > 3 && out.get(0).distance(out.get(out.size() - 1)) <= 1) {
            out.remove(out.size() - 1);
        }
        if (out.size() < 3) {
            return Contour.polygon(List.of(Vec2.of(-40, -40), Vec2.of(40, -40), Vec2.of(0, 40)));
        }
        return Contour.polygon(out);
    }

    /** A rounded rectangle with a concave arc bite: lines and both senses of arcs. */
    static Contour rounded(Random rnd) {
        double w = 30 + 30 * rnd.nextDouble();
        double h = 30 + 30 * rnd.nextDouble();
        double r = 5 + 10 * rnd.nextDouble();
        double bite = 5 + 10 * rnd.nextDouble();
        List<Curve2> cs = new ArrayList<>();
        cs.add(Segment2.of(-w + r, -h, -bite, -h));
        cs.add(new Arc2(Vec2.of(0, -h), Vec2.of(-bite, -h), Vec2.of(bite, -h), false));
        cs.add(Segment2.of(bite, -h, w - r, -h));
        cs.add(new Arc2(Vec2.of(w - r, -h + r), Vec2.of(w - r, -h), Vec2.of(w, -h + r), true));
        cs.add(Segment2.of(w, -h + r, w, h - r));
        cs.add(new Arc2(Vec2.of(w - r, h - r), Vec2.of(w, h - r), Vec2.of(w - r, h), true));
        cs.add(Segment2.of(w - r, h, -w + r, h));
        cs.add(new Arc2(Vec2.of(-w + r, h - r), Vec2.of(-w + r, h), Vec2.of(-w, h - r), true));
        cs.add(Segment2.of(-w, h - r, -w, -h + r));
        cs.add(new Arc2(Vec2.of(-w + r, -h + r), Vec2.of(-w, -h + r), Vec2.of(-w + r, -h), true));
        return Contour.of(cs, TOL);
    }
}
