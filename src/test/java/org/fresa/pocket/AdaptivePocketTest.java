package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.fresa.geom.Contour;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.model.ToolpathSection;
import org.fresa.post.Rs274;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.locationtech.jts.geom.Geometry;

/**
 * The adaptive planner ({@link AdaptivePocket}): from LinuxCNC's interpreter's moves, measured
 * with JTS as the other strategies are, it leaves less than 0.05 mm2 of the floor the tool can
 * reach and cuts no wall by 0.01 mm; measured by {@link Engagement}, every move at the programmed
 * feed stays within the angle of a cut of 1.1 times the stepover plus {@link #MARGIN_DEG} (on
 * thesis contours whose sharp corners, walls and links the first planner exceeded it at: cavity 05
 * by 22 degrees, cavity 06 by 28, examplepart by 7, where the offset passes slot their first loop
 * at 180), and every move the geometry makes wider is fed so much slower that it removes no more
 * per minute ({@link EngagementFeed}).
 */
class AdaptivePocketTest {

    /**
     * What the measure may read above the bound (deg): its own error (EngagementTest holds a slot
     * and a straight cut within 1.5 degrees) and one of its 180 rays either side.
     */
    static final double MARGIN_DEG = 3;

    /** How many random pockets the random test plans (the system property fresa.adaptive.pockets, 20 unless set). */
    static final int RANDOM_POCKETS = Integer.getInteger("fresa.adaptive.pockets", 20);

    @ParameterizedTest
    @ValueSource(
            strings = {"examplepart", "cavity01", "cavity02", "cavity03", "cavity04", "cavity05", "cavity06", "cavity07"
            })
    @InterpreterCheck
    void theThesisContoursLeaveNoFloorCutNoWallAndHoldTheLoad(String name, @TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        check(name, List.of(RecognitionTest.sample(name + ".dad").outline()), PocketCoverageTest.tech(name), dir);
    }

    @Test
    @InterpreterCheck
    void randomPocketsWithIslandsLeaveNoSliverNeverCutAWallAndHoldTheLoad(@TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        // the random pockets of the zigzag and offset tests, in the same order
        Random rnd = new Random(21);
        int done = 0;
        int[] byIslands = new int[4];
        int slowed = 0;
        for (int attempt = 0; done < RANDOM_POCKETS && attempt < 3 * RANDOM_POCKETS; attempt++) {
            List<Contour> p = PocketCleanUpTest.pocket(rnd);
            PocketTechnology t = PocketCleanUpTest.tech(rnd);
            try {
                RegionPocket.plan(p.get(0), p.subList(1, p.size()), t, true, EntryRule.DEFAULT, true);
            } catch (ToolTooLargeException | IllegalArgumentException e) {
                continue;
            }
            // every pocket the offset passes plan, adaptive plans too
            AdaptivePocket.Plan plan =
                    AdaptivePocket.plan(p.get(0), p.subList(1, p.size()), t, true, EntryRule.DEFAULT);
            check(String.format(Locale.ROOT, "r%03d-i%d", done, p.size() - 1), p, t, plan, dir);
            slowed += plan.slowed().any() ? 1 : 0;
            byIslands[p.size() - 1]++;
            done++;
        }
        System.out.printf(
                Locale.ROOT,
                "adaptive random pockets %d (islands 0..3: %d %d %d %d), %d with slowed cuts%n",
                done,
                byIslands[0],
                byIslands[1],
                byIslands[2],
                byIslands[3],
                slowed);
        assertEquals(RANDOM_POCKETS, done);
    }

    @Test
    void anAcuteCornerIsRoundedForTheWalksAndLeftToTheFinishingPass() throws Exception {
        // a triangle with a 30 degree corner: a centre reaching the pre-finish offset's corner
        // would engage 150 degrees however little it cut
        Contour outer = Contour.polygon(
                List.of(new Vec2(0, 0), new Vec2(60, 0), new Vec2(60, 60 * Math.tan(Math.toRadians(30)))));
        PocketTechnology t = new PocketTechnology(6, 0.45, 0.1, 0, -3, 3, 3000, 300, 100);
        AdaptivePocket.Plan plan = AdaptivePocket.plan(outer, List.of(), t, true, EntryRule.DEFAULT);
        Load load = holds("triangle", List.of(outer), t, plan);
        // the finishing pass meets the corner's rounded-off floor: the only move slowed
        assertTrue(load.fullFeedMaxDeg() <= bound(t) + MARGIN_DEG, load.toString());
    }

    @Test
    @InterpreterCheck
    void aChannelTheToolsCentreHasNoRoomInIsCutAtASlowerFeed(@TempDir Path dir) throws Exception {
        // a 60 mm slot 9 mm wide for a 6 mm tool leaving 0.6 mm: the centre has 0.9 mm either side
        // of the middle, where only a full-width cut reaches the floor; the slot is cut, slowed to
        // 1.1 times the stepover over the tool's diameter
        assumeTrue(Rs274.available(), Rs274.whyNot());
        Contour outer = Contour.polygon(List.of(new Vec2(0, 0), new Vec2(60, 0), new Vec2(60, 9), new Vec2(0, 9)));
        PocketTechnology t = new PocketTechnology(6, 0.4, 0.1, 0, -3, 3, 3000, 300, 100);
        AdaptivePocket.Plan plan = AdaptivePocket.plan(outer, List.of(), t, true, EntryRule.DEFAULT);
        assertTrue(plan.slowed().any(), plan.slowed().toString());
        assertTrue(plan.slowed().worstDeg() > 170, plan.slowed().toString());
        assertEquals(
                1.1 * 0.4, plan.slowed().lowestFactor(), 0.02, plan.slowed().toString());
        // the pre-finish pass slots the channel at 1.1 x 0.4 of the feed: 132 mm/min for 300
        assertTrue(
                plan.toolpath().sections().get(0).moves().stream()
                        .anyMatch(m -> feed(m) == Math.floor(300 * 1.1 * 0.4)),
                "no move at 132 mm/min");
        holds("channel", List.of(outer), t, plan);
        // a slot throughout: its mean engagement is a slot's, not the stepover's
        verdict("channel", List.of(outer), t, plan, dir);
    }

    @Test
    void openingRoundsTheOffsetsCornersAndKeepsItsEdges() {
        // a 40 x 30 rectangle offset by 5 is 30 x 20; rounded to 2 its four corners lose (4 - pi) 2^2
        Contour outer = Contour.polygon(List.of(new Vec2(0, 0), new Vec2(40, 0), new Vec2(40, 30), new Vec2(0, 30)));
        List<Contour> b = RegionOffsetter.oriented(outer, List.of());
        List<Contour> o = AdaptivePocket.opened(b, 5, 2);
        assertEquals(1, o.size());
        assertTrue(o.get(0).isCcw());
        assertEquals(30 * 20 - (4 - Math.PI) * 4, o.get(0).area(), 1e-3);
        assertEquals(5, o.get(0).distanceTo(new Vec2(20, 0)), 1e-9);
        // a hole about an island stays a hole, grown back to the plain offset
        Contour island =
                Contour.polygon(List.of(new Vec2(15, 10), new Vec2(25, 10), new Vec2(25, 20), new Vec2(15, 20)));
        List<Contour> withHole = AdaptivePocket.opened(RegionOffsetter.oriented(outer, List.of(island)), 3, 1);
        List<Contour> plain =
                RegionOffsetter.inward(RegionOffsetter.oriented(outer, List.of(island)), 3, Tolerance.DEFAULT);
        assertEquals(plain.size(), withHole.size());
        double area = withHole.stream().mapToDouble(Contour::signedArea).sum();
        double plainArea = plain.stream().mapToDouble(Contour::signedArea).sum();
        // only the outer loop's four sharp corners change; the hole's corners are rounded already
        assertEquals(plainArea - (4 - Math.PI), area, 1e-3);
    }

    static Engagement engagement(List<Contour> p, PocketTechnology t, AdaptivePocket.Plan plan) {
        List<Contour> boundary = RegionOffsetter.oriented(p.get(0), p.subList(1, p.size()));
        ToolpathSection a = plan.toolpath().sections().get(0);
        return Engagement.of(boundary, t.radiusMm(), a.start(), a.moves(), t.finishFeedMmPerMin());
    }

    /**
     * The load of a program, from its moves: the largest engagement of the moves at the
     * programmed feed (roughing or finishing), where it is, and the largest ratio of what a move
     * removes per minute (its feed times the width of a straight cut of its engagement, less the
     * measure's margin) to what a cut of 1.1 times the stepover removes at the programmed feed.
     */
    record Load(double fullFeedMaxDeg, Vec2 at, double removalRatio) {}

    static Load load(List<Contour> p, PocketTechnology t, AdaptivePocket.Plan plan) {
        List<Contour> boundary = RegionOffsetter.oriented(p.get(0), p.subList(1, p.size()));
        ToolpathSection a = plan.toolpath().sections().get(0);
        double boundWidth = 1.1 * Math.min(1, t.cutFraction()) * t.toolDiameterMm();
        double[] max = {0, 0};
        Vec2[] at = {null};
        Engagement.of(boundary, t.radiusMm(), a.start(), a.moves(), t.finishFeedMmPerMin(), (mi, q, deg) -> {
            double f = feed(a.moves().get(mi));
            boolean programmed = f == t.feedMmPerMin() || f == t.finishFeedMmPerMin();
            double base = f < t.finishFeedMmPerMin() ? t.finishFeedMmPerMin() : t.feedMmPerMin();
            if (programmed && deg > max[0]) {
                max[0] = deg;
                at[0] = q;
            }
            max[1] = Math.max(
                    max[1], f * Engagement.widthMm(Math.max(0, deg - MARGIN_DEG), t.radiusMm()) / (base * boundWidth));
        });
        return new Load(max[0], at[0], max[1]);
    }

    /** Asserts the load: the programmed feed within the bound, the slowed moves removing no more. */
    static Load holds(String name, List<Contour> p, PocketTechnology t, AdaptivePocket.Plan plan) {
        Load load = load(p, t, plan);
        assertTrue(
                load.fullFeedMaxDeg() <= bound(t) + MARGIN_DEG,
                name + ": " + load.fullFeedMaxDeg() + " deg at " + load.at() + ", bound " + bound(t));
        assertTrue(load.removalRatio() <= 1, name + ": " + load);
        return load;
    }

    static double feed(org.fresa.model.Move m) {
        return m instanceof org.fresa.model.Move.Linear l
                ? l.feedMmPerMin()
                : m instanceof org.fresa.model.Move.Circular c ? c.feedMmPerMin() : 0;
    }

    static double bound(PocketTechnology t) {
        return Engagement.angleDeg(1.1 * t.cutFraction() * t.toolDiameterMm(), t.radiusMm());
    }

    private static void check(String name, List<Contour> p, PocketTechnology t, Path dir) throws Exception {
        check(name, p, t, AdaptivePocket.plan(p.get(0), p.subList(1, p.size()), t, true, EntryRule.DEFAULT), dir);
    }

    /** The verdict and the load, and the mean engagement under the stepover's angle. */
    static void check(String name, List<Contour> p, PocketTechnology t, AdaptivePocket.Plan plan, Path dir)
            throws Exception {
        Engagement adaptive = verdict(name, p, t, plan, dir);
        double stepover = t.cutFraction() * t.toolDiameterMm();
        assertTrue(
                adaptive.meanDeg() < Engagement.angleDeg(stepover, t.radiusMm()),
                name + ": adaptive mean " + adaptive.meanDeg());
    }

    /** No floor left, no wall cut, the load held; the engagement measured. */
    static Engagement verdict(String name, List<Contour> p, PocketTechnology t, AdaptivePocket.Plan plan, Path dir)
            throws Exception {
        Geometry wall = RegionPocketTest.region(p);
        Geometry reachable = wall.buffer(-t.radiusMm(), 32).buffer(t.radiusMm(), 32);
        PocketCleanUpTest.Verdict v = PocketCleanUpTest.verdict(
                PocketCleanUpTest.interpreted(plan.toolpath(), dir, name),
                t.zBottomMm(),
                t.zTopMm(),
                t.radiusMm(),
                wall,
                reachable);
        Engagement adaptive = engagement(p, t, plan);
        Load load = load(p, t, plan);
        System.out.printf(
                Locale.ROOT,
                "%s D%.0f cut %.2f: %d walks, uncut %.4f mm2, gouge %.4f mm; engagement (bound %.1f deg) at the"
                        + " programmed feed max %.1f, mean %.1f; %d moves slowed (%.1f mm, down to %.2f of the feed),"
                        + " removal ratio %.3f%n",
                name,
                t.toolDiameterMm(),
                t.cutFraction(),
                plan.walks(),
                v.uncutMm2(),
                v.gougeMm(),
                bound(t),
                load.fullFeedMaxDeg(),
                adaptive.meanDeg(),
                plan.slowed().moves(),
                plan.slowed().lengthMm(),
                plan.slowed().lowestFactor(),
                load.removalRatio());
        assertTrue(v.uncutMm2() < PocketCleanUpTest.UNCUT_MM2, name + " leaves " + v.uncutMm2() + " mm2");
        assertTrue(v.gougeMm() < PocketCleanUpTest.GOUGE_MM, name + " cuts the wall by " + v.gougeMm() + " mm");
        holds(name, p, t, plan);
        return adaptive;
    }
}
