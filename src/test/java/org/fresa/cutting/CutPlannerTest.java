package org.fresa.cutting;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class CutPlannerTest {

    static List<Curve2> rect(double x, double y, double w, double h) {
        Vec2 a = Vec2.of(x, y);
        Vec2 b = Vec2.of(x + w, y);
        Vec2 c = Vec2.of(x + w, y + h);
        Vec2 d = Vec2.of(x, y + h);
        return List.of(new Segment2(a, b), new Segment2(b, c), new Segment2(c, d), new Segment2(d, a));
    }

    static CuttingOptions plasma(double kerf) {
        return CuttingOptions.of(CutProcess.PLASMA, kerf, 3, 1, true);
    }

    @ParameterizedTest(name = "gap {0} mm with tolerance {1} mm closes: {2}")
    @CsvSource(textBlock = """
            0.0005, 0.001, true
            0.002, 0.001, false
            0.04, 0.05, true
            """)
    void chainingJoinsEndsWithinTheGapTolerance(double gap, double tol, boolean closes) {
        List<Curve2> l = new ArrayList<>(rect(0, 0, 10, 10));
        l.set(2, Segment2.of(10, 10, 0 + gap, 10));
        Chainer.Chains c = Chainer.chain(l, tol);
        assertEquals(closes ? 1 : 0, c.closed().size());
        assertEquals(closes ? 0 : 1, c.open().size());
    }

    @Test
    void aQcadEllipseWithARatioAboveOneIsCutAsAHole() throws Exception {
        org.fresa.dxf.DxfDrawing d = org.fresa.dxf.DxfReader.read(java.nio.file.Path.of(
                CutPlannerTest.class.getResource("ellipse-ratio-above-one.dxf").toURI()));
        CutPlan p = CutPlanner.plan(d.layers(), plasma(2));
        assertEquals(1, p.outers().size());
        assertEquals(1, p.holes().size());
        assertEquals(2, p.cuts().size());
        assertTrue(p.uncut().isEmpty() && p.open().isEmpty(), p.warnings().toString());
        // the hole's semi-axes are 17.5 mm across and 5 mm up
        org.fresa.geom.Box2 b = p.holes().get(0).bounds();
        assertEquals(35, b.width(), 0.01);
        assertEquals(10, b.height(), 0.01);
    }

    @Test
    void anOutlineWithGapsOfAHundredthAtItsArcsClosesAndIsOffset() {
        // a 100 x 100 square with round corners of radius 10, each line stopping 0.01 mm short of its arc
        double g = 0.01;
        List<Curve2> l = List.of(
                Segment2.of(10, 0, 90 - g, 0),
                new Arc2(Vec2.of(90, 10), Vec2.of(90, 0), Vec2.of(100, 10), true),
                Segment2.of(100, 10 + g, 100, 90),
                new Arc2(Vec2.of(90, 90), Vec2.of(100, 90), Vec2.of(90, 100), true),
                Segment2.of(90 - g, 100, 10, 100),
                new Arc2(Vec2.of(10, 90), Vec2.of(10, 100), Vec2.of(0, 90), true),
                Segment2.of(0, 90 - g, 0, 10),
                new Arc2(Vec2.of(10, 10), Vec2.of(0, 10), Vec2.of(10, 0), true));
        CutPlan p = CutPlanner.plan(Map.of("0", l), plasma(2));
        assertEquals(1, p.cuts().size(), p.warnings()::toString);
        assertEquals(
                4,
                p.warnings().stream()
                        .filter(w -> w.startsWith("gap of 0.0100 mm"))
                        .count(),
                p.warnings()::toString);
        for (Curve2 c : p.outers().get(0).curves()) {
            if (c instanceof Arc2 a) {
                assertEquals(a.radius(), a.center().distance(a.end()), 1e-9, "both ends of an arc on its circle");
            }
        }
    }

    @Test
    void chainingIgnoresOrderAndDirectionAndRemovesRepeats() {
        List<Curve2> r = rect(0, 0, 10, 10);
        List<Curve2> l = List.of(
                r.get(2).reversed(),
                r.get(0),
                r.get(3),
                r.get(1).reversed(),
                r.get(0).reversed(),
                Segment2.of(5, 5, 5, 5));
        Chainer.Chains c = Chainer.chain(l, 0.001);
        assertEquals(1, c.closed().size());
        assertEquals(1, c.duplicates());
        assertEquals(1, c.zeroLength());
        Contour k = c.closed().get(0);
        for (int i = 0; i < k.size(); i++) {
            assertEquals(k.get(i).end(), k.get((i + 1) % k.size()).start());
        }
    }

    @Test
    void tenThousandLinesChainInOneGoWithoutQuadraticSearch() {
        // a 100 x 100 grid of unit squares' outlines, each square drawn as 4 separate lines, shuffled
        List<Curve2> l = new ArrayList<>();
        for (int i = 0; i < 50; i++) {
            for (int j = 0; j < 50; j++) {
                l.addAll(rect(i * 3, j * 3, 1, 1));
            }
        }
        java.util.Collections.shuffle(l, new java.util.Random(1));
        assertEquals(2500, Chainer.chain(l, 0.001).closed().size());
    }

    @Test
    void thePapersOneWayChainingFragmentsAnOpenChainStoredOutOfOrder() {
        Curve2 a = Segment2.of(0, 0, 10, 0);
        Curve2 b = Segment2.of(10, 0, 10, 10);
        Curve2 c = Segment2.of(10, 10, 20, 10);
        assertEquals(2, Chainer.chainPaper(List.of(b, a, c), 1e-4).open().size());
        assertEquals(1, Chainer.chain(List.of(b, a, c), 1e-4).open().size());
    }

    @Test
    void theWasherIsMisclassifiedByThePapersTriangleAreasButNotByContainment() {
        List<Curve2> outer = new ArrayList<>();
        for (int k = 0; k < 4; k++) {
            outer.add(Arc2.ofAngles(Vec2.ZERO, 50, k * Math.PI / 2, Math.PI / 2));
        }
        Contour o = new Contour(Chainer.snap(outer, true));
        Contour hole = new Contour(List.of(Arc2.circle(Vec2.ZERO, 47.5, true)));
        assertEquals(2 * Math.sqrt(2) * 2500, Math.abs(PaperCrc.triangleArea(o)), 1e-6);
        assertEquals(Math.PI * 2500, o.area(), 1e-9);
        assertTrue(Math.abs(PaperCrc.triangleArea(hole)) > Math.abs(PaperCrc.triangleArea(o)));
        List<Curve2> all = new ArrayList<>(outer);
        all.addAll(hole.curves());
        CutPlan paper = CutPlanner.plan(Map.of("0", all), plasma(0).withPaperMode(true));
        assertEquals(
                47.5, ((Arc2) paper.outers().get(0).get(0)).radius(), 1e-9, "the paper takes the hole for the outside");
        CutPlan exact = CutPlanner.plan(Map.of("0", all), plasma(0));
        assertEquals(1, exact.outers().size());
        assertEquals(Math.PI * 2500, exact.outers().get(0).area(), 1e-6);
    }

    @ParameterizedTest(name = "corner of {0} degrees: offset vertex {1} S from the corner, eq. 3 as printed {2}")
    @CsvSource(textBlock = """
            30, 3.8637, 1.0353
            60, 2.0000, 1.1547
            90, 1.4142, 1.4142
            120, 1.1547, 2.0000
            10, 11.4737, 1.0038
            """)
    void equationThreeIsCorrectedToSOverSinHalfGamma(double deg, double correct, double printed) {
        Vec2 u = Vec2.UNIT_X;
        Vec2 v = Vec2.ofAngle(Math.toRadians(deg));
        assertEquals(correct, PaperCrc.lineLineDistance(u, v, 1), 1e-4);
        assertEquals(printed, PaperCrc.lineLineDistanceAsPrinted(u, v, 1), 1e-4);
        // the paper's construction (sharp corner) puts the vertex at the corrected distance
        List<Vec2> tri = List.of(Vec2.ZERO, Vec2.of(100, 0), Vec2.of(100 * v.x(), 100 * v.y()));
        Contour c = Contour.polygon(tri).ccw();
        PaperCrc.Result r = PaperCrc.offset(c, 1, true); // CCW, tool on the left: inside
        Vec2 corner = r.path().get().curves().stream()
                .map(Curve2::start)
                .min((p, q) -> Double.compare(p.norm(), q.norm()))
                .get();
        assertEquals(correct, corner.norm(), 1e-4);
    }

    @Test
    void aCircleOfRadiusFifteenBecomesFourteenInsideAndSixteenOutside() {
        Contour c = new Contour(List.of(Arc2.circle(Vec2.ZERO, 15, true)));
        assertEquals(14, ((Arc2) PaperCrc.offset(c, 1, true).path().get().get(0)).radius(), 1e-12);
        assertEquals(16, ((Arc2) PaperCrc.offset(c, 1, false).path().get().get(0)).radius(), 1e-12);
        Contour small = new Contour(List.of(Arc2.circle(Vec2.ZERO, 0.8, true)));
        assertTrue(PaperCrc.offset(small, 1, true).path().isEmpty());
    }

    @Test
    void aHoleSmallerThanTheKerfIsReportedAndNotCut() {
        List<Curve2> all = new ArrayList<>(rect(0, 0, 50, 50));
        all.add(Arc2.circle(Vec2.of(25, 25), 0.8, true));
        CutPlan p = CutPlanner.plan(Map.of("0", all), plasma(2));
        assertEquals(1, p.uncut().size());
        assertEquals(1, p.cuts().size());
        assertTrue(
                p.warnings().stream().anyMatch(w -> w.contains("too small")),
                p.warnings().toString());
    }

    @Test
    void aPlateWithSixHolesCutsTheHolesFirstInTheOppositeSense() {
        List<Curve2> all = new ArrayList<>(rect(0, 0, 200, 100));
        for (int i = 0; i < 6; i++) {
            all.add(Arc2.circle(Vec2.of(25 + i * 30, 30 + (i % 2) * 40), 5 + i * 2, i % 2 == 0));
        }
        CutPlan p = CutPlanner.plan(Map.of("0", all), plasma(2));
        assertEquals(1, p.outers().size());
        assertEquals(6, p.holes().size());
        assertEquals(7, p.cuts().size());
        for (int i = 0; i < 6; i++) {
            assertFalse(p.cuts().get(i).outer());
            assertTrue(p.cuts().get(i).path().isCcw(), "holes counter-clockwise");
            assertEquals(
                    Math.PI * Math.pow(5 + 2 * indexOfRadius(p.cuts().get(i)) - 1, 2),
                    p.cuts().get(i).path().area(),
                    1e-6);
        }
        CutPath outer = p.cuts().get(6);
        assertTrue(outer.outer());
        assertFalse(outer.path().isCcw(), "outer clockwise");
        assertEquals(202 * 102 - (4 - Math.PI), outer.path().area(), 1e-6);
        assertFalse(outer.leadIn().isEmpty());
    }

    @ParameterizedTest(name = "outer cw {0}, holes cw {1}")
    @CsvSource(textBlock = """
        true,  false
        false, true
        false, false
        true,  true
        """)
    void theSensesOfOuterContoursAndHolesAreConfigurable(boolean outerCw, boolean holesCw) {
        List<Curve2> all = new ArrayList<>(rect(0, 0, 100, 60));
        all.add(Arc2.circle(Vec2.of(30, 30), 10, true));
        all.add(Arc2.circle(Vec2.of(70, 30), 10, false));
        CutPlan p = CutPlanner.plan(Map.of("0", all), plasma(2).withDirections(outerCw, holesCw));
        assertEquals(3, p.cuts().size());
        for (CutPath c : p.cuts()) {
            assertEquals(c.outer() ? !outerCw : !holesCw, c.path().isCcw(), c.label());
            // the path stays in the scrap whatever the sense: outside the part, inside the holes
            assertEquals(
                    c.outer() ? 102 * 62 - (4 - Math.PI) : Math.PI * 81,
                    c.path().area(),
                    1e-6,
                    c.label());
        }
    }

    @Test
    void controllerCompensationCutsTheDrawnContourWithTheToolOnTheScrapSide() {
        List<Curve2> all = new ArrayList<>(rect(0, 0, 100, 60));
        all.add(Arc2.circle(Vec2.of(30, 30), 10, true));
        for (boolean outerCw : new boolean[] {true, false}) {
            CutPlan p = CutPlanner.plan(
                    Map.of("0", all), plasma(2).withControllerCompensation(true).withDirections(outerCw, !outerCw));
            for (CutPath c : p.cuts()) {
                assertEquals(Math.abs(c.part().area()), Math.abs(c.path().area()), 1e-9, "the drawn contour");
                // clockwise outer: the scrap is on the left (G41); counter-clockwise: on the right (G42)
                assertEquals(outerCw ? 41 : 42, c.compensation(), c.label());
            }
        }
    }

    private static int indexOfRadius(CutPath c) {
        double r = ((Arc2) c.part().get(0)).radius();
        return (int) Math.round((r - 5) / 2);
    }

    @Test
    void aPartInsideAHoleIsCutBeforeThatHole() {
        List<Curve2> all = new ArrayList<>(rect(0, 0, 100, 100));
        all.addAll(rect(20, 20, 60, 60));
        all.addAll(rect(40, 40, 20, 20));
        CutPlan p = CutPlanner.plan(Map.of("0", all), plasma(1));
        assertEquals(2, p.outers().size());
        assertEquals(1, p.holes().size());
        assertEquals(
                List.of(true, false, true),
                p.cuts().stream().map(CutPath::outer).toList());
        assertEquals(400 + 4 * 20 * 0.5 + Math.PI * 0.25, p.cuts().get(0).path().area(), 1e-6);
    }

    @Test
    void thePaperFlagsTheSharpCornersOfASquareHoleAsInvalid() {
        List<Curve2> all = new ArrayList<>(rect(0, 0, 100, 100));
        all.addAll(rect(40, 40, 20, 20));
        CutPlan p = CutPlanner.plan(Map.of("0", all), plasma(2).withPaperMode(true));
        assertEquals(4, p.invalidVertices().size());
        assertTrue(p.cuts().get(0).leadIn().isEmpty());
        assertFalse(p.cuts().get(0).outer());
        // sharp offset corners: the hole's path is an 18 x 18 square
        assertEquals(18 * 18, p.cuts().get(0).path().area(), 1e-9);
    }

    @Test
    void leadsStayInTheScrapAndOvercutRunsPastThePierce() {
        CuttingOptions o = plasma(2).withOvercut(2);
        CutPlan p = CutPlanner.plan(Map.of("0", rect(0, 0, 50, 30)), o);
        CutPath c = p.cuts().get(0);
        Contour part = Contour.polygon(List.of(Vec2.ZERO, Vec2.of(50, 0), Vec2.of(50, 30), Vec2.of(0, 30)));
        for (Curve2 l : c.leadIn()) {
            for (int k = 0; k <= 20; k++) {
                assertTrue(part.distanceTo(l.pointAt(k / 20.0)) >= 1 - 1e-9);
            }
        }
        double tail = c.tail().stream().mapToDouble(Curve2::length).sum();
        assertTrue(tail >= 2 + 1 - 1e-9, "overcut 2 mm plus the lead-out");
    }

    @Test
    void partsAreOrderedSoThatNo2OptExchangeShortensTheRapids() {
        java.util.Random rnd = new java.util.Random(42);
        List<Curve2> all = new ArrayList<>();
        for (int i = 0; i < 30; i++) {
            all.addAll(rect(
                    Math.floor(rnd.nextDouble() * 20) * 25,
                    Math.floor(rnd.nextDouble() * 20) * 25 + (i % 2) * 500,
                    10,
                    10));
        }
        CutPlan p = CutPlanner.plan(Map.of("0", all), plasma(2).withAvoidCutParts(false));
        List<Vec2> at = new ArrayList<>();
        at.add(Vec2.ZERO);
        p.cuts().forEach(c -> at.add(c.pierce()));
        int n = at.size();
        assertTrue(n > 20, n + " pierces");
        for (int i = 0; i < n - 2; i++) {
            for (int j = i + 2; j < n; j++) {
                double before = at.get(i).distance(at.get(i + 1))
                        + (j + 1 < n ? at.get(j).distance(at.get(j + 1)) : 0);
                double after = at.get(i).distance(at.get(j))
                        + (j + 1 < n ? at.get(i + 1).distance(at.get(j + 1)) : 0);
                assertTrue(
                        after >= before - 1e-6,
                        "reversing " + (i + 1) + ".." + j + " saves " + (before - after) + " mm");
            }
        }
    }
}
