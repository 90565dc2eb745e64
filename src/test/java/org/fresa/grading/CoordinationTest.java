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
        assertAll(() -> assertEquals(1.034583333, fore.alfa(), 1e-9), () -> assertEquals(1.051428571, fore.beta(), 1e-9),
                () -> assertEquals(1.051875, heel.alfa(), 1e-9), () -> assertEquals(1.077142857, heel.beta(), 1e-9),
                () -> assertEquals(10.51875, heelPoint.x(), 1e-7), () -> assertEquals(107.7142857, heelPoint.y(), 1e-7),
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
                assertEquals(0, c.get(i).end().distance(c.get((i + 1) % c.size()).start()), 1e-9);
            }
        }
    }
}
