package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.fresa.cutting.CutPath;
import org.fresa.cutting.CutPlan;
import org.fresa.dxf.DxfDrawing;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;
import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.testing.CorpusCheck;
import org.fresa.testing.InterpreterCheck;
import org.fresa.testing.TestInputs;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.LineString;
import org.locationtech.jts.geom.Point;
import org.locationtech.jts.geom.prep.PreparedGeometry;
import org.locationtech.jts.geom.prep.PreparedGeometryFactory;
import org.locationtech.jts.operation.distance.IndexedFacetDistance;

/**
 * Real drawings of the interoperability corpus cut with a 2 mm kerf: LinuxCNC accepts every
 * program, the kerf never enters a part, every reachable edge is cut, and the number of closed
 * contours agrees with an independent count.
 */
class CuttingAcceptanceTest {

    static final Path CORPUS = TestInputs.DXF_CORPUS;
    static final GeometryFactory GF = new GeometryFactory();

    @ParameterizedTest(name = "{0}")
    @ValueSource(
            strings = {
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
                "dxf2gcode/lwpoly-bulge.dxf"
            })
    @InterpreterCheck
    @CorpusCheck
    void aRealDrawingIsCutCleanlyWithATwoMillimetreKerf(String name) throws Exception {
        Path dxf = CORPUS.resolve(name);
        Assumptions.assumeTrue(Files.exists(dxf), "corpus absent");
        CuttingSettings s = new CuttingSettings(
                dxf,
                2,
                org.fresa.cutting.CutProcess.PLASMA,
                3,
                1,
                org.fresa.cutting.LeadShape.ARC,
                0.001,
                org.fresa.dxf.DrawingUnits.AUTO,
                false,
                org.fresa.post.CuttingPost.LINUXCNC);
        CuttingService.Result r = CuttingService.compute(s, ProgressMonitor.NONE);
        CutPlan plan = r.plan();
        rs274Accepts(r.program(), name, 0);
        double half = 1;
        kerfNeverEntersAPart(plan, half, name);
        everyReachableEdgeIsCut(plan, half, name);
        int[] independent = independentClosedCount(r.drawing());
        int found = plan.outers().size() + plan.holes().size();
        if (independent[1] == 0) {
            assertEquals(independent[0], found, name);
        } else {
            // a node where three or more ends meet can be followed several ways: the planner
            // closes at least the loops free of such nodes, and at most one more per such node
            assertTrue(
                    found >= independent[0] && found <= independent[0] + independent[1],
                    name + ": " + found + " closed contours, independent count " + independent[0] + " + up to "
                            + independent[1] + " through junctions");
        }
    }

    /**
     * dxf2gcode's inch plate: its outlines meet with gaps of 0.008 to 0.011 mm, closed at the
     * default gap tolerance; all 20 loops (ezdxf 1.4's edgeminer finds 20 too) are cut, the four
     * 1049 x 1863 mm parts among them, and each gap closed is listed with its place.
     */
    @org.junit.jupiter.api.Test
    @CorpusCheck
    void theInchPlatesPartsCloseAcrossTheirTinyGapsAndAreAllCut() throws Exception {
        Path dxf = CORPUS.resolve("dxf2gcode/Teile.dxf");
        CuttingSettings s = new CuttingSettings(
                dxf,
                2,
                org.fresa.cutting.CutProcess.PLASMA,
                3,
                1,
                org.fresa.cutting.LeadShape.ARC,
                org.fresa.cutting.CuttingOptions.DEFAULT_GAP_MM,
                org.fresa.dxf.DrawingUnits.AUTO,
                false,
                org.fresa.post.CuttingPost.LINUXCNC);
        CutPlan plan = CuttingService.compute(s, ProgressMonitor.NONE).plan();
        List<String> gaps =
                plan.warnings().stream().filter(w -> w.startsWith("gap of ")).toList();
        org.junit.jupiter.api.Assertions.assertAll(
                () -> assertEquals(20, plan.outers().size() + plan.holes().size()),
                () -> assertEquals(0, plan.open().size(), plan.warnings()::toString),
                () -> assertEquals(List.of(), plan.uncut(), plan.warnings()::toString),
                () -> assertEquals(20, plan.cuts().size()),
                () -> assertEquals(
                        4,
                        plan.outers().stream()
                                .filter(c ->
                                        c.bounds().width() > 1049 && c.bounds().height() > 1863)
                                .count()),
                () -> assertEquals(16, gaps.size(), gaps::toString),
                () -> assertTrue(
                        gaps.contains("gap of 0.0084 mm between two ends closed at (445.423, 289.217)"),
                        gaps::toString));
    }

    @org.junit.jupiter.api.Test
    @InterpreterCheck
    void controllerCompensationProgramsPassLinuxCncsGougeChecks() throws Exception {
        Path dxf = Path.of("samples/cutting/plate.dxf");
        org.fresa.dxf.DxfDrawing d = org.fresa.dxf.DxfReader.read(dxf);
        org.fresa.cutting.CuttingOptions o = org.fresa.cutting.CuttingOptions.of(
                        org.fresa.cutting.CutProcess.PLASMA, 2, 3, 1, true)
                .withControllerCompensation(true);
        CutPlan plan = org.fresa.cutting.CutPlanner.plan(d.layers(), o);
        List<Integer> comp = plan.cuts().stream().map(CutPath::compensation).toList();
        assertTrue(comp.stream().allMatch(c -> c == 41), comp.toString());
        java.io.StringWriter w = new java.io.StringWriter();
        org.fresa.post.SheetCuttingPost.write(
                plan.toolpath(),
                "plate",
                new org.fresa.post.SheetCuttingPost.Job("plasma", 0.5, comp, 2),
                org.fresa.post.CuttingPost.LINUXCNC,
                w);
        assertTrue(w.toString().contains("G41 G1"), w.toString());
        rs274Accepts(w.toString(), "plate G41", 2);
    }

    static java.util.stream.Stream<String> corpus() throws IOException {
        Assumptions.assumeTrue(Files.isDirectory(CORPUS), "corpus absent");
        try (java.util.stream.Stream<Path> s = Files.walk(CORPUS)) {
            return s
                    .filter(p -> p.toString().toLowerCase(java.util.Locale.ROOT).endsWith(".dxf"))
                    .map(p -> CORPUS.relativize(p).toString())
                    .sorted()
                    .toList()
                    .stream();
        }
    }

    /** Every corpus drawing, default and paper mode: a program LinuxCNC accepts, or a clear refusal of the file. */
    @ParameterizedTest(name = "{0}")
    @org.junit.jupiter.params.provider.MethodSource("corpus")
    @InterpreterCheck
    @CorpusCheck
    void everyCorpusDrawingIsCutInBothModesIntoAProgramLinuxCncAccepts(String name) throws Exception {
        for (boolean paper : new boolean[] {false, true}) {
            CuttingSettings s = new CuttingSettings(
                    CORPUS.resolve(name),
                    2,
                    org.fresa.cutting.CutProcess.PLASMA,
                    3,
                    1,
                    org.fresa.cutting.LeadShape.ARC,
                    0.001,
                    org.fresa.dxf.DrawingUnits.AUTO,
                    paper,
                    org.fresa.post.CuttingPost.LINUXCNC);
            CuttingService.Result r;
            try {
                r = CuttingService.compute(s, ProgressMonitor.NONE);
            } catch (org.fresa.model.CamInputException e) {
                assertTrue(e.getMessage().contains(name.substring(name.indexOf('/') + 1)), e.getMessage());
                return;
            }
            rs274Accepts(r.program(), name + (paper ? " (paper mode)" : ""), 0);
        }
    }

    /** G41/G42 left to the controller (D = the 2 mm kerf): LinuxCNC's cutter-compensation checks pass. */
    @ParameterizedTest(name = "{0}")
    @ValueSource(
            strings = {
                "dxf2gcode/132_2000.dxf",
                "dxf2gcode/pumpenteile.dxf",
                "dxf2gcode/Teile.dxf",
                "ezdxf/examples_addons_optimize_forms.dxf",
                "dxf2gcode/2-test-layers-nested.dxf",
                "dxf2gcode/lwpoly-bulge.dxf",
                "dxf2gcode/american-flag.dxf",
                "dxf2gcode/Schlüssel_Andi.dxf"
            })
    @InterpreterCheck
    @CorpusCheck
    void controllerCompensationOnRealDrawingsPassesLinuxCnc(String name) throws Exception {
        Path dxf = CORPUS.resolve(name);
        Assumptions.assumeTrue(Files.exists(dxf), "corpus absent");
        CuttingSettings s = new CuttingSettings(
                dxf,
                2,
                org.fresa.cutting.CutProcess.PLASMA,
                3,
                1,
                org.fresa.cutting.LeadShape.ARC,
                0.001,
                org.fresa.dxf.DrawingUnits.AUTO,
                false,
                org.fresa.post.CuttingPost.LINUXCNC,
                org.fresa.cutting.KerfCompensation.CONTROLLER,
                org.fresa.cutting.CutSense.PROCESS,
                org.fresa.cutting.CutSense.PROCESS,
                0,
                true);
        CuttingService.Result r = CuttingService.compute(s, ProgressMonitor.NONE);
        assertTrue(r.program().contains("G41"), name);
        rs274Accepts(r.program(), name + " G41/G42", 2);
    }

    @ParameterizedTest(name = "post {0}")
    @ValueSource(strings = {"linuxcnc", "iso"})
    @InterpreterCheck
    void theSamplePlateIsAcceptedByLinuxCncInEveryRs274Dialect(String post) throws Exception {
        CuttingSettings s = new CuttingSettings(
                Path.of("samples/cutting/plate.dxf"),
                2,
                org.fresa.cutting.CutProcess.LASER,
                3,
                1,
                org.fresa.cutting.LeadShape.LINE,
                0.001,
                org.fresa.dxf.DrawingUnits.AUTO,
                false,
                org.fresa.setting.SettingRanges.Cutting.POST.require(post));
        CuttingService.Result r = CuttingService.compute(s, ProgressMonitor.NONE);
        assertEquals(10, r.plan().cuts().size());
        // iso dwells are G04 X seconds (Fanuc-like controls); LinuxCNC's word for the same is P,
        // as NcPostsTest translates the milling iso post
        String program = post.equals("iso") ? r.program().replaceAll("(?m)^(N\\d+ )?G04 X", "$1G04 P") : r.program();
        if (post.equals("iso")) {
            assertTrue(r.program().contains("G04 X"), "the plate's pierces dwell");
        }
        rs274Accepts(program, post, 0);
    }

    static void rs274Accepts(String program, String name, double toolDiameter)
            throws IOException, InterruptedException {
        Assumptions.assumeTrue(org.fresa.post.Rs274.available(), org.fresa.post.Rs274.whyNot());
        Path f = Files.createTempFile("cut", ".ngc");
        Files.writeString(f, program);
        org.fresa.post.Rs274.Result r = org.fresa.post.Rs274.run(f, toolDiameter);
        Files.deleteIfExists(f);
        assertEquals(0, r.exitStatus(), () -> name + ": rs274 rejected the program: " + org.fresa.post.Rs274.log(r));
    }

    static String tail(String s) {
        return s.length() > 800 ? s.substring(s.length() - 800) : s;
    }

    /** The region between the contours (odd nesting depth inside), from JTS polygons of the drawn contours. */
    static Geometry material(CutPlan plan, List<Contour> except) {
        Geometry m = GF.createPolygon();
        List<Contour> all = new ArrayList<>(plan.outers());
        all.addAll(plan.holes());
        all.removeAll(except);
        for (Contour c : all) {
            m = m.symDifference(polygon(c));
        }
        return m;
    }

    static Geometry polygon(Contour c) {
        List<Coordinate> pts = new ArrayList<>();
        for (Curve2 cv : c.curves()) {
            for (Vec2 p : sample(cv, 1e-5)) {
                pts.add(new Coordinate(p.x(), p.y()));
            }
        }
        pts.add(pts.get(0));
        return GF.createPolygon(pts.toArray(new Coordinate[0])).buffer(0);
    }

    /** Points of a curve from its start (inclusive) to its end (exclusive), chord error below errMm. */
    static List<Vec2> sample(Curve2 c, double errMm) {
        int n = 1;
        if (c instanceof Arc2 a) {
            double r = a.radius();
            double step = r > errMm ? 2 * Math.acos(1 - errMm / r) : Math.PI / 4;
            n = Math.max(2, (int) Math.ceil(Math.abs(a.sweepRad()) / step));
            n = Math.min(n, 4000);
        }
        List<Vec2> out = new ArrayList<>();
        for (int k = 0; k < n; k++) {
            out.add(c.pointAt((double) k / n));
        }
        return out;
    }

    static void kerfNeverEntersAPart(CutPlan plan, double half, String name) {
        List<Contour> crossing = crossing(plan);
        PreparedGeometry inside = PreparedGeometryFactory.prepare(material(plan, crossing));
        IndexedFacetDistance boundary = new IndexedFacetDistance(lines(drawn(plan), 1e-5));
        for (CutPath c : plan.cuts()) {
            if (crossing.contains(c.part())) {
                continue; // drawn contours that cross each other cannot both be cut without touching
            }
            for (Curve2 cv : c.curves()) {
                int n = Math.min(400, Math.max(2, (int) Math.ceil(cv.length() / 0.2)));
                for (int k = 0; k <= n; k++) {
                    Vec2 p = cv.pointAt((double) k / n);
                    Point pt = GF.createPoint(new Coordinate(p.x(), p.y()));
                    double d = boundary.distance(pt);
                    assertTrue(
                            d > half - 2e-3 && !inside.contains(pt),
                            name + ": the kerf of " + c.label() + " at " + p + " reaches a part (" + d
                                    + " mm from its edge)");
                }
            }
        }
    }

    /** Drawn contours whose outline crosses another's (overlapping parts in the drawing). */
    static List<Contour> crossing(CutPlan plan) {
        List<Contour> all = new ArrayList<>(plan.outers());
        all.addAll(plan.holes());
        List<Geometry> rings = new ArrayList<>();
        for (Contour c : all) {
            rings.add(lines(c.curves(), 1e-4));
        }
        List<Contour> out = new ArrayList<>();
        Geometry region = GF.createPolygon();
        for (int i = 0; i < all.size(); i++) {
            for (int j = 0; j < all.size(); j++) {
                if (i != j
                        && rings.get(i)
                                .getEnvelopeInternal()
                                .intersects(rings.get(j).getEnvelopeInternal())
                        && rings.get(i).intersects(rings.get(j))) {
                    out.add(all.get(i));
                    region = region.union(polygon(all.get(i)));
                    break;
                }
            }
        }
        // and everything nested inside them: their parity is undefined
        for (Contour c : all) {
            if (!out.contains(c) && !region.isEmpty() && region.covers(polygon(c))) {
                out.add(c);
            }
        }
        return out;
    }

    static List<Curve2> drawn(CutPlan plan) {
        List<Curve2> drawn = new ArrayList<>();
        for (Contour c : plan.outers()) {
            drawn.addAll(c.curves());
        }
        for (Contour c : plan.holes()) {
            drawn.addAll(c.curves());
        }
        return drawn;
    }

    static Geometry lines(List<Curve2> curves, double err) {
        List<LineString> ls = new ArrayList<>();
        for (Curve2 c : curves) {
            List<Coordinate> pts = new ArrayList<>();
            for (Vec2 p : sample(c, err)) {
                pts.add(new Coordinate(p.x(), p.y()));
            }
            pts.add(new Coordinate(c.end().x(), c.end().y()));
            ls.add(GF.createLineString(pts.toArray(new Coordinate[0])));
        }
        return GF.createMultiLineString(ls.toArray(new LineString[0]));
    }

    static void everyReachableEdgeIsCut(CutPlan plan, double half, String name) {
        List<Curve2> paths = new ArrayList<>();
        for (CutPath c : plan.cuts()) {
            paths.addAll(c.path().curves());
        }
        if (paths.isEmpty()) {
            assertTrue(
                    plan.outers().size() + plan.holes().size() == plan.uncut().size(), name);
            return;
        }
        IndexedFacetDistance drawnIndex = new IndexedFacetDistance(lines(drawn(plan), 1e-6));
        IndexedFacetDistance pathIndex = new IndexedFacetDistance(lines(paths, 1e-6));
        int checked = 0;
        List<Contour> cut = new ArrayList<>();
        for (Contour c : plan.outers()) {
            if (!plan.uncut().contains(c)) {
                cut.add(c);
            }
        }
        for (Contour c : plan.holes()) {
            if (!plan.uncut().contains(c)) {
                cut.add(c);
            }
        }
        for (Contour c : cut) {
            boolean outer = plan.outers().contains(c);
            boolean ccw = c.isCcw();
            for (Curve2 e : c.curves()) {
                Vec2 m = e.pointAt(0.5);
                Vec2 t;
                try {
                    t = e instanceof Arc2 a
                            ? (a.ccw()
                                    ? m.minus(a.center()).normalized().leftNormal()
                                    : m.minus(a.center())
                                            .normalized()
                                            .leftNormal()
                                            .negated())
                            : e.startTangent();
                } catch (IllegalArgumentException ex) {
                    continue;
                }
                Vec2 inward = ccw ? t.leftNormal() : t.leftNormal().negated();
                Vec2 scrap = outer ? inward.negated() : inward;
                Vec2 q = m.plus(scrap.times(half));
                Point qp = GF.createPoint(new Coordinate(q.x(), q.y()));
                if (drawnIndex.distance(qp) < half - 1e-4) {
                    continue; // the kerf's disc does not fit there: an unreachable corner or slot
                }
                checked++;
                // within the drawing's own joint error (gap tolerance 0.001 mm) and the index's chords
                double d = pathIndex.distance(qp);
                assertTrue(d < 2e-3, name + ": the edge " + e + " of a contour is not cut (path " + d + " mm off)");
            }
        }
        assertTrue(checked > 0 || cut.isEmpty(), name);
    }

    static double nearest(List<Curve2> curves, Vec2 p) {
        double best = Double.POSITIVE_INFINITY;
        for (Curve2 c : curves) {
            Box2 b = c.bounds();
            double dx = Math.max(0, Math.max(b.minX() - p.x(), p.x() - b.maxX()));
            double dy = Math.max(0, Math.max(b.minY() - p.y(), p.y() - b.maxY()));
            if (dx >= best || dy >= best) {
                continue;
            }
            best = Math.min(best, c.distanceTo(p));
        }
        return best;
    }

    /**
     * An independent count of closed contours: end points merged within 0.001 mm by union-find,
     * zero-length and repeated elements dropped, full circles counted alone, then every connected
     * component whose nodes all have degree 2 is one closed contour.
     */
    static int[] independentClosedCount(DxfDrawing d) {
        int[] total = {0, 0};
        for (List<Curve2> layer : d.layers().values()) {
            int[] c = closedIn(layer);
            total[0] += c[0];
            total[1] += c[1];
        }
        return total;
    }

    /** {closed loops free of junctions, nodes of degree above 2}. */
    static int[] closedIn(List<Curve2> curves) {
        double tol = 0.001;
        List<Vec2> pts = new ArrayList<>();
        List<int[]> edges = new ArrayList<>();
        Map<String, Integer> seen = new HashMap<>();
        int circles = 0;
        for (Curve2 c : curves) {
            if (c instanceof Arc2 a && a.isFullCircle()) {
                String key = "c" + Math.round(a.center().x() / tol) + ","
                        + Math.round(a.center().y() / tol) + "," + Math.round(a.radius() / tol);
                if (seen.putIfAbsent(key, 1) == null) {
                    circles++;
                }
                continue;
            }
            if (c.start().distance(c.end()) <= tol) {
                continue;
            }
            Vec2 m = c.pointAt(0.5);
            long ax = Math.round(c.start().x() / tol);
            long ay = Math.round(c.start().y() / tol);
            long bx = Math.round(c.end().x() / tol);
            long by = Math.round(c.end().y() / tol);
            String k1 = ax + "," + ay;
            String k2 = bx + "," + by;
            String key = (k1.compareTo(k2) < 0 ? k1 + ";" + k2 : k2 + ";" + k1) + ";" + Math.round(m.x() / tol) + ","
                    + Math.round(m.y() / tol);
            if (seen.putIfAbsent(key, 1) != null) {
                continue;
            }
            edges.add(new int[] {pts.size(), pts.size() + 1});
            pts.add(c.start());
            pts.add(c.end());
        }
        int n = pts.size();
        int[] parent = new int[n];
        for (int i = 0; i < n; i++) {
            parent[i] = i;
        }
        // merge points within tol: sort by x and sweep
        Integer[] idx = new Integer[n];
        for (int i = 0; i < n; i++) {
            idx[i] = i;
        }
        java.util.Arrays.sort(
                idx, (a, b) -> Double.compare(pts.get(a).x(), pts.get(b).x()));
        for (int i = 0; i < n; i++) {
            for (int j = i + 1; j < n && pts.get(idx[j]).x() - pts.get(idx[i]).x() <= tol; j++) {
                if (pts.get(idx[i]).distance(pts.get(idx[j])) <= tol) {
                    union(parent, idx[i], idx[j]);
                }
            }
        }
        Map<Integer, Integer> degree = new HashMap<>();
        for (int[] e : edges) {
            degree.merge(find(parent, e[0]), 1, Integer::sum);
            degree.merge(find(parent, e[1]), 1, Integer::sum);
        }
        // components over nodes, joined by edges
        Map<Integer, Integer> comp = new HashMap<>();
        int[] cp = new int[n];
        for (int i = 0; i < n; i++) {
            cp[i] = i;
        }
        for (int[] e : edges) {
            union(cp, find(parent, e[0]), find(parent, e[1]));
        }
        Map<Integer, Boolean> allTwo = new HashMap<>();
        for (Map.Entry<Integer, Integer> e : degree.entrySet()) {
            int c = find(cp, e.getKey());
            allTwo.merge(c, e.getValue() == 2, Boolean::logicalAnd);
        }
        int closed = 0;
        for (boolean b : allTwo.values()) {
            if (b) {
                closed++;
            }
        }
        comp.clear();
        int junctions = 0;
        for (int deg : degree.values()) {
            if (deg > 2) {
                junctions++;
            }
        }
        return new int[] {closed + circles, junctions};
    }

    static int find(int[] p, int i) {
        while (p[i] != i) {
            p[i] = p[p[i]];
            i = p[i];
        }
        return i;
    }

    static void union(int[] p, int a, int b) {
        p[find(p, a)] = find(p, b);
    }
}
