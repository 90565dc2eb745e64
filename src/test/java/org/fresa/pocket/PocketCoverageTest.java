package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.operation.buffer.BufferParameters;
import org.locationtech.jts.operation.union.UnaryUnionOp;

/**
 * The acceptance check of pocket milling: at the pocket floor the tool disc, swept along every feed move
 * of Fresa's default toolpath, clears the region bounded by the thesis's own finishing pass grown
 * by R, and never leaves it (0.01 mm).
 */
class PocketCoverageTest {

    static final GeometryFactory GF = new GeometryFactory();

    static PocketTechnology tech(String name) throws Exception {
        for (String line : Files.readAllLines(Path.of("samples/pocket/jobs.csv"))) {
            String[] f = line.split(",");
            if (f[0].equals(name + ".dad")) {
                double[] v = new double[9];
                for (int i = 0; i < 9; i++) {
                    v[i] = Double.parseDouble(f[i + 1]);
                }
                return new PocketTechnology(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]);
            }
        }
        throw new IllegalArgumentException(name);
    }

    static List<Coordinate> arcPoints(Vec2 from, Vec2 to, Vec2 c, boolean ccw) {
        double r = from.distance(c);
        double a0 = Math.atan2(from.y() - c.y(), from.x() - c.x());
        double a1 = Math.atan2(to.y() - c.y(), to.x() - c.x());
        double sweep = a1 - a0;
        if (ccw && sweep <= 0) {
            sweep += 2 * Math.PI;
        } else if (!ccw && sweep >= 0) {
            sweep -= 2 * Math.PI;
        }
        if (from.distance(to) < 1e-9) {
            sweep = 0;
        }
        int n = Math.max(2, (int) Math.ceil(Math.abs(sweep) / Math.acos(Math.max(-1, 1 - 0.0005 / Math.max(r, 1e-6)))));
        List<Coordinate> out = new ArrayList<>();
        for (int i = 0; i <= n; i++) {
            double a = a0 + sweep * i / n;
            out.add(new Coordinate(c.x() + r * Math.cos(a), c.y() + r * Math.sin(a)));
        }
        out.set(out.size() - 1, new Coordinate(to.x(), to.y()));
        return out;
    }

    static Geometry swept(Toolpath path, double z, double r) {
        BufferParameters bp = new BufferParameters(64);
        List<Geometry> parts = new ArrayList<>();
        for (ToolpathSection s : path.sections()) {
            Vec3 cur = s.start();
            for (Move m : s.moves()) {
                Vec3 e = m.end();
                boolean floor = Math.abs(cur.z() - z) < 1e-6 && Math.abs(e.z() - z) < 1e-6;
                if (floor && !(m instanceof Move.Rapid)) {
                    List<Coordinate> pts;
                    if (m instanceof Move.Circular c) {
                        pts = arcPoints(cur.xy(), e.xy(), c.center().xy(), c.ccw());
                    } else {
                        pts = List.of(new Coordinate(cur.x(), cur.y()), new Coordinate(e.x(), e.y()));
                    }
                    Geometry g =
                            pts.size() < 2 || pts.get(0).distance(pts.get(pts.size() - 1)) < 1e-9 && pts.size() == 2
                                    ? GF.createPoint(pts.get(0))
                                    : GF.createLineString(pts.toArray(new Coordinate[0]));
                    parts.add(org.locationtech.jts.operation.buffer.BufferOp.bufferOp(g, r, bp));
                }
                cur = e;
            }
        }
        return UnaryUnionOp.union(parts);
    }

    static Geometry region(PocketPass finishing, double r) {
        List<Coordinate> pts = new ArrayList<>();
        for (PassPiece p : finishing.pieces()) {
            if (p.isArc() && p.radiusMm() > 1e-9) {
                // on the arc's true offset circle: cavity 02's snapped junctions lie off it
                Vec2 c = p.center();
                Vec2 s =
                        c.plus(p.start().minus(c).times(p.radiusMm() / p.start().distance(c)));
                Vec2 e = c.plus(p.end().minus(c).times(p.radiusMm() / p.end().distance(c)));
                pts.add(new Coordinate(p.start().x(), p.start().y()));
                pts.addAll(arcPoints(s, e, c, p.ccw()));
                pts.add(new Coordinate(p.end().x(), p.end().y()));
            } else {
                pts.add(new Coordinate(p.start().x(), p.start().y()));
                pts.add(new Coordinate(p.end().x(), p.end().y()));
            }
        }
        pts.add(pts.get(0));
        Geometry poly = GF.createPolygon(pts.toArray(new Coordinate[0])).buffer(0);
        return poly.buffer(r, 64);
    }

    static double[] uncutAndOutside(String name, boolean faithful) throws Exception {
        PocketTechnology t = tech(name);
        Recognition.Result rec = Recognition.of(RecognitionTest.sample(name + ".dad"));
        PocketPlan thesis = PassPlanner.plan(rec, t, true);
        PocketPlan plan = PassPlanner.plan(rec, t, faithful);
        Toolpath path = PocketToolpath.of(plan, true);
        Geometry swept = swept(path, t.zBottomMm(), t.radiusMm());
        Geometry wall = region(thesis.generated().get(0), t.radiusMm());
        double uncut = wall.buffer(-0.01, 64).difference(swept).getArea();
        double outside = swept.difference(wall.buffer(0.01, 64)).getArea();
        return new double[] {uncut, outside};
    }

    @ParameterizedTest
    @ValueSource(
            strings = {"examplepart", "cavity01", "cavity02", "cavity03", "cavity04", "cavity05", "cavity06", "cavity07"
            })
    void defaultPassesClearThePocketFloorAndNeverLeaveIt(String name) throws Exception {
        double[] r = uncutAndOutside(name, false);
        double[] th = uncutAndOutside(name, true);
        System.out.printf(
                java.util.Locale.ROOT,
                "%s default uncut %.4f outside %.4f | thesis uncut %.4f outside %.4f%n",
                name,
                r[0],
                r[1],
                th[0],
                th[1]);
        assertTrue(r[1] < 1e-3, name + " goes beyond the wall by " + r[1] + " mm2");
        assertTrue(r[0] < 1e-3, name + " leaves " + r[0] + " mm2 uncut");
    }
}
