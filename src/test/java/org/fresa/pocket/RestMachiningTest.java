package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.fresa.check.Limits;
import org.fresa.check.NcDialect;
import org.fresa.check.ProgramCheck;
import org.fresa.check.ToolLimits;
import org.fresa.geom.Contour;
import org.fresa.geom.Vec2;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.fresa.post.NcPosts;
import org.fresa.post.Rs274;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.operation.buffer.BufferOp;
import org.locationtech.jts.operation.buffer.BufferParameters;

/**
 * Rest machining ({@link RestMachining}): a 10 mm tool then a 4 mm one (and 6 then 2), on the
 * thesis's eight contours and on 30 seeded random pockets with 0 to 3 islands, checked from
 * LinuxCNC's interpreter's moves with JTS: the floor the small tool can reach is cut but for less
 * than 0.05 mm2, neither tool comes within the wall by 0.01 mm, the small tool feeds through air
 * (feed, ramps, lead-ins and links included, whose disc meets no material the first tool left)
 * less than a third of the length of its own whole plan where there is 1 mm2 of rest (the
 * totals are printed: 3314 mm against 29773 mm of whole plans over the random pockets, worst
 * 26 %; going down on a ramp over the rest itself it was 8023 mm, worst 62 %), the program passes the program check in the linuxcnc, iso, fanuc and 840d
 * posts, and the small tool feeds at the floor its pieces and less than a quarter of its own whole
 * plan beside them (a second pass over the whole pocket would feed all of it). Air, not the share of the feed that meets rest: a
 * ramp on legs over a corner's rest meets it at every leg, and reads better than going down
 * beside it in floor already cleared.
 */
class RestMachiningTest {

    private static final int POCKETS = 30;
    private static final double[][] TOOLS = {{10, 4}, {6, 2}};
    private static final List<String> POSTS = List.of("linuxcnc", "iso", "fanuc", "840d", "apt");

    /** What the measures found for one pocket. */
    record Measure(double uncutMm2, double gougeMm, double meetsFraction, double feedLengthMm, double floorLengthMm) {}

    @ParameterizedTest
    @ValueSource(
            strings = {"examplepart", "cavity01", "cavity02", "cavity03", "cavity04", "cavity05", "cavity06", "cavity07"
            })
    @InterpreterCheck
    void theThesisContoursAreCleanedByTheRestToolOnlyWhereTheFirstLeftMaterial(String name, @TempDir Path dir)
            throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        PocketTechnology base = PocketCoverageTest.tech(name);
        PocketProfile profile = RecognitionTest.sample(name + ".dad");
        List<Contour> p = List.of(profile.outline());
        int planned = 0;
        for (double[] tools : TOOLS) {
            PocketTechnology t = withDiameter(base, tools[0]);
            RestMachining.Plan rest;
            StrategyPocket.Planned plan;
            try {
                plan = StrategyPocket.plan(p.get(0), List.of(), t, strategy(tools[1]), true, EntryRule.DEFAULT);
                rest = plan.rest().orElseThrow();
            } catch (ToolTooLargeException e) {
                System.out.printf(Locale.ROOT, "%s %.0f/%.0f: refused: %s%n", name, tools[0], tools[1], e.getMessage());
                continue;
            }
            planned++;
            Measure m = measure(p, plan.toolpath(), t, rest, dir, name + "_" + (int) tools[0]);
            report(name, tools, rest, m);
            check(name, plan.toolpath(), t, tools[1], rest, m);
        }
        assertTrue(planned > 0, name + ": neither pair of tools planned");
    }

    @Test
    @InterpreterCheck
    void randomPocketsWithIslandsAreCleanedByTheRestToolOnlyWhereTheFirstLeftMaterial(@TempDir Path dir)
            throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        Random rnd = new Random(2121);
        int done = 0;
        double worstUncut = 0;
        double worstGouge = 0;
        double airLength = 0;
        double planLength = 0;
        List<String> bad = new ArrayList<>();
        for (int attempt = 0; done < POCKETS && attempt < 3 * POCKETS; attempt++) {
            List<Contour> p = PocketCleanUpTest.pocket(rnd);
            double[] tools = TOOLS[done % 2];
            PocketTechnology t = withDiameter(PocketCleanUpTest.tech(rnd), tools[0]);
            StrategyPocket.Planned plan;
            try {
                plan = StrategyPocket.plan(
                        p.get(0), p.subList(1, p.size()), t, strategy(tools[1]), true, EntryRule.DEFAULT);
            } catch (ToolTooLargeException e) {
                continue;
            }
            RestMachining.Plan rest = plan.rest().orElseThrow();
            String name = "r" + done + " (" + (p.size() - 1) + " islands)";
            Measure m = measure(p, plan.toolpath(), t, rest, dir, "r" + done);
            report(name, tools, rest, m);
            worstUncut = Math.max(worstUncut, m.uncutMm2());
            worstGouge = Math.max(worstGouge, m.gougeMm());
            airLength += (1 - m.meetsFraction()) * m.feedLengthMm();
            planLength += rest.fullPlanLengthMm();
            try {
                check(name, plan.toolpath(), t, tools[1], rest, m);
            } catch (AssertionError e) {
                bad.add(e.getMessage());
            }
            done++;
        }
        System.out.printf(
                Locale.ROOT,
                "rest machining: %d pockets, worst uncut %.4f mm2, worst gouge %.4f mm, the rest tool feeds %.1f mm"
                        + " through air against %.1f mm of its whole plans%n",
                done,
                worstUncut,
                worstGouge,
                airLength,
                planLength);
        assertEquals(POCKETS, done);
        assertTrue(bad.isEmpty(), bad.size() + " pockets fail: " + bad);
    }

    @Test
    void aPocketTheFirstToolReachesEverywhereHasNoSecondTool() throws Exception {
        // a round pocket: a 10 mm tool reaches all of it, a 4 mm one nothing more
        Contour outer = new Contour(List.of(org.fresa.geom.Arc2.circle(new Vec2(0, 0), 30, true)));
        PocketTechnology t = new PocketTechnology(10, 0.6, 0.1, 0, -6, 3, 3000, 300, 100);
        StrategyPocket.Planned plan = StrategyPocket.plan(outer, List.of(), t, strategy(4), true, EntryRule.DEFAULT);
        assertFalse(plan.rest().orElseThrow().cuts());
        assertEquals(1, plan.toolpath().sections().size());
    }

    @Test
    void aSquareCornersRestIsCutByTheSecondToolAloneAndNotTheWholePocket() throws Exception {
        Contour outer = Contour.polygon(List.of(new Vec2(0, 0), new Vec2(80, 0), new Vec2(80, 50), new Vec2(0, 50)));
        PocketTechnology t = new PocketTechnology(10, 0.6, 0.1, 0, -6, 3, 3000, 300, 100);
        StrategyPocket.Planned plan = StrategyPocket.plan(outer, List.of(), t, strategy(4), true, EntryRule.DEFAULT);
        RestMachining.Plan rest = plan.rest().orElseThrow();
        assertTrue(rest.cuts());
        assertEquals(2, plan.toolpath().sections().size());
        ToolpathSection second = plan.toolpath().sections().get(1);
        assertEquals(2, second.toolNumber());
        assertEquals(4, second.toolDiameterMm());
        assertEquals(7500, second.spindleRpm(), "the same cutting speed: 3000 rpm times 10 / 4");
        // the rest of a 5 mm radius corner less a 2 mm one: 4 (25 - 4)(1 - pi / 4); every piece in a corner
        List<Vec2> corners = List.of(new Vec2(0, 0), new Vec2(80, 0), new Vec2(80, 50), new Vec2(0, 50));
        for (var piece : rest.pieces()) {
            for (var c : piece) {
                assertTrue(
                        corners.stream().anyMatch(k -> k.distance(c.start()) < 10 && k.distance(c.end()) < 10),
                        "a piece away from the corners: " + c);
            }
        }
        assertEquals(4 * 21 * (1 - Math.PI / 4), rest.restAreaMm2(), 1.5);
        assertTrue(
                rest.piecesLengthMm() < 0.2 * rest.fullPlanLengthMm(),
                "the rest tool cuts " + rest.piecesLengthMm() + " mm of its " + rest.fullPlanLengthMm() + " mm plan");
        // at every layer each piece, nothing else, at the floor
        double floor = 0;
        Move prev = null;
        for (Move m : second.moves()) {
            if (prev != null
                    && !(m instanceof Move.Rapid)
                    && m.end().z() == -6
                    && prev.end().z() == -6) {
                floor += prev.end().distance(m.end());
            }
            prev = m;
        }
        assertTrue(floor < 0.25 * rest.fullPlanLengthMm(), "at the floor " + floor + " mm");
    }

    @Test
    void aRestToolNotSmallerThanTheFirstIsRefused() {
        Contour outer = Contour.polygon(List.of(new Vec2(0, 0), new Vec2(80, 0), new Vec2(80, 50), new Vec2(0, 50)));
        PocketTechnology t = new PocketTechnology(10, 0.6, 0.1, 0, -6, 3, 3000, 300, 100);
        assertThrows(
                IllegalArgumentException.class,
                () -> StrategyPocket.plan(outer, List.of(), t, strategy(9.995), true, EntryRule.DEFAULT));
        assertTrue(PocketStrategy.restToolFits(9.98, 10));
        assertFalse(PocketStrategy.restToolFits(9.99, 10));
        assertFalse(PocketStrategy.restToolFits(0, 10));
        assertFalse(PocketStrategy.restToolFits(0.005, 10));
        assertTrue(PocketStrategy.restToolFits(0.01, 10));
    }

    private static PocketStrategy strategy(double restMm) {
        return new PocketStrategy(PocketStrategy.Kind.OFFSET, 0, 0, PocketStrategy.Order.INSIDE_OUT, restMm);
    }

    static PocketTechnology withDiameter(PocketTechnology t, double d) {
        return new PocketTechnology(
                d,
                t.cutFraction(),
                t.finishFraction(),
                t.zTopMm(),
                t.zBottomMm(),
                t.maxDepthMm(),
                t.spindleRpm(),
                t.feedMmPerMin(),
                t.finishFeedMmPerMin());
    }

    private static void report(String name, double[] tools, RestMachining.Plan rest, Measure m) {
        System.out.printf(
                Locale.ROOT,
                "%s %.0f/%.0f: rest %.2f mm2 in %d pieces (%.1f of %.1f mm), uncut %.4f mm2, gouge %.4f mm,"
                        + " its feed %.1f mm (%.1f at the floor) meets rest over %.1f %%%n",
                name,
                tools[0],
                tools[1],
                rest.restAreaMm2(),
                rest.pieces().size(),
                rest.piecesLengthMm(),
                rest.fullPlanLengthMm(),
                m.uncutMm2(),
                m.gougeMm(),
                m.feedLengthMm(),
                m.floorLengthMm(),
                100 * m.meetsFraction());
    }

    private static void check(
            String name, Toolpath path, PocketTechnology t, double restMm, RestMachining.Plan rest, Measure m)
            throws Exception {
        assertTrue(m.uncutMm2() < PocketCleanUpTest.UNCUT_MM2, name + " leaves " + m.uncutMm2() + " mm2");
        assertTrue(m.gougeMm() < PocketCleanUpTest.GOUGE_MM, name + " cuts the wall by " + m.gougeMm() + " mm");
        if (rest.cuts()) {
            // the rest tool does not go round the pocket again: at the floor, its pieces and no more
            // than a quarter of its own plan beside them (lead-ins and links through cleared floor)
            assertTrue(
                    m.floorLengthMm() < rest.piecesLengthMm() + 0.25 * rest.fullPlanLengthMm(),
                    name + ": the rest tool feeds " + m.floorLengthMm() + " mm at the floor for "
                            + rest.piecesLengthMm() + " mm of pieces, of its " + rest.fullPlanLengthMm()
                            + " mm plan");
            // of at least 1 mm2 of rest: a sliver thinner than the measure's 0.04 mm meets no disc in JTS
            double airMm = (1 - m.meetsFraction()) * m.feedLengthMm();
            assertTrue(
                    rest.restAreaMm2() < 1 || airMm < rest.fullPlanLengthMm() / 3,
                    name + ": the rest tool feeds " + airMm + " mm through air, of its " + rest.fullPlanLengthMm()
                            + " mm plan");
        }
        for (String post : POSTS) {
            StringWriter w = new StringWriter();
            NcPosts.byName(post).orElseThrow().write(path, name, w);
            var failure = ProgramCheck.of(w.toString(), dialect(post), limits(t, restMm))
                    .failure();
            assertTrue(
                    failure.isEmpty(),
                    name + " in " + post + ": " + failure.map(f -> f.message()).orElse(""));
        }
    }

    static NcDialect dialect(String post) {
        return NcDialect.byPost(post).orElseThrow();
    }

    /** The pocket's limits as the service gives them: a cutter not cutting at its centre, 3 degrees. */
    static Limits limits(PocketTechnology t, double restMm) {
        return Limits.milling()
                .withHeights(t.zTopMm(), t.zBottomMm(), 0)
                .withOtherTools(ToolLimits.notCentreCutting().withRadiusMm(t.radiusMm()))
                .withTool(2, ToolLimits.notCentreCutting().withRadiusMm(restMm / 2));
    }

    /**
     * Both tools through the interpreter: the whole program (with its tool change) must be
     * accepted, then each tool's section on its own gives its moves.
     */
    static Measure measure(
            List<Contour> p, Toolpath path, PocketTechnology t, RestMachining.Plan rest, Path dir, String name)
            throws Exception {
        StringWriter w = new StringWriter();
        NcPosts.byName("linuxcnc").orElseThrow().write(path, name, w);
        Path f = dir.resolve(name + "_both.ngc");
        Files.writeString(f, w.toString());
        Rs274.Result whole = Rs274.run(f, t.toolDiameterMm());
        assertEquals(0, whole.exitStatus(), name + ": " + Rs274.log(whole));
        double r1 = t.radiusMm();
        double r2 = rest.technology().radiusMm();
        Geometry wall = RegionPocketTest.region(p);
        Geometry reachable = wall.buffer(-r2, 32).buffer(r2, 32);
        List<Rs274.Canon> first = PocketCleanUpTest.interpreted(
                new Toolpath(List.of(path.sections().get(0))), dir, name + "_1");
        PocketCleanUpTest.Verdict v1 = PocketCleanUpTest.verdict(first, t.zBottomMm(), t.zTopMm(), r1, wall, reachable);
        Geometry swept1 = swept(first, t.zBottomMm(), r1);
        Geometry restMaterial =
                reachable.buffer(-PocketCleanUpTest.GOUGE_MM, 32).difference(swept1);
        if (path.sections().size() == 1) {
            return new Measure(restMaterial.getArea(), v1.gougeMm(), 0, 0, 0);
        }
        List<Rs274.Canon> second = PocketCleanUpTest.interpreted(
                new Toolpath(List.of(path.sections().get(1))), dir, name + "_2");
        PocketCleanUpTest.Verdict v2 =
                PocketCleanUpTest.verdict(second, t.zBottomMm(), t.zTopMm(), r2, wall, reachable);
        Geometry swept2 = swept(second, t.zBottomMm(), r2);
        double uncut = restMaterial.difference(swept2).getArea();
        // how much of the rest tool's feed at the floor has its disc meet material the first tool left
        org.locationtech.jts.geom.prep.PreparedGeometry restPrep =
                org.locationtech.jts.geom.prep.PreparedGeometryFactory.prepare(restMaterial.buffer(-0.02));
        double total = 0;
        double meets = 0;
        for (Coordinate[] seg : feedSegments(second, Double.NaN)) {
            double len = seg[0].distance(seg[1]);
            total += len;
            Geometry disc = PocketCoverageTest.GF.createLineString(seg).buffer(r2 - 0.02, 8);
            if (restPrep.intersects(disc)) {
                meets += len;
            }
        }
        double floor = floorMoves(second, t.zBottomMm()).stream()
                .mapToDouble(pts -> PocketCoverageTest.GF
                        .createLineString(pts.toArray(new Coordinate[0]))
                        .getLength())
                .sum();
        return new Measure(uncut, Math.max(v1.gougeMm(), v2.gougeMm()), total > 0 ? meets / total : 0, total, floor);
    }

    /** The feed moves at the floor (every feed move for a floor of NaN), each as its points in XY. */
    private static List<List<Coordinate>> floorMoves(List<Rs274.Canon> motions, double floorZ) {
        List<List<Coordinate>> out = new ArrayList<>();
        org.fresa.geom.Vec3 cur = null;
        for (Rs274.Canon m : motions) {
            org.fresa.geom.Vec3 e = m.end();
            if (cur != null
                    && !m.kind().equals("rapid")
                    && !m.kind().equals("dwell")
                    && (Double.isNaN(floorZ)
                            || (Math.abs(cur.z() - floorZ) < 1e-4 && Math.abs(e.z() - floorZ) < 1e-4))) {
                List<Coordinate> pts = new ArrayList<>();
                Vec2 a = new Vec2(cur.x(), cur.y());
                Vec2 b = new Vec2(e.x(), e.y());
                if (m.kind().equals("arc") && a.distance(b) > 1e-9) {
                    pts.addAll(PocketCoverageTest.arcPoints(
                            a, b, new Vec2(m.center().x(), m.center().y()), m.rotation() > 0));
                } else {
                    pts.add(new Coordinate(a.x(), a.y()));
                    pts.add(new Coordinate(b.x(), b.y()));
                }
                out.add(pts);
            }
            cur = e;
        }
        return out;
    }

    /** The feed moves ({@link #floorMoves}) in stretches of at most 0.5 mm. */
    private static List<Coordinate[]> feedSegments(List<Rs274.Canon> motions, double floorZ) {
        List<Coordinate[]> out = new ArrayList<>();
        for (List<Coordinate> pts : floorMoves(motions, floorZ)) {
            for (int i = 0; i + 1 < pts.size(); i++) {
                Coordinate p = pts.get(i);
                Coordinate q = pts.get(i + 1);
                int n = Math.max(1, (int) Math.ceil(p.distance(q) / 0.5));
                for (int k = 0; k < n; k++) {
                    out.add(new Coordinate[] {
                        new Coordinate(p.x + (q.x - p.x) * k / n, p.y + (q.y - p.y) * k / n),
                        new Coordinate(p.x + (q.x - p.x) * (k + 1) / n, p.y + (q.y - p.y) * (k + 1) / n)
                    });
                }
            }
        }
        return out;
    }

    /** What the tool's disc sweeps along its feed moves at the floor. */
    private static Geometry swept(List<Rs274.Canon> motions, double floorZ, double r) {
        List<Geometry> lines = new ArrayList<>();
        for (List<Coordinate> pts : floorMoves(motions, floorZ)) {
            lines.add(
                    pts.get(0).distance(pts.get(pts.size() - 1)) < 1e-9 && pts.size() == 2
                            ? PocketCoverageTest.GF.createPoint(pts.get(0))
                            : PocketCoverageTest.GF.createLineString(pts.toArray(new Coordinate[0])));
        }
        BufferParameters bp = new BufferParameters((int) Math.ceil(Math.PI / 2 / Math.acos(1 - 0.004 / r)));
        return BufferOp.bufferOp(PocketCoverageTest.GF.buildGeometry(lines), r, bp);
    }
}
