package org.fresa.cutting;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;
import org.junit.jupiter.api.Test;

class CutOrderTest {

    /** Parts of 20 x 20 mm with a 5 mm hole each, scattered over a 1000 x 600 sheet (fixed seed). */
    static List<Curve2> scatteredParts(int count, long seed) {
        Random r = new Random(seed);
        List<Curve2> all = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            // a 40 x 40 cell per part keeps them apart
            int cx = i % 25;
            int cy = i / 25;
            double x = cx * 40 + r.nextDouble() * 15;
            double y = cy * 40 + r.nextDouble() * 15;
            all.addAll(CutPlannerTest.rect(x, y, 20, 20));
            all.addAll(CutPlannerTest.rect(x + 5 + r.nextDouble() * 8, y + 5 + r.nextDouble() * 8, 5, 5));
        }
        return all;
    }

    /**
     * The travel of a plain nearest-neighbour tour, computed here independently: from the origin
     * to the nearest pierce of a cut whose holes are all cut, then from its exit on.
     */
    static double nearestNeighbourTravel(CutPlan p) {
        List<CutPath> left = new ArrayList<>(p.cuts());
        Vec2 at = Vec2.ZERO;
        double travel = 0;
        while (!left.isEmpty()) {
            CutPath best = null;
            for (CutPath c : left) {
                if (c.outer()
                        && left.stream().anyMatch(h -> !h.outer() && h.label().startsWith(c.label() + " hole"))) {
                    continue;
                }
                if (best == null || c.pierce().distance(at) < best.pierce().distance(at)) {
                    best = c;
                }
            }
            travel += best.pierce().distance(at);
            at = best.exit();
            left.remove(best);
        }
        return travel;
    }

    @Test
    void theCutOrderTravelsLessThanANearestNeighbourTourAndKeepsHolesFirst() {
        CuttingOptions o = CuttingOptions.of(CutProcess.PLASMA, 2, 0, 0, false).withAvoidCutParts(false);
        CutPlan p = CutPlanner.plan(Map.of("0", scatteredParts(300, 7)), o);
        assertEquals(600, p.cuts().size());
        List<String> done = new ArrayList<>();
        for (CutPath c : p.cuts()) {
            if (c.outer()) {
                assertTrue(done.contains(c.label() + " hole 1"), c.label() + " cut before its hole");
            }
            done.add(c.label());
        }
        double nn = nearestNeighbourTravel(p);
        double got = p.rapidLengthMm();
        // the measured figure: 0.8x or better of the plain tour on this sheet
        System.out.printf(
                java.util.Locale.ROOT,
                "CutOrderTest: rapid %.1f mm, nearest-neighbour tour %.1f mm (%.3f)%n",
                got,
                nn,
                got / nn);
        assertTrue(got <= nn * 0.9, got + " mm of rapids, the nearest-neighbour tour " + nn + " mm");
    }

    @Test
    void anImprovedOrderIsNeverLongerThanItsStart() {
        Random r = new Random(3);
        List<Vec2> pts = new ArrayList<>();
        List<int[]> before = new ArrayList<>();
        for (int i = 0; i < 400; i++) {
            pts.add(Vec2.of(r.nextDouble() * 500, r.nextDouble() * 500));
            // every fourth cut holds the three before it
            before.add(i % 4 == 3 ? new int[] {i - 3, i - 2, i - 1} : new int[0]);
        }
        CutOrder co = new CutOrder(pts, pts, before);
        int[] nn = co.nearestNeighbour();
        int[] better = co.improve(nn, Long.MAX_VALUE / 2);
        int[] pos = new int[400];
        for (int k = 0; k < 400; k++) {
            pos[better[k]] = k;
        }
        for (int i = 0; i < 400; i++) {
            for (int b : before.get(i)) {
                assertTrue(pos[b] < pos[i], "cut " + b + " before " + i);
            }
        }
        assertTrue(co.travel(better) <= co.travel(nn));
        assertTrue(co.travel(better) < 0.95 * co.travel(nn), co.travel(better) + " vs " + co.travel(nn));
    }

    /**
     * The budget counts moves looked at, not time: a short budget stops the improvement at the
     * same order whatever the machine's load, so the tab's preview and a run of the saved job agree.
     */
    @Test
    void theWorkBudgetNotTheClockEndsTheImprovement() {
        Random r = new Random(11);
        List<Vec2> pts = new ArrayList<>();
        List<int[]> before = new ArrayList<>();
        for (int i = 0; i < 2000; i++) {
            pts.add(Vec2.of(r.nextDouble() * 1000, r.nextDouble() * 1000));
            before.add(new int[0]);
        }
        int[] nn = new CutOrder(pts, pts, before).nearestNeighbour();
        CutOrder first = new CutOrder(pts, pts, before);
        int[] shortRun = first.improve(nn, 20_000);
        assertTrue(first.work() < 20_000 + 2_000, "work " + first.work());
        CutOrder second = new CutOrder(pts, pts, before);
        assertTrue(java.util.Arrays.equals(shortRun, second.improve(nn, 20_000)));
        CutOrder whole = new CutOrder(pts, pts, before);
        int[] longRun = whole.improve(nn, Long.MAX_VALUE / 2);
        assertTrue(whole.travel(longRun) < whole.travel(shortRun), "the short budget stopped the improvement early");
    }
}
