package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.fresa.geom.Contour;
import org.fresa.geom.Vec2;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.post.Rs274;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.locationtech.jts.geom.Geometry;

/**
 * Stock to leave and the offset passes' order ({@link StrategyPocket}), checked from LinuxCNC's
 * interpreter's moves with JTS on seeded random pockets with 0 to 3 islands: with stock s the
 * tool never comes nearer the walls than s (within 0.01 mm) and leaves no more than s (the region
 * less s cut within 0.05 mm2), and its lowest feed is the floor plus s; outside in, the first
 * pass is the outermost roughing one and the finishing pass is still last.
 */
class StockAndOrderTest {

    private static final int POCKETS = 20;

    @Test
    @InterpreterCheck
    void stockIsLeftOnWallsIslandsAndFloorAndNoMore(@TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        Random rnd = new Random(2121);
        int done = 0;
        List<String> bad = new ArrayList<>();
        double nearest = Double.POSITIVE_INFINITY;
        double worstUncut = 0;
        for (int attempt = 0; done < POCKETS && attempt < 3 * POCKETS; attempt++) {
            List<Contour> p = PocketCleanUpTest.pocket(rnd);
            PocketTechnology t = PocketCleanUpTest.tech(rnd);
            double stock = done % 2 == 0 ? 0.5 : 1.2;
            PocketStrategy st = done % 3 == 0
                    ? new PocketStrategy(PocketStrategy.Kind.ZIGZAG, 15, stock, PocketStrategy.Order.INSIDE_OUT)
                    : new PocketStrategy(
                            PocketStrategy.Kind.OFFSET,
                            0,
                            stock,
                            done % 3 == 1 ? PocketStrategy.Order.INSIDE_OUT : PocketStrategy.Order.OUTSIDE_IN);
            Toolpath path;
            try {
                path = StrategyPocket.toolpath(p.get(0), p.subList(1, p.size()), t, st, true, EntryRule.DEFAULT);
            } catch (ToolTooLargeException | IllegalArgumentException e) {
                continue;
            }
            double floor = t.zBottomMm() + stock;
            // what the tool may cut: the region less the stock; what it must cut: all of that it can reach
            Geometry wall = RegionPocketTest.region(p).buffer(-stock, 32);
            Geometry reachable = wall.buffer(-t.radiusMm(), 32).buffer(t.radiusMm(), 32);
            List<Rs274.Canon> moves = PocketCleanUpTest.interpreted(path, dir, "s" + done);
            PocketCleanUpTest.Verdict v =
                    PocketCleanUpTest.verdict(moves, floor, t.zTopMm(), t.radiusMm(), wall, reachable);
            double lowest = moves.stream().mapToDouble(m -> m.end().z()).min().orElseThrow();
            nearest = Math.min(nearest, stock - v.gougeMm());
            worstUncut = Math.max(worstUncut, v.uncutMm2());
            if (v.gougeMm() >= PocketCleanUpTest.GOUGE_MM
                    || v.uncutMm2() >= PocketCleanUpTest.UNCUT_MM2
                    || Math.abs(lowest - floor) > 1e-3) {
                bad.add(String.format(
                        Locale.ROOT,
                        "pocket %d (%s, stock %.1f): into the stock %.4f mm, uncut %.4f mm2, lowest Z %.4f",
                        done,
                        st.kind().word() + " " + st.order().word(),
                        stock,
                        v.gougeMm(),
                        v.uncutMm2(),
                        lowest));
            }
            done++;
        }
        System.out.printf(
                Locale.ROOT,
                "stock to leave: %d pockets, stock left at least its value less %.4f mm, worst uncut %.4f mm2%n",
                done,
                Math.max(0, -(nearest - 0.5)),
                worstUncut);
        assertEquals(POCKETS, done);
        assertTrue(bad.isEmpty(), bad.size() + " pockets fail: " + bad);
    }

    @Test
    void outsideInStartsAtTheOutermostRoughingPassAndFinishesLast() throws Exception {
        Contour outer = Contour.polygon(List.of(new Vec2(0, 0), new Vec2(80, 0), new Vec2(80, 50), new Vec2(0, 50)));
        Contour island =
                Contour.polygon(List.of(new Vec2(30, 20), new Vec2(30, 30), new Vec2(45, 30), new Vec2(45, 20)));
        PocketTechnology t = new PocketTechnology(6, 0.6, 0.1, 0, -3, 3, 3000, 300, 100);
        List<Contour> boundary = RegionOffsetter.oriented(outer, List.of(island));
        RegionPocket.Plan in = RegionPocket.plan(boundary, t, true, EntryRule.DEFAULT, true, false);
        RegionPocket.Plan out = RegionPocket.plan(boundary, t, true, EntryRule.DEFAULT, true, true);
        int deepest = in.levels().size() - 1;
        assertEquals(deepest, in.order().get(0).level(), "inside out: the innermost pass first");
        assertEquals(1, out.order().get(0).level(), "outside in: the pre-finish pass first");
        assertEquals(0, in.order().get(in.order().size() - 1).level(), "inside out: finishing last");
        assertEquals(0, out.order().get(out.order().size() - 1).level(), "outside in: finishing last");
        assertEquals(in.order().size(), out.order().size(), "the same loops");
        // the first cutting move at the floor lies on the outermost roughing loop, not near the middle
        Vec2 first = firstAtFloor(out.toolpath(), t.zBottomMm());
        assertTrue(
                out.levels().get(1).loops().stream().anyMatch(l -> l.distanceTo(first) < 1e-6),
                "the program starts on the pre-finish loop: " + first);
    }

    @Test
    void stockAsDeepAsThePocketIsRefused() {
        Contour outer = Contour.polygon(List.of(new Vec2(0, 0), new Vec2(80, 0), new Vec2(80, 50), new Vec2(0, 50)));
        PocketTechnology t = new PocketTechnology(6, 0.6, 0.1, 0, -3, 3, 3000, 300, 100);
        PocketStrategy st = new PocketStrategy(PocketStrategy.Kind.OFFSET, 0, 3, PocketStrategy.Order.INSIDE_OUT);
        assertThrows(
                IllegalArgumentException.class,
                () -> StrategyPocket.toolpath(outer, List.of(), t, st, true, EntryRule.DEFAULT));
    }

    private static Vec2 firstAtFloor(Toolpath path, double z) {
        for (Move m : path.sections().get(0).moves()) {
            if (!(m instanceof Move.Rapid) && Math.abs(m.end().z() - z) < 1e-9) {
                return new Vec2(m.end().x(), m.end().y());
            }
        }
        throw new AssertionError("no move at the floor");
    }
}
