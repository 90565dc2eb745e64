package org.fresa.pocket;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;
import org.fresa.model.Toolpath;
import org.fresa.post.NcPosts;
import org.fresa.post.Rs274;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIfSystemProperty;
import org.locationtech.jts.geom.Geometry;

/**
 * The island pockets Fresa is measured on against FreeCAD's libarea (bench/libarea, and
 * docs/pocket-vs-libarea.md): seeded random pockets of lines and arcs with one to three islands
 * from {@link PocketCleanUpTest#pocket}, each with its technology. With the system property
 * {@code fresa.bench.out} set to a folder, the export writes the pockets as JSON
 * ({@code pockets.json}, read by bench/libarea/pocket.py) and Fresa's program for each
 * ({@code ours/NAME.ngc}, LinuxCNC post); without it the export does not run.
 */
class LibareaPockets {

    /** How many pockets of each island count (1, 2, 3) the set holds. */
    static final int PER_ISLAND_COUNT = 8;
    /** The seed of the set: the same pockets every run. */
    static final long SEED = 2021;

    /** A pocket of the set: its name, outer contour then islands, and technology. */
    record Bench(String name, List<Contour> contours, PocketTechnology tech) {}

    /**
     * The set: the first PER_ISLAND_COUNT pockets with one, two and three islands of the seeded
     * generator that the planner takes.
     */
    static List<Bench> pockets() {
        return pockets(Double.NaN);
    }

    /** The set, with the finishing allowance (fraction of D) given, or the generator's when NaN. */
    static List<Bench> pockets(double finishFraction) {
        Random rnd = new Random(SEED);
        List<Bench> out = new ArrayList<>();
        int[] taken = new int[4];
        for (int attempt = 0; out.size() < 3 * PER_ISLAND_COUNT && attempt < 1000; attempt++) {
            List<Contour> p = PocketCleanUpTest.pocket(rnd);
            PocketTechnology t = PocketCleanUpTest.tech(rnd);
            if (p.size() < 2 || taken[p.size() - 1] >= PER_ISLAND_COUNT) {
                continue;
            }
            // the same feed for every pass: the bench compares paths, not the finishing feed
            PocketTechnology same = new PocketTechnology(
                    t.toolDiameterMm(),
                    t.cutFraction(),
                    Double.isNaN(finishFraction) ? t.finishFraction() : finishFraction,
                    t.zTopMm(),
                    t.zBottomMm(),
                    t.maxDepthMm(),
                    t.spindleRpm(),
                    t.feedMmPerMin(),
                    t.feedMmPerMin());
            try {
                plan(new Bench("", p, same));
            } catch (ToolTooLargeException | IllegalArgumentException e) {
                continue;
            }
            taken[p.size() - 1]++;
            out.add(new Bench(String.format(Locale.ROOT, "r%02d-i%d", out.size(), p.size() - 1), p, same));
        }
        return out;
    }

    /** Fresa's default plan of a bench pocket (climb, the default entry). */
    static RegionPocket.Plan plan(Bench b) throws ToolTooLargeException {
        return RegionPocket.plan(
                b.contours().get(0), b.contours().subList(1, b.contours().size()), b.tech(), true);
    }

    /** Fresa's program of a bench pocket, LinuxCNC post. */
    static String program(Bench b) throws IOException, ToolTooLargeException {
        Toolpath path = plan(b).toolpath();
        StringWriter w = new StringWriter();
        NcPosts.byName("linuxcnc").orElseThrow().write(path, b.name(), w);
        return w.toString();
    }

    @Test
    @EnabledIfSystemProperty(named = "fresa.bench.out", matches = ".+")
    void export() throws Exception {
        // (the uncut measure below runs after bench/libarea/pocket.py has written libarea's programs)
        Path dir = Path.of(System.getProperty("fresa.bench.out"));
        Files.createDirectories(dir.resolve("ours"));
        StringBuilder json = new StringBuilder("[\n");
        List<Bench> set = pockets(allowance());
        for (int i = 0; i < set.size(); i++) {
            Bench b = set.get(i);
            Files.writeString(dir.resolve("ours").resolve(b.name() + ".ngc"), program(b));
            PocketTechnology t = b.tech();
            json.append(String.format(
                    Locale.ROOT,
                    "{\"name\": \"%s\", \"toolDiameterMm\": %s, \"stepoverMm\": %s, \"zTopMm\": %s,"
                            + " \"zBottomMm\": %s, \"depthStepMm\": %s, \"clearanceZMm\": %s,"
                            + " \"feedMmPerMin\": %s, \"contours\": [",
                    b.name(),
                    num(t.toolDiameterMm()),
                    num(t.effectiveCut() * t.toolDiameterMm()),
                    num(t.zTopMm()),
                    num(t.zBottomMm()),
                    num(t.depthStepMm()),
                    num(t.zTopMm() + 5),
                    num(t.feedMmPerMin())));
            for (int k = 0; k < b.contours().size(); k++) {
                // outer counter-clockwise, islands clockwise, as libarea's areas are
                Contour c = b.contours().get(k);
                Contour o = (k == 0) == c.isCcw() ? c : c.reversed();
                json.append(k == 0 ? "\n  " : ",\n  ").append(contour(o));
            }
            json.append("]}").append(i + 1 < set.size() ? ",\n" : "\n");
        }
        json.append("]\n");
        Files.writeString(dir.resolve("pockets.json"), json.toString());
    }

    /** The finishing allowance of the property fresa.bench.allowance (fraction of D), NaN without it. */
    private static double allowance() {
        String a = System.getProperty("fresa.bench.allowance", "");
        return a.isBlank() ? Double.NaN : Double.parseDouble(a);
    }

    /**
     * The floor each side leaves uncut and how far it cuts into a wall, measured as {@link
     * PocketCleanUpTest} measures Fresa's pockets (LinuxCNC's moves, JTS): DIR/uncut.csv for the
     * programs in DIR/ours and DIR/theirs (where bench/libarea/pocket.py writes libarea's).
     */
    @Test
    @EnabledIfSystemProperty(named = "fresa.bench.out", matches = ".+")
    void uncut() throws Exception {
        Path dir = Path.of(System.getProperty("fresa.bench.out"));
        if (!Files.isDirectory(dir.resolve("theirs"))) {
            return;
        }
        StringBuilder csv = new StringBuilder("pocket,side,uncutMm2,gougeMm\n");
        for (Bench b : pockets(allowance())) {
            PocketTechnology t = b.tech();
            Geometry wall = RegionPocketTest.region(b.contours());
            Geometry reachable = wall.buffer(-t.radiusMm(), 32).buffer(t.radiusMm(), 32);
            for (String side : List.of("ours", "theirs")) {
                Path f = dir.resolve(side).resolve(b.name() + ".ngc");
                if (!Files.exists(f)) {
                    continue;
                }
                Rs274.Result res = Rs274.run(f, t.toolDiameterMm());
                PocketCleanUpTest.Verdict v = PocketCleanUpTest.verdict(
                        res.motions(), t.zBottomMm(), t.zTopMm(), t.radiusMm(), wall, reachable);
                csv.append(String.format(Locale.ROOT, "%s,%s,%.4f,%.4f%n", b.name(), side, v.uncutMm2(), v.gougeMm()));
            }
        }
        Files.writeString(dir.resolve("uncut.csv"), csv.toString());
    }

    /**
     * A contour as libarea's vertices: [type, x, y, cx, cy] with type 0 a line to (x, y), 1 a
     * counter-clockwise and -1 a clockwise arc about (cx, cy); the first entry is the start.
     * Whole circles are written as two half circles.
     */
    private static String contour(Contour c) {
        List<String> v = new ArrayList<>();
        Vec2 s = c.get(0).start();
        v.add(String.format(Locale.ROOT, "[0, %s, %s, 0, 0]", num(s.x()), num(s.y())));
        for (Curve2 k : c.curves()) {
            if (k instanceof Arc2 a) {
                int type = a.ccw() ? 1 : -1;
                if (a.isFullCircle()) {
                    Vec2 opp = a.center().times(2).minus(a.start());
                    v.add(vertex(type, opp, a.center()));
                }
                v.add(vertex(type, a.end(), a.center()));
            } else {
                v.add(vertex(0, k.end(), Vec2.ZERO));
            }
        }
        return "[" + String.join(", ", v) + "]";
    }

    private static String vertex(int type, Vec2 p, Vec2 c) {
        return String.format(Locale.ROOT, "[%d, %s, %s, %s, %s]", type, num(p.x()), num(p.y()), num(c.x()), num(c.y()));
    }

    private static String num(double v) {
        return String.format(Locale.ROOT, "%.9f", v);
    }
}
