package org.fresa.kin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.junit.jupiter.api.Test;

/** The table placement search on small parts whose answer is known. */
class PlacementSearchTest {

    static final Vec3 DOWN = new Vec3(0, 0, -1);

    /** A zig-zag of targets over a w x h rectangle at height z of the table, the tool pointing down. */
    static List<ToolTarget> top(String label, double x0, double y0, double z, double w, double h) {
        List<ToolTarget> out = new ArrayList<>();
        for (int r = 0; r <= 5; r++) {
            for (int k = 0; k <= 8; k++) {
                double x = x0 + (r % 2 == 0 ? k : 8 - k) * w / 8;
                out.add(ToolTarget.of(label, new Vec3(x, y0 + r * h / 5, z), DOWN));
            }
        }
        return out;
    }

    /** Targets on a face normal to -y at y = y0, the tool pointing along +y into it. */
    static List<ToolTarget> side(String label, double x0, double y0, double z0) {
        List<ToolTarget> out = new ArrayList<>();
        for (int k = 0; k <= 10; k++) {
            out.add(ToolTarget.of(label, new Vec3(x0 + 10 * k, y0, z0 - 2 * k), new Vec3(0, 1, 0)));
        }
        return out;
    }

    static PlacementSearch search(Robot r) {
        return new PlacementSearch(r, label -> r, new PlacementSearch.Bounds(100_000));
    }

    /** Every target solved (by solveAll, with the turns about the tool axis) from the placement. */
    static int reached(Robot r, List<ToolTarget> ts, PlacementSearch.TablePlacement p) {
        IkSolver s = r.newSolver(IkOptions.DEFAULT);
        Transform3 t = p.toTransform();
        int n = 0;
        for (ToolTarget x : ts) {
            ToolTarget placed = new ToolTarget(
                    x.label(),
                    t.applyToPoint(x.positionMm()),
                    t.applyToDirection(x.toolAxis()),
                    t.applyToDirection(x.preferredX()));
            boolean any = false;
            for (double turn : new double[] {0, 180, 90, -90}) {
                for (IkResult.Converged c : s.solveAll(placed.pose(turn))) {
                    Transform3 f = r.forward(c.q());
                    any |= f.translationPart().distance(placed.positionMm()) <= 1e-6;
                }
            }
            n += any ? 1 : 0;
        }
        return n;
    }

    @Test
    void aPartOutOfReachIsMovedWhereTheIrb140ReachesAllOfIt() {
        Robot irb = Robots.irb140();
        List<ToolTarget> part = new ArrayList<>(top("top", 2000, 0, 0, 200, 100));
        part.addAll(side("side", 2020, 0, -10));
        // at the origin the part is 2 m away: nothing is reached
        assertEquals(0, reached(irb, part, new PlacementSearch.TablePlacement(0, 0, 0, 0)));
        PlacementSearch.Result r = search(irb).search(part, (f, w) -> {});
        assertTrue(r.found().isPresent(), r::toString);
        assertEquals(part.size(), r.reached());
        assertEquals(part.size(), reached(irb, part, r.found().get()));
        assertTrue(r.minMargin() > 0.05, r::toString);
        assertTrue(r.outOfReachEverywhere().isEmpty());
        // the rotation stays within half a turn either way
        assertTrue(Math.abs(r.found().get().rzDeg()) <= 180);
    }

    @Test
    void theTriceptReachesAPartBelowIt() {
        Robot tri = Robots.tricept806();
        List<ToolTarget> part = top("top", 0, 0, 0, 300, 200);
        assertEquals(0, reached(tri, part, new PlacementSearch.TablePlacement(0, 0, 0, 0)));
        PlacementSearch.Result r = search(tri).search(part, (f, w) -> {});
        assertTrue(r.found().isPresent(), r::toString);
        assertEquals(part.size(), reached(tri, part, r.found().get()));
        assertTrue(r.found().get().zMm() < -1000, r::toString);
    }

    @Test
    void aScaraCannotReachASideFaceFromAnyPlacementAndSaysWhich() {
        Robot adept = Robots.adeptOne();
        List<ToolTarget> part = new ArrayList<>(top("top", 0, 0, 0, 200, 100));
        part.addAll(side("side", 20, 0, -10));
        PlacementSearch.Result r = search(adept).search(part, (f, w) -> {});
        assertTrue(r.found().isEmpty(), "never a partial placement");
        assertEquals(List.of("side"), r.outOfReachEverywhere());
        assertEquals(List.of(), r.notTogether());
        assertEquals(part.size() - 11, r.reached());
        assertTrue(r.notes().get(0).contains("always"), r.notes()::toString);
        // the best placement reaches the top face
        assertEquals(part.size() - 11, reached(adept, part.subList(0, part.size() - 11), r.best()));
    }

    @Test
    void twoFacesTooFarApartAreEachReachableButNotTogether() {
        Robot irb = Robots.irb140();
        List<ToolTarget> part = new ArrayList<>(top("near", 0, 0, 0, 100, 100));
        part.addAll(top("far", 3000, 0, 0, 100, 100));
        PlacementSearch.Result r = search(irb).search(part, (f, w) -> {});
        assertTrue(r.found().isEmpty());
        assertEquals(List.of(), r.outOfReachEverywhere());
        assertEquals(1, r.notTogether().size(), r::toString);
        assertEquals(part.size() / 2, r.reached());
    }

    @Test
    void cancellingStopsTheSearch() {
        Robot irb = Robots.irb140();
        List<ToolTarget> part = top("top", 0, 0, 0, 200, 100);
        org.junit.jupiter.api.Assertions.assertThrows(
                java.util.concurrent.CancellationException.class,
                () -> search(irb).search(part, (f, w) -> {
                    if (f > 0.1) {
                        throw new java.util.concurrent.CancellationException("cancelled");
                    }
                }));
    }
}
