package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.post.Rs274;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.locationtech.jts.geom.Geometry;

/**
 * Zigzag pockets, checked as {@link PocketCleanUpTest} checks the offset ones: from what
 * LinuxCNC's interpreter makes of the program, the tool disc swept at the floor leaves less than
 * 0.05 mm2 of the material the tool can reach and never comes within the wall by 0.01 mm; on the
 * thesis's eight contours and on 100 random pockets with 0 to 3 islands (the same generator and
 * seed), each at two angles.
 */
class ZigzagPocketTest {

    private static final double[] ANGLES_DEG = {0, 37};

    @ParameterizedTest
    @ValueSource(
            strings = {"examplepart", "cavity01", "cavity02", "cavity03", "cavity04", "cavity05", "cavity06", "cavity07"
            })
    @InterpreterCheck
    void theThesisContoursInZigzagLeaveNoSliverAndNeverCutAWall(String name, @TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        PocketTechnology t = PocketCoverageTest.tech(name);
        PocketProfile profile = RecognitionTest.sample(name + ".dad");
        // the wall as drawn (not the thesis's pass grown by R: its offset of a line whose (A, B) is
        // not of unit length, cavity 01's element 4, lies 2.924 mm from it, not 3)
        Geometry wall = RegionPocketTest.polygon(profile.outline());
        Geometry reachable = wall.buffer(-t.radiusMm(), 32).buffer(t.radiusMm(), 32);
        for (double angle : ANGLES_DEG) {
            ZigzagPocket.Plan plan = ZigzagPocket.plan(profile.outline(), List.of(), t, angle, true, EntryRule.DEFAULT);
            PocketCleanUpTest.Verdict v = PocketCleanUpTest.verdict(
                    PocketCleanUpTest.interpreted(plan.toolpath(), dir, name + "_" + (int) angle),
                    t.zBottomMm(),
                    t.zTopMm(),
                    t.radiusMm(),
                    wall,
                    reachable);
            System.out.printf(
                    Locale.ROOT,
                    "%s zigzag %.0f deg: %d lines in %d cuts, uncut %.4f mm2, gouge %.4f mm%n",
                    name,
                    angle,
                    plan.lines(),
                    plan.order().size(),
                    v.uncutMm2(),
                    v.gougeMm());
            assertTrue(plan.lines() > 0, name + ": no zigzag line");
            assertTrue(v.uncutMm2() < PocketCleanUpTest.UNCUT_MM2, name + " leaves " + v.uncutMm2() + " mm2");
            assertTrue(v.gougeMm() < PocketCleanUpTest.GOUGE_MM, name + " cuts the wall by " + v.gougeMm() + " mm");
        }
    }

    @Test
    @InterpreterCheck
    void randomPocketsWithIslandsInZigzagLeaveNoSliverAndNeverCutAWall(@TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        Random rnd = new Random(21);
        int done = 0;
        double worst = 0;
        double worstGouge = 0;
        int[] byIslands = new int[4];
        List<String> bad = new ArrayList<>();
        for (int attempt = 0; done < PocketCleanUpTest.POCKETS && attempt < 3 * PocketCleanUpTest.POCKETS; attempt++) {
            List<Contour> p = PocketCleanUpTest.pocket(rnd);
            PocketTechnology t = PocketCleanUpTest.tech(rnd);
            // each pocket at one of the two angles, and every angle also turned by a random amount
            double angle = (done % 2 == 0 ? ANGLES_DEG[0] : ANGLES_DEG[1]) + (done % 4 >= 2 ? -90 : 0);
            ZigzagPocket.Plan plan;
            try {
                plan = ZigzagPocket.plan(p.get(0), p.subList(1, p.size()), t, angle, true, EntryRule.DEFAULT);
            } catch (ToolTooLargeException | IllegalArgumentException e) {
                continue;
            }
            Geometry wall = RegionPocketTest.region(p);
            Geometry reachable = wall.buffer(-t.radiusMm(), 32).buffer(t.radiusMm(), 32);
            PocketCleanUpTest.Verdict v = PocketCleanUpTest.verdict(
                    PocketCleanUpTest.interpreted(plan.toolpath(), dir, "z" + done),
                    t.zBottomMm(),
                    t.zTopMm(),
                    t.radiusMm(),
                    wall,
                    reachable);
            worst = Math.max(worst, v.uncutMm2());
            worstGouge = Math.max(worstGouge, v.gougeMm());
            if (v.uncutMm2() >= PocketCleanUpTest.UNCUT_MM2 || v.gougeMm() >= PocketCleanUpTest.GOUGE_MM) {
                bad.add(String.format(
                        Locale.ROOT,
                        "pocket %d (%d islands, %.0f deg): uncut %.4f mm2, gouge %.4f mm",
                        done,
                        p.size() - 1,
                        angle,
                        v.uncutMm2(),
                        v.gougeMm()));
            }
            byIslands[p.size() - 1]++;
            done++;
        }
        System.out.printf(
                Locale.ROOT,
                "zigzag random pockets %d (islands 0..3: %d %d %d %d): worst uncut %.4f mm2, worst gouge %.4f mm%n",
                done,
                byIslands[0],
                byIslands[1],
                byIslands[2],
                byIslands[3],
                worst,
                worstGouge);
        assertEquals(PocketCleanUpTest.POCKETS, done);
        assertTrue(bad.isEmpty(), bad.size() + " pockets fail: " + bad);
    }

    @Test
    void theLinesRunAtTheAngleAskedForAndAlternate() throws Exception {
        Contour square = Contour.polygon(List.of(new Vec2(0, 0), new Vec2(60, 0), new Vec2(60, 40), new Vec2(0, 40)));
        PocketTechnology t = new PocketTechnology(6, 0.6, 0.1, 0, -3, 3, 3000, 300, 100);
        for (double angle : new double[] {0, 30, 90, -45}) {
            ZigzagPocket.Plan plan = ZigzagPocket.plan(square, List.of(), t, angle, true, EntryRule.DEFAULT);
            // a convex pocket: one chain of lines linked along the pre-finish offset, then the two contour passes
            assertEquals(3, plan.order().size(), angle + " deg: " + plan.order().size() + " cuts");
            Vec2 u = Vec2.ofAngle(Math.toRadians(angle));
            int lines = 0;
            double previous = 0;
            for (Curve2 c : plan.order().get(0).curves()) {
                Vec2 d = c.end().minus(c.start());
                if (c instanceof Segment2
                        && d.norm() > 1e-3
                        && Math.abs(d.normalized().cross(u)) < 1e-9) {
                    double along = d.dot(u);
                    assertTrue(lines == 0 || Math.signum(along) != Math.signum(previous), "lines alternate");
                    previous = along;
                    lines++;
                }
            }
            assertEquals(plan.lines(), lines, angle + " deg");
            assertTrue(plan.order().get(1).closed() && plan.order().get(2).finishing());
        }
    }

    @Test
    void theStepBetweenLinesIsAtMostTheStepoverAndArcsStayArcs() throws Exception {
        Contour disc = new Contour(List.of(Arc2.circle(new Vec2(0, 0), 30, true)));
        PocketTechnology t = new PocketTechnology(10, 0.8, 0.1, 0, -2, 2, 3000, 300, 100);
        ZigzagPocket.Plan plan = ZigzagPocket.plan(disc, List.of(), t, 0, true, EntryRule.DEFAULT);
        // the pre-finish circle spans 2 (30 - 5 - 1) = 48 mm: 6 lines 8 mm apart (the stepover, 0.8 D)
        assertEquals(6, plan.lines());
        Toolpath path = plan.toolpath();
        long arcs = path.sections().get(0).moves().stream()
                .filter(m -> m instanceof Move.Circular)
                .count();
        assertTrue(arcs >= 4, "the contour passes and the links along the offset are arcs: " + arcs);
    }
}
