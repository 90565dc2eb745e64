package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.fresa.geom.Vec2;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class PassPlannerTest {

    static PocketPlan plan(String name, PocketTechnology t) throws Exception {
        return PassPlanner.plan(Recognition.of(RecognitionTest.sample(name)), t);
    }

    static List<Double> offsets(PocketPlan p) {
        return p.generated().stream().map(PocketPass::offsetMm).toList();
    }

    static void assertOffsets(List<Double> expected, List<Double> actual) {
        assertEquals(expected.size(), actual.size(), actual.toString());
        for (int i = 0; i < expected.size(); i++) {
            assertEquals(expected.get(i), actual.get(i), 1e-4, actual.toString());
        }
    }

    @Test
    void cavity01PassesAndTheMidpointLastPass() throws Exception {
        PocketPlan p = plan("cavity01.dad", new PocketTechnology(6, 0.62, 0.13, 30, 27, 3, 3200, 290, 100));
        assertOffsets(List.of(3.0, 3.78, 7.5, 11.22, 14.94, 17.15267), offsets(p));
        PocketPass inner = p.milled().get(0);
        List<Vec2> v = inner.pieces().stream().map(PassPiece::start).toList();
        assertEquals(
                List.of(new Vec2(34.979, 46.847), new Vec2(49.458, 46.847), new Vec2(50.578, 43.325)),
                v.stream()
                        .map(q -> new Vec2(Math.rint(q.x() * 1000) / 1000, Math.rint(q.y() * 1000) / 1000))
                        .toList());
        PocketPass outer = p.generated().get(0);
        assertEquals(6, outer.pieces().size());
        assertEquals(17.0, outer.start().x(), 1e-3);
        assertEquals(54.146, outer.start().y(), 1e-3);
    }

    @Test
    void cavity02InnermostPassIsClampedIntoTheFinalSubcontour() throws Exception {
        PocketPlan p = plan("cavity02.dad", new PocketTechnology(42, 0.74, 0.15, 23, 20, 5, 3000, 300, 100));
        assertOffsets(List.of(21.0, 27.3, 58.38, 89.46, 110.0623), offsets(p));
        PocketPass inner = p.milled().get(0);
        assertEquals(149.930, inner.start().x(), 1e-3);
        assertEquals(133.062, inner.start().y(), 1e-3);
        assertEquals(170.544, inner.pieces().get(1).start().x(), 1e-3);
        assertEquals(139.535, inner.pieces().get(1).start().y(), 1e-3);
        assertEquals(316, inner.pieces().get(1).center().x(), 1e-9);
        assertEquals(
                196.062,
                inner.pieces().get(1).start().distance(inner.pieces().get(1).center()),
                1e-3);
    }

    /**
     * Cavity 05 divides at 11.535 (arcs 8 and 12 across line 10) into the main area and the sliver
     * {8, 10, 12}, whose leaf is 11.766: the sub-area begins and ends between the parent's passes
     * 6.7 and 13.9. The thesis's printed program (Tab. D.5) mills only the main area (52 blocks,
     * one sub-area, no hop); Fresa's default mills the sliver too.
     */
    @Test
    void cavity05SliverBetweenTwoPassesGetsAPassOnlyByDefault() throws Exception {
        PocketTechnology t = new PocketTechnology(10, 0.72, 0.17, 15, 12, 4, 3250, 295, 90);
        Recognition.Result rec = Recognition.of(RecognitionTest.sample("cavity05.dad"));
        PocketPlan thesis = PassPlanner.plan(rec, t, true);
        PocketPlan fresa = PassPlanner.plan(rec, t, false);
        assertOffsets(List.of(5.0, 6.7, 13.9, 20.96666), offsets(thesis));
        int sliver = rec.root().children().get(1).id();
        assertEquals(
                0, thesis.generated().stream().filter(p -> p.nodeId() == sliver).count());
        List<PocketPass> inSliver =
                fresa.generated().stream().filter(p -> p.nodeId() == sliver).toList();
        assertEquals(1, inSliver.size());
        // the default's stepover stops at d + R = 11.7 where the subcontour changes
        assertEquals(11.7, inSliver.get(0).offsetMm(), 1e-6);
    }

    @Test
    void cavity03CorrectsTheStepoverForTheSharpCornerOfTheParent() throws Exception {
        PocketPlan p = plan("cavity03.dad", new PocketTechnology(6, 0.73, 0.22, 30, 27, 5, 2750, 280, 90));
        // the seed rounds s to 4.1919; the NC radius 33.579 - 20.687 confirms 12.892
        assertOffsets(List.of(3.0, 4.32, 8.70, 8.70, 12.89176, 17.27176), offsets(p));
        double alpha = Recognition.of(RecognitionTest.sample("cavity03.dad"))
                .root()
                .stateAt(5.7)
                .minAngleDeg(5.7);
        assertEquals(49.32, alpha, 0.01);
        assertEquals(0.69865, PassPlanner.stepoverFraction(0.73, alpha), 5e-5);
    }

    @ParameterizedTest
    @CsvSource(textBlock = """
            0.50, 0
            0.55, 11.5
            0.60, 23.1
            0.65, 34.9
            0.70, 47.2
            0.75, 60.0
            0.80, 73.7
            0.90, 106.3
            1.00, 180
            """)
    void table74SmallestAngleWithoutCorrection(double p, double angleDeg) {
        assertEquals(angleDeg, PassPlanner.minAngleWithoutCorrectionDeg(p), 0.06);
    }

    @Test
    void aFiftyDegreeCornerAtSeventyFivePercentCutsAtSeventyPointThirteen() {
        assertEquals(0.7013, PassPlanner.stepoverFraction(0.75, 50), 1e-4);
        assertEquals(0.75, PassPlanner.stepoverFraction(0.75, 61), 1e-12);
        assertEquals(0.5, PassPlanner.stepoverFraction(0.3, 120), 1e-12);
    }

    @Test
    void aToolLargerThanTheLargestHoleIsRefused() {
        assertThrows(
                ToolTooLargeException.class,
                () -> plan("examplepart.dad", new PocketTechnology(16, 0.6, 0.1, 8, 6, 2, 3000, 300, 100)));
    }
}
