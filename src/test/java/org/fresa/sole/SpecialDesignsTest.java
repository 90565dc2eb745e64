package org.fresa.sole;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.model.CamInputException;
import org.fresa.model.ContourFile;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The special designs of Table 5.2 (groups F to J): each a field of grooves with the count and
 * spacing its parameters give, clipped to the sample sole's outline as every tread figure is, and
 * named in the figure library.
 */
class SpecialDesignsTest {

    private static final Tolerance TOL = Tolerance.DEFAULT;
    /** The men's size-40 sole of the thesis: x from -59.72 to 33.23, y from -29.00 to 240.23. */
    static Contour sole;

    @BeforeAll
    static void readSole() throws Exception {
        try (Reader r = Files.newBufferedReader(Path.of("samples/sole/men40.contour"))) {
            sole = ContourFile.read(r, "men40.contour").get(0);
        }
    }

    private static TreadFigure figure(String macro, String params) throws CamInputException {
        return TreadFigures.of(macro, TreadFigures.parseParams(params, macro), macro);
    }

    private static List<Segment2> segments(List<Stroke> strokes) {
        List<Segment2> out = new ArrayList<>();
        for (Stroke s : strokes) {
            for (Curve2 c : s.curves()) {
                out.add((Segment2) c);
            }
        }
        return out;
    }

    /** Every cut of the clipped strokes keeps the margin from the outline (and is inside it). */
    private static void assertInside(List<Stroke> clipped, double marginMm) {
        assertFalse(clipped.isEmpty());
        for (Stroke s : clipped) {
            for (Curve2 c : s.curves()) {
                for (double t : new double[] {0, 0.25, 0.5, 0.75, 1}) {
                    Vec2 p = c.pointAt(t);
                    assertTrue(sole.windingNumber(p) != 0, p + " outside the sole");
                    assertTrue(sole.distanceTo(p) >= marginMm - 1e-6, p + " nearer than the margin");
                }
            }
        }
    }

    @Test
    void everySpecialDesignIsInTheFigureLibraryWithAnExample() throws Exception {
        assertEquals(
                List.of("PARAL", "COLMEIA", "PIRAM", "TEXTURA", "LOGO"),
                TreadFigures.MACROS.subList(18, TreadFigures.MACROS.size()));
        for (String m : SpecialDesigns.MACROS) {
            assertTrue(TreadFigures.isSpecial(m));
            assertFalse(TreadFigures.parameters(m).isEmpty());
            if (!TreadFigures.needsDrawing(m)) {
                assertFalse(
                        figure(m, TreadFigures.thesisExample(m))
                                .path(Vec2.ZERO, TOL)
                                .strokes()
                                .isEmpty(),
                        m);
            }
        }
        CamInputException e = assertThrows(CamInputException.class, () -> figure("LOGO", "X=0,Y=0,H=10"));
        assertTrue(e.getMessage().contains("drawing"), e.getMessage());
    }

    @Test
    void groupFParallelogramsAreALatticeOfSidesAAndBAtAng() throws Exception {
        // sides 5 along x and 11.18 at 116.57 deg: the parallelogram (15,15) (20,15) (15,25) (10,25) of test 05
        TreadFigure f = figure("PARAL", "XO=15,YO=15,A=5,B=11.18034,ANG=116.56505,NA=4,NB=2");
        List<Stroke> st = f.path(Vec2.ZERO, TOL).strokes();
        assertEquals((2 + 1) + (4 + 1), st.size(), "NB + 1 lines along x, NA + 1 along the slanted side");
        List<Segment2> seg = segments(st);
        // the lines along x at y = 15, 25, 35, each 4 x 5 = 20 long
        Set<Long> ys = new HashSet<>();
        for (Segment2 s : seg.subList(0, 3)) {
            assertEquals(0, s.end().y() - s.start().y(), 1e-9);
            assertEquals(20, s.length(), 1e-6);
            ys.add(Math.round(s.start().y() * 1000));
        }
        assertEquals(Set.of(15_000L, 25_000L, 35_000L), ys);
        // the slanted lines 5 apart along x, each 2 x 11.18 long, and one of them through (15,15) and (10,25)
        List<Double> xs = new ArrayList<>();
        for (Segment2 s : seg.subList(3, 8)) {
            assertEquals(2 * 11.18034, s.length(), 1e-4);
            Vec2 low = s.start().y() < s.end().y() ? s.start() : s.end();
            xs.add(low.x());
        }
        xs.sort(null);
        for (int i = 0; i < 5; i++) {
            assertEquals(15 + 5 * i, xs.get(i), 1e-9);
        }
        assertTrue(seg.stream()
                .anyMatch(s -> s.distanceTo(Vec2.of(10, 25)) < 1e-4 && s.distanceTo(Vec2.of(15, 15)) < 1e-9));
        // clipped to the sole: a lattice bigger than the sole keeps only what lies 2 mm inside
        TreadFigure big = figure("PARAL", "XO=-80,YO=-40,A=8,B=8,ANG=60,NA=30,NB=40");
        List<Stroke> all = big.path(Vec2.ZERO, TOL).strokes();
        List<Stroke> kept = TreadClipper.clip(all, sole, 2, TOL);
        assertInside(kept, 2);
        assertTrue(kept.size() > 20);
    }

    @Test
    void groupGHoneycombCutsEverySideOnce() throws Exception {
        SpecialDesigns.Honeycomb one = (SpecialDesigns.Honeycomb) figure("COLMEIA", "XO=0,YO=0,S=5,NX=1,NY=1");
        assertEquals(6, segments(one.path(Vec2.ZERO, TOL).strokes()).size());
        assertEquals(1, one.path(Vec2.ZERO, TOL).strokes().size(), "one hexagon is one closed groove");
        // 2 x 2 cells, the second row half a cell to the right: 24 sides, 5 shared
        SpecialDesigns.Honeycomb four = (SpecialDesigns.Honeycomb) figure("COLMEIA", "XO=0,YO=0,S=5,NX=2,NY=2");
        List<Segment2> seg = segments(four.path(Vec2.ZERO, TOL).strokes());
        assertEquals(19, seg.size());
        double total = 0;
        for (Segment2 s : seg) {
            assertEquals(5, s.length(), 1e-9, "every side S long");
            total += s.length();
        }
        assertEquals(95, total, 1e-9);
        // centres sqrt(3) S apart in a row, rows 1.5 S apart and shifted half a cell
        assertEquals(5 * Math.sqrt(3), four.centre(1, 0).x() - four.centre(0, 0).x(), 1e-12);
        assertEquals(7.5, four.centre(0, 1).y() - four.centre(0, 0).y(), 1e-12);
        assertEquals(
                5 * Math.sqrt(3) / 2, four.centre(0, 1).x() - four.centre(0, 0).x(), 1e-12);
        // every side once: no two segments the same
        Set<String> keys = new HashSet<>();
        for (Segment2 s : seg) {
            Vec2 a = s.start();
            Vec2 b = s.end();
            String ka = String.format(java.util.Locale.ROOT, "%.6f,%.6f", a.x(), a.y());
            String kb = String.format(java.util.Locale.ROOT, "%.6f,%.6f", b.x(), b.y());
            assertTrue(keys.add(ka.compareTo(kb) < 0 ? ka + kb : kb + ka));
        }
        // a honeycomb over the heel, clipped to the sole
        List<Stroke> kept = TreadClipper.clip(
                figure("COLMEIA", "XO=-70,YO=-40,S=6,NX=10,NY=8")
                        .path(Vec2.ZERO, TOL)
                        .strokes(),
                sole,
                2,
                TOL);
        assertInside(kept, 2);
    }

    @Test
    void groupHInvertedPyramidsAreVGroovesInTwoDirectionsAtRightAngles() throws Exception {
        List<Stroke> st = figure("PIRAM", "XO=-30,YO=0,P=6,ANG=45,N1=5,N2=3")
                .path(Vec2.ZERO, TOL)
                .strokes();
        assertEquals((3 + 1) + (5 + 1), st.size());
        List<Segment2> seg = segments(st);
        for (Segment2 s : seg.subList(0, 4)) {
            double cross =
                    (s.end().x() - s.start().x()) - (s.end().y() - s.start().y());
            assertEquals(0, cross, 1e-9, "along 45 degrees");
            assertEquals(30, s.length(), 1e-9);
        }
        for (Segment2 s : seg.subList(4, 10)) {
            double dot =
                    (s.end().x() - s.start().x()) * 1 + (s.end().y() - s.start().y()) * 1;
            assertEquals(0, dot, 1e-9, "at right angles to the first direction");
            assertEquals(18, s.length(), 1e-9);
        }
        // pitch: the first set's lines 6 apart (distance of a line's start from the next line)
        assertEquals(6, lineDistance(seg.get(0), seg.get(1)), 1e-9);
        assertEquals(6, lineDistance(seg.get(4), seg.get(5)), 1e-9);
        List<Stroke> kept = TreadClipper.clip(
                figure("PIRAM", "XO=-20,YO=-60,P=6,ANG=45,N1=40,N2=40")
                        .path(Vec2.ZERO, TOL)
                        .strokes(),
                sole,
                3,
                TOL);
        assertInside(kept, 3);
    }

    private static double lineDistance(Segment2 a, Segment2 b) {
        Vec2 d = a.end().minus(a.start()).normalized();
        Vec2 w = b.start().minus(a.start());
        return Math.abs(d.x() * w.y() - d.y() * w.x());
    }

    @Test
    void groupITextureLinesAreDashedLikeStitching() throws Exception {
        // 3 lines 60 long, 3 apart; dashes 4 with gaps 2: 10 dashes a line, the last one whole
        List<Stroke> st = figure("TEXTURA", "XO=-30,YO=100,L=60,P=3,ANG=0,N=3,DASH=4,GAP=2")
                .path(Vec2.ZERO, TOL)
                .strokes();
        assertEquals(30, st.size());
        for (Segment2 s : segments(st)) {
            assertEquals(4, s.length(), 1e-9);
        }
        assertEquals(100, st.get(0).start().y(), 1e-12);
        assertEquals(103, st.get(10).start().y(), 1e-12);
        assertEquals(-30, st.get(0).start().x(), 1e-12);
        assertEquals(-24, st.get(1).start().x(), 1e-12, "dash 4 + gap 2");
        // whole lines without dashes; back and forth
        List<Stroke> ribs = figure("TEXTURA", "XO=-30,YO=100,L=60,P=1.5,ANG=90,N=4,DASH=0,GAP=0")
                .path(Vec2.ZERO, TOL)
                .strokes();
        assertEquals(4, ribs.size());
        assertEquals(-31.5, ribs.get(1).start().x(), 1e-12, "the next line 1.5 to the left of the first at 90 deg");
        assertEquals(160, ribs.get(1).start().y(), 1e-12, "the second line runs back");
        List<Stroke> kept = TreadClipper.clip(
                figure("TEXTURA", "XO=35,YO=-40,L=300,P=2,ANG=90,N=60,DASH=5,GAP=2")
                        .path(Vec2.ZERO, TOL)
                        .strokes(),
                sole,
                2,
                TOL);
        assertInside(kept, 2);
    }

    @Test
    void groupJALogoIsTheDrawingsOutlinesScaledToHeightH() throws Exception {
        // a drawing 40 x 20 about (100, 100): a rectangle and a circle of radius 5
        Contour box =
                Contour.polygon(List.of(Vec2.of(100, 100), Vec2.of(140, 100), Vec2.of(140, 120), Vec2.of(100, 120)));
        Arc2 circle = new Arc2(Vec2.of(110, 110), Vec2.of(115, 110), Vec2.of(115, 110), true);
        TreadFigure f = TreadFigures.of(
                "LOGO", Map.of("X", -20.0, "Y", 150.0, "H", 10.0), List.of(box.curves(), List.of(circle)), "logo");
        List<Stroke> st = f.path(Vec2.ZERO, TOL).strokes();
        assertEquals(2, st.size(), "one groove per outline");
        assertEquals(4, st.get(0).curves().size());
        Arc2 a = (Arc2) st.get(1).curves().get(0);
        assertEquals(2.5, a.radius(), 1e-12, "scaled by H / 20 = 0.5, still an arc");
        assertEquals(Vec2.of(-15, 155).x(), a.center().x(), 1e-12);
        assertEquals(155, a.center().y(), 1e-12);
        double minX = Double.MAX_VALUE;
        double minY = Double.MAX_VALUE;
        double maxY = -Double.MAX_VALUE;
        for (Curve2 c : st.get(0).curves()) {
            minX = Math.min(minX, c.bounds().minX());
            minY = Math.min(minY, c.bounds().minY());
            maxY = Math.max(maxY, c.bounds().maxY());
        }
        assertEquals(-20, minX, 1e-12);
        assertEquals(150, minY, 1e-12);
        assertEquals(10, maxY - minY, 1e-12);
        // a logo wider than the toe is cut where the outline lets it
        TreadFigure wide =
                TreadFigures.of("LOGO", Map.of("X", -80.0, "Y", 200.0, "H", 50.0), List.of(box.curves()), "logo");
        List<Stroke> kept = TreadClipper.clip(wide.path(Vec2.ZERO, TOL).strokes(), sole, 2, TOL);
        assertInside(kept, 2);
        double cut = kept.stream().mapToDouble(Stroke::length).sum();
        assertTrue(cut > 50 && cut < 250, "part of the 300 mm rectangle is cut: " + cut);
    }
}
