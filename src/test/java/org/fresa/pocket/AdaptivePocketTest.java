package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.fresa.geom.Contour;
import org.fresa.model.ToolpathSection;
import org.fresa.post.Rs274;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.locationtech.jts.geom.Geometry;

/**
 * The adaptive planner ({@link AdaptivePocket}) as it stands, refused by the command line until
 * it holds its engagement along the walls too: from LinuxCNC's interpreter's moves, measured with
 * JTS as the other strategies are, it leaves less than 0.05 mm2 of the floor the tool can reach
 * and cuts no wall by 0.01 mm; measured by {@link Engagement}, it never takes the full-width cut
 * the offset passes take at their first loop (which fail the same measure at 180 degrees).
 */
class AdaptivePocketTest {

    @Test
    @InterpreterCheck
    void theWalksLeaveNoFloorCutNoWallAndTakeNoFullWidthCut(@TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        for (String name : new String[] {"cavity01", "cavity05"}) {
            check(name, List.of(RecognitionTest.sample(name + ".dad").outline()), PocketCoverageTest.tech(name), dir);
        }
    }

    private static void check(String name, List<Contour> p, PocketTechnology t, Path dir) throws Exception {
        AdaptivePocket.Plan plan = AdaptivePocket.plan(p.get(0), p.subList(1, p.size()), t, true, EntryRule.DEFAULT);
        Geometry wall = RegionPocketTest.region(p);
        Geometry reachable = wall.buffer(-t.radiusMm(), 32).buffer(t.radiusMm(), 32);
        PocketCleanUpTest.Verdict v = PocketCleanUpTest.verdict(
                PocketCleanUpTest.interpreted(plan.toolpath(), dir, name),
                t.zBottomMm(),
                t.zTopMm(),
                t.radiusMm(),
                wall,
                reachable);
        List<Contour> boundary = RegionOffsetter.oriented(p.get(0), p.subList(1, p.size()));
        ToolpathSection a = plan.toolpath().sections().get(0);
        Engagement adaptive = Engagement.of(boundary, t.radiusMm(), a.start(), a.moves(), t.finishFeedMmPerMin());
        ToolpathSection o = RegionPocket.plan(p.get(0), p.subList(1, p.size()), t, true, EntryRule.DEFAULT)
                .toolpath()
                .sections()
                .get(0);
        Engagement offset = Engagement.of(boundary, t.radiusMm(), o.start(), o.moves(), t.finishFeedMmPerMin());
        double stepover = t.cutFraction() * t.toolDiameterMm();
        double bound = Engagement.angleDeg(1.1 * stepover, t.radiusMm());
        System.out.printf(
                Locale.ROOT,
                "%s D%.0f cut %.2f: %d walks, uncut %.4f mm2, gouge %.4f mm; engagement (bound %.1f deg) adaptive max"
                        + " %.1f mean %.1f, offset max %.1f mean %.1f; finishing pass max %.1f / %.1f%n",
                name,
                t.toolDiameterMm(),
                t.cutFraction(),
                plan.walks(),
                v.uncutMm2(),
                v.gougeMm(),
                bound,
                adaptive.maxDeg(),
                adaptive.meanDeg(),
                offset.maxDeg(),
                offset.meanDeg(),
                adaptive.finishingMaxDeg(),
                offset.finishingMaxDeg());
        assertTrue(v.uncutMm2() < PocketCleanUpTest.UNCUT_MM2, name + " leaves " + v.uncutMm2() + " mm2");
        assertTrue(v.gougeMm() < PocketCleanUpTest.GOUGE_MM, name + " cuts the wall by " + v.gougeMm() + " mm");
        // the offset passes slot their first loop: the measure sees it
        assertTrue(offset.maxDeg() > 170, name + ": offset " + offset.maxDeg());
        // the walks never slot (the entry helix aside) and stay in the mean at the stepover's angle
        assertTrue(adaptive.maxDeg() < 160, name + ": adaptive " + adaptive.maxDeg() + " deg at " + adaptive.worstAt());
        assertTrue(
                adaptive.meanDeg() < Engagement.angleDeg(stepover, t.radiusMm()),
                name + ": adaptive mean " + adaptive.meanDeg());
    }
}
