package org.fresa.grading;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.fresa.geom.Vec2;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Seed 6.4: one heel per group of three sizes, mouth-test data NP 35. */
class CoordinationTest {

    private static final GradingRule MOUTH =
            new GradingRule(SizeSystem.BR, 35, 6.66, 1.66, 259, 96, 0, ShrinkageMode.ADDITIVE);
    private static final GradingFrame THESIS = GradingFrame.alongY(Vec2.ZERO);
    private static final Coordination BALL_LINE = new Coordination(150, 3);

    @ParameterizedTest
    @CsvSource(textBlock = """
            31, 32
            32, 32
            33, 32
            34, 35
            35, 35
            36, 35
            37, 38
            38, 38
            39, 38
            40, 41
            41, 41
            42, 41
            """)
    void sizesShareTheHeelOfTheMiddleSizeOfTheirGroup(double nd, double nbc) {
        assertEquals(nbc, BALL_LINE.heelSize(nd, 35, SizeSystem.BR), 1e-12);
    }

    @Test
    void size37GradesItsForepartAs37AndItsHeelAs38() {
        ScaleFactors fore = MOUTH.factors(37);
        ScaleFactors heel = MOUTH.factors(BALL_LINE.heelSize(37, 35, SizeSystem.BR));
        Vec2 heelPoint = PantographMap.of(THESIS, heel).apply(new Vec2(10, 100));
        Vec2 forePoint = PantographMap.of(THESIS, fore).apply(new Vec2(10, 100));
        assertAll(
                () -> assertEquals(1.034583333, fore.alfa(), 1e-9),
                () -> assertEquals(1.051428571, fore.beta(), 1e-9),
                () -> assertEquals(1.051875, heel.alfa(), 1e-9),
                () -> assertEquals(1.077142857, heel.beta(), 1e-9),
                () -> assertEquals(10.51875, heelPoint.x(), 1e-7),
                () -> assertEquals(107.7142857, heelPoint.y(), 1e-7),
                () -> assertEquals(10.3458333, forePoint.x(), 1e-7),
                () -> assertEquals(105.1428571, forePoint.y(), 1e-7));
    }

    @Test
    void pointsOnTheBoundaryBelongToTheHeel() {
        assertAll(() -> assertEquals(true, BALL_LINE.isHeel(150)), () -> assertEquals(false, BALL_LINE.isHeel(150.01)));
    }

    @Test
    void sizes34To36KeepThePatternsHeelAndTheOutlineStaysClosed() {
        EscomPattern base = ThesisPatterns.mouldMouth35();
        for (double nd : new double[] {34, 35, 36}) {
            PantographMap fore = PantographMap.of(THESIS, MOUTH.factors(nd));
            PantographMap heel = PantographMap.of(THESIS, MOUTH.factors(BALL_LINE.heelSize(nd, 35, SizeSystem.BR)));
            EscomPattern g = base.graded(n -> BALL_LINE.isHeel(base.point(n).y()) ? heel : fore);
            base.points().forEach((n, p) -> {
                if (BALL_LINE.isHeel(p.y())) {
                    assertEquals(p, g.point(n));
                }
            });
            org.fresa.geom.Contour c = g.toContour();
            for (int i = 0; i < c.size(); i++) {
                assertEquals(
                        0, c.get(i).end().distance(c.get((i + 1) % c.size()).start()), 1e-9);
            }
        }
    }

    /**
     * Figure 4.4: the planner names the heel's elements (the CONTORNO INFERIOR). On the mould
     * mouth: elements 1-4 (C P1-P21-P2 .. the line P4-P5) and 18-20 (C P18-P30-P19, the line
     * P19-P20, C P20-P31-P1). Their points grade as the heel NBC 38, the junctions P5 and P18 with
     * the forepart included; every other point as ND 37.
     */
    @Test
    void theDesignatedHeelElementsAndTheirJunctionsGradeWithTheHeel() {
        EscomPattern base = ThesisPatterns.mouldMouth35();
        Coordination co = Coordination.ofHeelElements(java.util.List.of(1, 2, 3, 4, 18, 19, 20), 3);
        assertEquals(java.util.Optional.empty(), co.misfit(base));
        PantographMap fore = PantographMap.of(THESIS, MOUTH.factors(37));
        PantographMap heel = PantographMap.of(THESIS, MOUTH.factors(co.heelSize(37, 35, SizeSystem.BR)));
        EscomPattern g = base.graded(n -> co.isHeelPoint(base, n, base.point(n).y()) ? heel : fore);
        for (String n : java.util.List.of("P1", "P2", "P5", "P18", "P19", "P20", "P21", "P30", "P31")) {
            assertEquals(heel.apply(base.point(n)), g.point(n), n + " is a heel point");
        }
        for (String n : java.util.List.of("P6", "P17", "P24", "P29", "P10")) {
            assertEquals(fore.apply(base.point(n)), g.point(n), n + " is a forepart point");
        }
        // P5 (31, 44) lies ahead of a ball line at 40 mm and P17 (-34.5, 139) far ahead: the
        // elements, not the distance, decide
        assertEquals(false, new Coordination(40, 3).isHeel(base.point("P5").y()));
        org.fresa.geom.Contour c = g.toContour();
        for (int i = 0; i < c.size(); i++) {
            assertEquals(0, c.get(i).end().distance(c.get((i + 1) % c.size()).start()), 1e-9);
        }
    }

    @Test
    void heelElementsTheOutlineDoesNotHaveOrNoForepartAreRefused() {
        EscomPattern base = ThesisPatterns.mouldMouth35();
        assertEquals(
                "heel element 21 does not exist: the outline has 20 elements",
                Coordination.ofHeelElements(java.util.List.of(1, 21), 3)
                        .misfit(base)
                        .orElseThrow());
        java.util.List<Integer> all = new java.util.ArrayList<>();
        for (int i = 1; i <= 20; i++) {
            all.add(i);
        }
        assertEquals(
                true,
                Coordination.ofHeelElements(all, 3).misfit(base).orElseThrow().contains("every element"));
        org.junit.jupiter.api.Assertions.assertThrows(
                IllegalArgumentException.class, () -> Coordination.ofHeelElements(java.util.List.of(), 3));
    }
}
