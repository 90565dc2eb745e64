package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.StringReader;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.model.ContourFile;
import org.fresa.post.NcPosts;
import org.fresa.post.Rs274;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;

/** Beyond the thesis: islands and many-way splits, milled completely. */
class RegionPocketTest {

    static final Tolerance TOL = Tolerance.DEFAULT;

    static List<Contour> read(String file) throws Exception {
        return ContourFile.read(new StringReader(Files.readString(Path.of(file))), file);
    }

    /** A contour as a JTS ring, arcs as chords within 0.5 um. */
    static Geometry polygon(Contour c) {
        List<Coordinate> pts = new ArrayList<>();
        for (Curve2 k : c.curves()) {
            if (k instanceof Arc2 a && a.isFullCircle()) {
                Vec2 opposite = a.center().times(2).minus(a.start());
                pts.addAll(PocketCoverageTest.arcPoints(a.start(), opposite, a.center(), a.ccw()));
                pts.addAll(PocketCoverageTest.arcPoints(opposite, a.start(), a.center(), a.ccw()));
            } else if (k instanceof Arc2 a) {
                pts.addAll(PocketCoverageTest.arcPoints(a.start(), a.end(), a.center(), a.ccw()));
            } else {
                pts.add(new Coordinate(k.start().x(), k.start().y()));
                pts.add(new Coordinate(k.end().x(), k.end().y()));
            }
        }
        pts.add(pts.get(0));
        return PocketCoverageTest.GF
                .createPolygon(pts.toArray(new Coordinate[0]))
                .buffer(0);
    }

    static Geometry region(List<Contour> contours) {
        Geometry g = polygon(contours.get(0));
        for (int i = 1; i < contours.size(); i++) {
            g = g.difference(polygon(contours.get(i)));
        }
        return g;
    }

    @Test
    void squareWithSquareIslandOffsetsToASquareAndARoundedRing() {
        Contour outer =
                Contour.polygon(List.of(new Vec2(0, 0), new Vec2(100, 0), new Vec2(100, 100), new Vec2(0, 100)));
        Contour island =
                Contour.polygon(List.of(new Vec2(40, 40), new Vec2(60, 40), new Vec2(60, 60), new Vec2(40, 60)));
        List<Contour> loops = RegionOffsetter.inward(RegionOffsetter.oriented(outer, List.of(island)), 5, TOL);
        assertAll(
                () -> assertEquals(2, loops.size()),
                () -> assertTrue(loops.get(0).isCcw()),
                () -> assertEquals(90 * 90, loops.get(0).area(), 1e-6),
                () -> assertTrue(!loops.get(1).isCcw()),
                () -> assertEquals(
                        20 * 20 + 4 * 20 * 5 + Math.PI * 25, loops.get(1).area(), 1e-6),
                () -> assertEquals(
                        4,
                        loops.get(1).curves().stream()
                                .filter(c -> c instanceof Arc2)
                                .count()));
    }

    @Test
    void anIslandNearTheWallMergesWithTheOuterOffset() {
        Contour outer = Contour.polygon(List.of(new Vec2(0, 0), new Vec2(100, 0), new Vec2(100, 50), new Vec2(0, 50)));
        // 4 mm from the bottom wall: at offset 3 the ring around it and the outer loop meet
        Contour island = Contour.polygon(List.of(new Vec2(40, 4), new Vec2(60, 4), new Vec2(60, 20), new Vec2(40, 20)));
        List<Contour> loops = RegionOffsetter.inward(RegionOffsetter.oriented(outer, List.of(island)), 3, TOL);
        assertEquals(1, loops.size());
        Geometry expected = region(List.of(outer, island)).buffer(-3, 256);
        assertEquals(expected.getArea(), loops.get(0).area(), 0.01);
    }

    @Test
    @InterpreterCheck
    void threeRoomsWithTwoIslandsSplitThreeWaysAndAreMilledCompletelyWithinTheirWalls(@TempDir Path dir)
            throws Exception {
        List<Contour> c = read("samples/pocket/rooms-islands.contour");
        assertEquals(3, c.size());
        PocketTechnology t = new PocketTechnology(6, 0.7, 0.1, 0, -6, 3, 3000, 300, 100);
        RegionPocket.Plan plan = RegionPocket.plan(c.get(0), c.subList(1, 3), t, true);
        List<Long> faces = plan.levels().stream()
                .map(l -> l.loops().stream().filter(Contour::isCcw).count())
                .toList();
        int split = faces.indexOf(faces.stream().filter(f -> f > 1).findFirst().orElseThrow());
        // one face becomes three at one step: both necks close at t = 5
        assertAll(
                () -> assertEquals(1, faces.get(split - 1)),
                () -> assertEquals(3, faces.get(split)),
                () -> assertTrue(plan.levels().get(split - 1).offsetMm() < 5
                        && plan.levels().get(split).offsetMm() > 5));
        // both islands are ringed by the finishing pass
        assertEquals(
                2, plan.levels().get(0).loops().stream().filter(l -> !l.isCcw()).count());
        Geometry wall = region(c);
        Geometry reachable = wall.buffer(-3, 64).buffer(3, 64);
        Geometry swept = PocketCoverageTest.swept(plan.toolpath(), -6, 3);
        double uncut = reachable.buffer(-0.01, 64).difference(swept).getArea();
        double outside = swept.difference(wall.buffer(0.01, 64)).getArea();
        System.out.printf(
                java.util.Locale.ROOT,
                "rooms-islands: %d levels, uncut %.5f mm2, outside %.5f mm2%n",
                plan.levels().size(),
                uncut,
                outside);
        assertTrue(uncut < 1e-3, "uncut " + uncut + " mm2");
        assertTrue(outside < 1e-3, "beyond the walls " + outside + " mm2");
        assumeTrue(Rs274.available(), Rs274.whyNot());
        StringWriter w = new StringWriter();
        NcPosts.byName("linuxcnc").orElseThrow().write(plan.toolpath(), "rooms-islands", w);
        Path f = dir.resolve("rooms-islands.ngc");
        Files.writeString(f, w.toString());
        Rs274.Result r = Rs274.run(f, 6);
        assertEquals(0, r.exitStatus(), r.stderr());
        assertTrue(r.motions().stream().anyMatch(m -> m.kind().equals("arc")), "arcs kept as arcs");
    }
}
