package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;

/**
 * The screen's thinning of a curve per pixel column: the polyline through the points kept covers,
 * column by column, the rows the full one covers, keeps its gaps, and draws a few points per
 * column instead of thousands.
 */
class ColumnThinningTest {

    @Test
    void everyColumnsEnvelopeAndEveryGapOfRandomCurvesStay() {
        Random random = new Random(20);
        for (int trial = 0; trial < 400; trial++) {
            int n = 1 + random.nextInt(3000);
            double pointsPerColumn = 0.3 + random.nextDouble() * 30;
            boolean forward = random.nextInt(4) > 0;
            double[] x = new double[n];
            double[] y = new double[n];
            double walk = 0;
            for (int i = 0; i < n; i++) {
                // a point number along the axis, or (one trial in four) a curve that turns back
                x[i] = forward ? 3.5 + i / pointsPerColumn : 200 + 150 * Math.sin(i / (7 * pointsPerColumn));
                walk += random.nextGaussian();
                // a spike now and then, and stretches without a value (unreachable targets)
                y[i] = random.nextInt(200) == 0 ? walk + 1e3 * random.nextGaussian() : walk;
            }
            int gaps = random.nextInt(6);
            for (int g = 0; g < gaps; g++) {
                int from = random.nextInt(n);
                int to = Math.min(n, from + 1 + random.nextInt(n / 4 + 1));
                for (int i = from; i < to; i++) {
                    if (random.nextBoolean() && g % 2 == 0) {
                        y[i] = Double.NaN;
                    } else if (g % 2 == 1) {
                        x[i] = Double.NaN;
                    } else {
                        y[i] = Double.NaN;
                    }
                }
            }
            boolean[] kept = ColumnThinning.keep(x, y);
            String what = "trial " + trial + ", " + n + " points";
            assertEquals(envelopes(x, y, all(n)), envelopes(x, y, kept), what);
            assertEquals(segments(x, y, all(n)), segments(x, y, kept), what);
            assertTrue(kept[0] && kept[n - 1], what);
        }
    }

    @Test
    void aSpikeOfOnePointAmongThousandsIsDrawn() {
        int n = 6518;
        double[] x = new double[n];
        double[] y = new double[n];
        for (int i = 0; i < n; i++) {
            // 6518 points over 400 columns, as the Position tab's error plot shows example 2
            x[i] = 40 + 400.0 * i / n;
            y[i] = 0.001 * Math.sin(i / 50.0);
        }
        y[3217] = 5;
        boolean[] kept = ColumnThinning.keep(x, y);
        assertTrue(kept[3217]);
        int count = 0;
        for (boolean k : kept) {
            count += k ? 1 : 0;
        }
        // first, lowest and highest with their neighbours, and last of each of the 400 columns, at most
        assertTrue(count <= 8 * 401 && count >= 2 * 400, "kept " + count);
    }

    @Test
    void aCurveWithNoValueKeepsOnePointPerGapAndItsEnds() {
        double[] x = {0, 1, 2, 3, 4};
        double[] y = {Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN};
        assertArrayEquals(new boolean[] {true, false, false, false, true}, ColumnThinning.keep(x, y));
        assertArrayEquals(new boolean[0], ColumnThinning.keep(new double[0], new double[0]));
        assertArrayEquals(new boolean[] {true}, ColumnThinning.keep(new double[] {0.5}, new double[] {2}));
        assertThrows(IllegalArgumentException.class, () -> ColumnThinning.keep(new double[2], new double[3]));
    }

    @Test
    void pointsInOneColumnKeepTheirFirstAndLastAndTheirExtremesWithTheirNeighbours() {
        double[] x = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.1};
        double[] y = {3, 5, 4, 1, 2, 3, 9, 4, 4, 0};
        boolean[] kept = ColumnThinning.keep(x, y);
        // first (0), lowest (3) and highest (6) with their neighbours, last (8); then the next column
        assertArrayEquals(new boolean[] {true, false, true, true, true, true, true, true, true, true}, kept);
        assertFalse(kept[1]);
    }

    private static boolean[] all(int n) {
        boolean[] b = new boolean[n];
        java.util.Arrays.fill(b, true);
        return b;
    }

    private static boolean valid(double[] x, double[] y, int i) {
        return !Double.isNaN(x[i]) && !Double.isNaN(y[i]);
    }

    /** Per pixel column, the lowest and highest value of the points drawn in it. */
    private static Map<Long, List<Double>> envelopes(double[] x, double[] y, boolean[] kept) {
        Map<Long, List<Double>> m = new TreeMap<>();
        for (int i = 0; i < x.length; i++) {
            if (kept[i] && valid(x, y, i)) {
                long c = (long) Math.floor(x[i]);
                List<Double> e = m.get(c);
                m.put(c, e == null ? List.of(y[i], y[i]) : List.of(Math.min(e.get(0), y[i]), Math.max(e.get(1), y[i])));
            }
        }
        return m;
    }

    /**
     * The drawn line's segments that leave a column, and its pieces between gaps: for each
     * segment of the polyline through the points kept, either its two ends (when they lie in two
     * columns) or the column it stays in, with the number of the piece it belongs to.
     */
    private static List<String> segments(double[] x, double[] y, boolean[] kept) {
        List<String> out = new ArrayList<>();
        int piece = 0;
        int last = -1;
        for (int i = 0; i < x.length; i++) {
            if (!kept[i]) {
                continue;
            }
            if (!valid(x, y, i)) {
                if (last >= 0) {
                    piece++;
                }
                last = -1;
                continue;
            }
            if (last >= 0) {
                long a = (long) Math.floor(x[last]);
                long b = (long) Math.floor(x[i]);
                if (a != b) {
                    out.add(piece + ": " + last + " -> " + i);
                } else if (out.isEmpty() || !out.get(out.size() - 1).equals(piece + ": in " + a)) {
                    out.add(piece + ": in " + a);
                }
            } else {
                out.add(piece + ": from " + i);
            }
            last = i;
        }
        return out;
    }
}
