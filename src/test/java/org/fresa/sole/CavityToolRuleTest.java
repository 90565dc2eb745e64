package org.fresa.sole;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.model.ContourFile;
import org.junit.jupiter.api.Test;

/** Figure 6.16: the cavity cutter smaller than the outline's smallest arc. */
class CavityToolRuleTest {

    static Contour men40() throws Exception {
        try (Reader r = Files.newBufferedReader(Path.of("samples/sole/men40.contour"))) {
            return ContourFile.read(r, "men40.contour").get(0);
        }
    }

    @Test
    void theThesissToolsFitAndASixtyMillimetreOneDoesNot() throws Exception {
        Contour outline = men40();
        // the real 25 mm end mill and the largest fictitious cutter the thesis declared (47 mm)
        assertTrue(CavityToolRule.check(outline, 25).isEmpty());
        assertTrue(CavityToolRule.check(outline, 47).isEmpty());
        CavityToolRule.Violation v = CavityToolRule.check(outline, 60).orElseThrow();
        // the toe arc C7 (8th element: C1, C2, C3, L1, C4, C5, C6, C7), radius 27.37 (27.92 graded at 1.02)
        assertEquals(8, v.elementIndex());
        assertEquals(27.37, v.arc().radius(), 0.01);
        assertTrue(v.sentence().contains("arc 8") && v.sentence().contains("54.7"), v.sentence());
    }

    @Test
    void aToolAsLargeAsTheArcIsRefused() throws Exception {
        double d = 2 * CavityToolRule.check(men40(), 60).orElseThrow().arc().radius();
        assertTrue(CavityToolRule.check(men40(), d).isPresent());
        assertTrue(CavityToolRule.check(men40(), d - 1e-6).isEmpty());
    }

    @Test
    void anArcBendingAwayFromTheCavityDoesNotLimitTheTool() {
        // a 40 x 40 square whose top side has a notch bulging into the cavity: a clockwise arc
        // of radius 2 in a counter-clockwise outline, its centre outside the cavity
        Tolerance tol = Tolerance.DEFAULT;
        List<Curve2> curves = List.of(
                Segment2.of(0, 0, 40, 0),
                Segment2.of(40, 0, 40, 40),
                Segment2.of(40, 40, 22, 40),
                Arc2.cw(Vec2.of(20, 40), Vec2.of(22, 40), Vec2.of(18, 40), tol),
                Segment2.of(18, 40, 0, 40),
                Segment2.of(0, 40, 0, 0));
        Contour notched = Contour.of(curves, tol);
        assertTrue(notched.isCcw());
        assertTrue(CavityToolRule.check(notched, 10).isEmpty());
        assertTrue(CavityToolRule.check(notched.reversed(), 10).isEmpty());
    }
}
