package org.fresa.cutting;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Stream;
import org.fresa.dxf.DxfDrawing;
import org.fresa.dxf.DxfReader;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.testing.CorpusCheck;
import org.fresa.testing.TestInputs;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.LineString;
import org.locationtech.jts.geom.prep.PreparedGeometry;
import org.locationtech.jts.geom.prep.PreparedGeometryFactory;

/**
 * Rapid moves avoid crossing parts already cut free, checked independently with JTS:
 * a rapid segment crosses a part when it meets the interior of the part's drawn outline.
 */
class RapidRouterTest {

    static final Path CORPUS = TestInputs.DXF_CORPUS;
    static final GeometryFactory GF = new GeometryFactory();

    static Contour square(double x0, double y0, double side) {
        Vec2 a = new Vec2(x0, y0);
        Vec2 b = new Vec2(x0 + side, y0);
        Vec2 c = new Vec2(x0 + side, y0 + side);
        Vec2 d = new Vec2(x0, y0 + side);
        return new Contour(List.of(new Segment2(a, b), new Segment2(b, c), new Segment2(c, d), new Segment2(d, a)));
    }

    static double length(List<Vec2> route) {
        double l = 0;
        for (int i = 0; i + 1 < route.size(); i++) {
            l += route.get(i).distance(route.get(i + 1));
        }
        return l;
    }

    @Test
    void aRapidAcrossACutPartGoesAroundItsCornerWithTheClearance() {
        RapidRouter r = new RapidRouter(1);
        r.cutFree(square(0, 0, 10));
        List<Vec2> route = r.route(new Vec2(-5, 4), new Vec2(15, 4));
        // around a corner of the square grown by the clearance: longer than straight, shorter than a lap
        assertAll(
                () -> assertTrue(route.size() > 2, route.toString()),
                () -> assertEquals(new Vec2(-5, 4), route.get(0)),
                () -> assertEquals(new Vec2(15, 4), route.get(route.size() - 1)),
                () -> assertTrue(length(route) > 20 && length(route) < 20 + 2 * 6, length(route) + " mm"),
                () -> assertEquals(0, crossings(route, List.of(square(0, 0, 10)))));
    }

    @Test
    void aRapidThatMissesEveryCutPartStaysStraight() {
        RapidRouter r = new RapidRouter(1);
        r.cutFree(square(0, 0, 10));
        assertEquals(List.of(new Vec2(-5, 20), new Vec2(15, 20)), r.route(new Vec2(-5, 20), new Vec2(15, 20)));
    }

    @Test
    void aDetourAroundOnePartDoesNotRunIntoTheNext() {
        RapidRouter r = new RapidRouter(0.5);
        List<Contour> cut = List.of(square(0, 0, 10), square(0, -12, 10), square(0, 12, 10));
        cut.forEach(r::cutFree);
        List<Vec2> route = r.route(new Vec2(-5, 5), new Vec2(15, 5));
        assertEquals(0, crossings(route, cut), route.toString());
    }

    @Test
    void aRapidEndingInsideACutPartsHullStaysStraightAndIsCounted() {
        RapidRouter r = new RapidRouter(0.5);
        r.cutFree(square(0, 0, 10));
        assertEquals(2, r.route(new Vec2(-5, 5), new Vec2(5, 5)).size());
        assertEquals(1, r.unavoidable());
    }

    @Test
    void theConvexHullHoldsTheWholeArcOfACircle() {
        Vec2[] h = RapidRouter.hull(
                List.of(new Vec2(0, 0), new Vec2(2, 0), new Vec2(1, 1), new Vec2(1, 0.5), new Vec2(0, 2)));
        assertEquals(3, h.length); // (1, 1) lies on the edge, (1, 0.5) inside
        RapidRouter r = new RapidRouter(0);
        r.cutFree(new Contour(List.of(Arc2.circle(Vec2.ZERO, 10, true))));
        // a chord just inside the circle's top is blocked; one just outside is not
        assertTrue(r.route(new Vec2(-20, 9.99), new Vec2(20, 9.99)).size() > 2);
        assertEquals(2, r.route(new Vec2(-20, 10.2), new Vec2(20, 10.2)).size());
    }

    /** Rapid segments of the route that enter the interior of one of the parts. */
    static int crossings(List<Vec2> route, List<Contour> parts) {
        int n = 0;
        for (int i = 0; i + 1 < route.size(); i++) {
            LineString s = segment(route.get(i), route.get(i + 1));
            for (Contour c : parts) {
                Geometry p = polygon(c);
                if (s.intersects(p) && !s.touches(p)) {
                    n++;
                    break;
                }
            }
        }
        return n;
    }

    static LineString segment(Vec2 a, Vec2 b) {
        return GF.createLineString(new Coordinate[] {new Coordinate(a.x(), a.y()), new Coordinate(b.x(), b.y())});
    }

    static Geometry polygon(Contour c) {
        List<Coordinate> pts = new ArrayList<>();
        for (Curve2 cv : c.curves()) {
            int n = cv instanceof Arc2 a ? Math.max(2, (int) Math.ceil(Math.abs(a.sweepRad()) / Math.toRadians(3))) : 1;
            for (int k = 0; k < n; k++) {
                Vec2 p = cv.pointAt((double) k / n);
                pts.add(new Coordinate(p.x(), p.y()));
            }
        }
        pts.add(pts.get(0));
        return GF.createPolygon(pts.toArray(new Coordinate[0])).buffer(0);
    }

    /** {rapid segments crossing an already-cut part: straight, routed; rapids} for one plan. */
    static int[] crossingCounts(CutPlan plan) {
        int before = 0;
        int after = 0;
        List<PreparedGeometry> cutFree = new ArrayList<>();
        List<org.locationtech.jts.geom.Envelope> env = new ArrayList<>();
        Vec2 at = Vec2.ZERO;
        for (int i = 0; i < plan.cuts().size(); i++) {
            CutPath c = plan.cuts().get(i);
            before += count(List.of(at, c.pierce()), cutFree, env);
            after += count(plan.rapids().get(i), cutFree, env);
            if (c.outer()) {
                Geometry g = polygon(c.part());
                cutFree.add(PreparedGeometryFactory.prepare(g));
                env.add(g.getEnvelopeInternal());
            }
            at = c.exit();
        }
        return new int[] {before, after, plan.cuts().size()};
    }

    private static int count(
            List<Vec2> route, List<PreparedGeometry> parts, List<org.locationtech.jts.geom.Envelope> env) {
        int n = 0;
        for (int k = 0; k + 1 < route.size(); k++) {
            LineString s = segment(route.get(k), route.get(k + 1));
            for (int j = 0; j < parts.size(); j++) {
                if (env.get(j).intersects(s.getEnvelopeInternal())
                        && parts.get(j).intersects(s)
                        && !parts.get(j).getGeometry().touches(s)) {
                    n++;
                    break;
                }
            }
        }
        return n;
    }

    /**
     * Every corpus drawing with parts, a 2 mm kerf: the routed rapids cross already-cut parts
     * fewer times than straight ones (the figures go to target/rapid-crossings.txt). By default
     * the drawings of the acceptance list; {@code -Dfresa.corpus.all=true} takes every file.
     */
    @Test
    @CorpusCheck
    void routedRapidsCrossFewerCutPartsThanStraightOnesOnTheCorpus() throws Exception {
        Assumptions.assumeTrue(Files.isDirectory(CORPUS), "corpus absent");
        List<Path> files;
        if (Boolean.getBoolean("fresa.corpus.all")) {
            try (Stream<Path> s = Files.walk(CORPUS)) {
                files = s.filter(p -> p.toString().toLowerCase(Locale.ROOT).endsWith(".dxf"))
                        .sorted()
                        .toList();
            }
        } else {
            files = Stream.of(
                            "dxf2gcode/132_2000.dxf",
                            "dxf2gcode/pumpenteile.dxf",
                            "dxf2gcode/Schlüssel_Andi.dxf",
                            "dxf2gcode/AFluegel_Rippen_b2_0201.dxf",
                            "dxf2gcode/Teile.dxf",
                            "dxf2gcode/american-flag.dxf",
                            "dxf2gcode/celic-knot.dxf",
                            "ezdxf/examples_addons_optimize_forms.dxf",
                            "dxf2gcode/2-test-layers-nested.dxf",
                            "dxf2gcode/1-poly-with-reflex.dxf",
                            "dxf2gcode/liu-8f.dxf",
                            "dxf2gcode/lwpoly-bulge.dxf")
                    .map(CORPUS::resolve)
                    .toList();
        }
        StringBuilder report = new StringBuilder("drawing,rapids,crossing_straight,crossing_routed\n");
        int before = 0;
        int after = 0;
        for (Path f : files) {
            DxfDrawing d;
            try {
                d = DxfReader.read(f);
            } catch (org.fresa.model.CamInputException e) {
                continue; // a malformed file: DxfCorpusTest checks its message
            }
            Map<String, List<Curve2>> layers = d.layers();
            CutPlan plan = CutPlanner.plan(layers, CuttingOptions.of(CutProcess.PLASMA, 2, 3, 1, true));
            int[] c = crossingCounts(plan);
            report.append(CORPUS.relativize(f))
                    .append(',')
                    .append(c[2])
                    .append(',')
                    .append(c[0])
                    .append(',')
                    .append(c[1])
                    .append('\n');
            assertTrue(c[1] <= c[0], f + ": routed " + c[1] + " > straight " + c[0]);
            before += c[0];
            after += c[1];
        }
        report.append("total,,").append(before).append(',').append(after).append('\n');
        Files.createDirectories(Path.of("target"));
        Files.writeString(Path.of("target/rapid-crossings.txt"), report);
        assertTrue(after < before, report.toString());
        assertFalse(before == 0, "the corpus drawings have no rapid over a cut part to avoid: the check is void");
    }
}
