package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import org.fresa.cutting.CutPath;
import org.fresa.cutting.CutPlan;
import org.fresa.cutting.CuttingOptions;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.model.CamInputException;
import org.fresa.testing.CorpusCheck;
import org.fresa.testing.TestInputs;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The cut order on every corpus drawing (the project's and, when beside the checkout, the shared
 * one), cut as {@code --no-avoid-cut-parts --lead-in 0 --lead-out 0} would: the straight rapid
 * travel is at most that of a nearest-neighbour tour computed here, independently of the planner
 * (from the origin to the nearest point of the nearest cut path whose inner contours are all
 * cut), and at least 10 % shorter on drawings with more than 50 pierces.
 */
@CorpusCheck
class CutOrderCorpusTest {

    static Stream<String> drawings() throws IOException {
        List<String> out = new ArrayList<>();
        for (Path root : List.of(TestInputs.DXF_CORPUS, TestInputs.SHARED_CORPUS.resolve("dxf"))) {
            if (!Files.isDirectory(root)) {
                continue;
            }
            try (Stream<Path> s = Files.walk(root)) {
                s.filter(p -> p.toString().toLowerCase(Locale.ROOT).endsWith(".dxf"))
                        .map(Path::toString)
                        .sorted()
                        .forEach(out::add);
            }
        }
        Assumptions.assumeFalse(out.isEmpty(), "corpus absent");
        return out.stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("drawings")
    void theRapidTravelIsNoLongerThanANearestNeighbourTourAndShorterOnBigSheets(String file) throws Exception {
        Path dxf = Path.of(file);
        CuttingSettings s = new CuttingSettings(
                dxf,
                2,
                org.fresa.cutting.CutProcess.PLASMA,
                0,
                0,
                org.fresa.cutting.LeadShape.ARC,
                CuttingOptions.DEFAULT_GAP_MM,
                org.fresa.dxf.DrawingUnits.AUTO,
                false,
                org.fresa.post.CuttingPost.LINUXCNC,
                org.fresa.cutting.KerfCompensation.SOFTWARE,
                org.fresa.cutting.CutSense.PROCESS,
                org.fresa.cutting.CutSense.PROCESS,
                0,
                false);
        CutPlan plan;
        try {
            plan = CuttingService.compute(s, ProgressMonitor.NONE).plan();
        } catch (CamInputException e) {
            Assumptions.abort("refused: " + e.getMessage());
            return;
        }
        Assumptions.assumeFalse(plan.cuts().isEmpty(), "nothing to cut");
        double nn = nearestNeighbourTour(plan.cuts());
        double ours = plan.rapidLengthMm();
        int pierces = plan.cuts().size();
        System.out.printf(
                Locale.ROOT,
                "cut order | %s | %d pierces | nearest-neighbour %.1f mm | ours %.1f mm | %.3f%n",
                dxf.getFileName(),
                pierces,
                nn,
                ours,
                nn > 0 ? ours / nn : 1.0);
        // within a micrometre a pierce, a program's resolution: celic-knot-simple's cut paths hold
        // arcs of radius 5e12 mm (near-straight lines), whose points are known only to about that
        assertTrue(
                ours <= nn + 1e-3 * pierces,
                dxf + ": rapids " + ours + " mm, the nearest-neighbour tour " + nn + " mm");
        if (pierces > 50) {
            assertTrue(
                    ours <= 0.9 * nn,
                    dxf + ": " + pierces + " pierces, rapids " + ours
                            + " mm, not 10 % below the nearest-neighbour tour's " + nn + " mm");
        }
    }

    /**
     * From the origin, to the nearest point of the nearest cut path whose inner contours (drawn
     * contours inside its own) are all cut; a cut without leads ends where it started.
     */
    static double nearestNeighbourTour(List<CutPath> cuts) {
        int n = cuts.size();
        Box2[] box = new Box2[n];
        double[] area = new double[n];
        for (int i = 0; i < n; i++) {
            box[i] = cuts.get(i).part().bounds();
            area[i] = cuts.get(i).part().area();
        }
        // waitFor[i]: how many drawn contours inside cut i's own are not cut yet
        int[] waitFor = new int[n];
        boolean[][] inside = new boolean[n][];
        Tolerance t = new Tolerance(1e-7, 1e-9);
        for (int i = 0; i < n; i++) {
            inside[i] = new boolean[n];
            Contour outer = cuts.get(i).part();
            for (int j = 0; j < n; j++) {
                if (j == i || !(area[j] < area[i]) || !within(box[j], box[i])) {
                    continue;
                }
                Vec2 p = cuts.get(j).part().get(0).pointAt(0.5);
                if (outer.contains(p, t)) {
                    inside[i][j] = true;
                    waitFor[i]++;
                }
            }
        }
        boolean[] done = new boolean[n];
        Vec2 at = Vec2.ZERO;
        double travel = 0;
        for (int k = 0; k < n; k++) {
            int best = -1;
            double bestD = Double.POSITIVE_INFINITY;
            Vec2 bestQ = null;
            for (int i = 0; i < n; i++) {
                if (done[i] || waitFor[i] > 0) {
                    continue;
                }
                for (Curve2 c : cuts.get(i).path().curves()) {
                    Vec2 q = closest(c, at);
                    double d = q.distance(at);
                    if (d < bestD) {
                        bestD = d;
                        best = i;
                        bestQ = q;
                    }
                }
            }
            done[best] = true;
            travel += bestD;
            at = bestQ;
            for (int i = 0; i < n; i++) {
                if (inside[i][best]) {
                    waitFor[i]--;
                }
            }
        }
        return travel;
    }

    private static boolean within(Box2 a, Box2 b) {
        return a.minX() >= b.minX() - 1e-9
                && a.maxX() <= b.maxX() + 1e-9
                && a.minY() >= b.minY() - 1e-9
                && a.maxY() <= b.maxY() + 1e-9;
    }

    /** The point of a line or arc nearest p. */
    static Vec2 closest(Curve2 c, Vec2 p) {
        if (c instanceof Segment2 s) {
            Vec2 d = s.end().minus(s.start());
            double l2 = d.dot(d);
            double u = l2 == 0 ? 0 : Math.max(0, Math.min(1, p.minus(s.start()).dot(d) / l2));
            return s.start().plus(d.times(u));
        }
        Arc2 a = (Arc2) c;
        Vec2 d = p.minus(a.center());
        if (d.norm() > 0 && a.containsAngle(d.angleRad())) {
            return a.center().plus(d.times(a.radius() / d.norm()));
        }
        return p.distance(a.start()) <= p.distance(a.end()) ? a.start() : a.end();
    }
}
