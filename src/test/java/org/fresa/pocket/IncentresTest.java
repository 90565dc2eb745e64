package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

class IncentresTest {

    @Test
    void appendixACircleCircleLineIncentreIsTheSmallerRoot() {
        PocketElement c1 = new PocketElement(1, true, -1, 0, 2, 1, 'S');
        PocketElement c2 = new PocketElement(2, true, 3, -1, 5, -1, 'S');
        PocketElement l3 = new PocketElement(3, false, 1, 0, 1, -1, 'S');
        List<Incentres.Solution> s = Incentres.of(c1, c2, l3);
        assertEquals(2, s.size());
        // 121 t² - 228 t + 100 = 0
        assertEquals((228 - Math.sqrt(3584)) / 242, s.get(0).t(), 1e-12);
        assertEquals(0.69477, s.get(0).t(), 1e-5);
        assertEquals(1.18953, s.get(1).t(), 1e-5);
        assertEquals(0.30523, s.get(0).point().x(), 1e-5);
        // the thesis substitutes the rounded t = .69477; the exact root gives y = 2.357569
        assertEquals(2.35753, s.get(0).point().y(), 5e-5);
    }

    @Test
    void threeLinesGiveTheInradius() {
        // the unit right triangle (0,0) (0,1) (1,0), clockwise: x = 0 up, y = 1 - x, y = 0 back
        PocketElement a = new PocketElement(1, false, 1, 0, 0, 1, 'S');
        PocketElement b = new PocketElement(2, false, Math.sqrt(0.5), Math.sqrt(0.5), Math.sqrt(0.5), -1, 'S');
        PocketElement c = new PocketElement(3, false, 0, 1, 0, 1, 'S');
        Incentres.Solution s = Incentres.of(a, b, c).get(0);
        assertEquals(1 - Math.sqrt(0.5), s.t(), 1e-12);
        assertEquals(s.t(), s.point().x(), 1e-12);
    }
}
