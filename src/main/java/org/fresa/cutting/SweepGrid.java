package org.fresa.cutting;

import java.util.Arrays;
import java.util.function.IntPredicate;

/**
 * Boxes filed in a uniform grid, held as coordinate arrays: which boxes meet a given one. Fenced
 * fast path for the crossing test of a whole drawing (727 000 curves on the 50 MB sheet): the
 * cells of every box in two int arrays, no object per box or per cell. A box spanning more than
 * {@value #MOST_CELLS} cells (a long line across the sheet) is kept aside and tested against every
 * box instead.
 */
final class SweepGrid {
    private static final int MOST_CELLS = 64;
    private static final int MOST_ACROSS = 1024;

    private final double[] minX;
    private final double[] minY;
    private final double[] maxX;
    private final double[] maxY;
    private final double x0;
    private final double y0;
    private final double cellMm;
    private final int across;
    private final int down;
    /** Where the boxes of cell c start in {@link #items}; the cell's boxes end where the next one's start. */
    private final int[] start;

    private final int[] items;
    private final int[] big;
    private final int[] seen;
    private int stamp;

    SweepGrid(double[] minX, double[] minY, double[] maxX, double[] maxY) {
        this.minX = minX;
        this.minY = minY;
        this.maxX = maxX;
        this.maxY = maxY;
        int n = minX.length;
        double ax = Double.POSITIVE_INFINITY;
        double ay = Double.POSITIVE_INFINITY;
        double bx = Double.NEGATIVE_INFINITY;
        double by = Double.NEGATIVE_INFINITY;
        double sizes = 0;
        for (int i = 0; i < n; i++) {
            ax = Math.min(ax, minX[i]);
            ay = Math.min(ay, minY[i]);
            bx = Math.max(bx, maxX[i]);
            by = Math.max(by, maxY[i]);
            sizes += Math.max(maxX[i] - minX[i], maxY[i] - minY[i]);
        }
        if (n == 0) {
            ax = ay = bx = by = 0;
        }
        double extent = Math.max(bx - ax, by - ay);
        double cell = Math.max(sizes / Math.max(1, n), extent / MOST_ACROSS);
        this.cellMm = cell > 0 ? cell : 1;
        this.x0 = ax;
        this.y0 = ay;
        this.across = cellOf(bx, ax) + 1;
        this.down = cellOf(by, ay) + 1;
        int[] count = new int[across * down + 1];
        int bigs = 0;
        for (int i = 0; i < n; i++) {
            if (isBig(i)) {
                bigs++;
                continue;
            }
            for (int y = cellOf(minY[i], y0); y <= cellOf(maxY[i], y0); y++) {
                for (int x = cellOf(minX[i], x0); x <= cellOf(maxX[i], x0); x++) {
                    count[y * across + x + 1]++;
                }
            }
        }
        for (int c = 1; c < count.length; c++) {
            count[c] += count[c - 1];
        }
        this.start = count.clone();
        this.items = new int[count[count.length - 1]];
        this.big = new int[bigs];
        bigs = 0;
        for (int i = 0; i < n; i++) {
            if (isBig(i)) {
                big[bigs++] = i;
                continue;
            }
            for (int y = cellOf(minY[i], y0); y <= cellOf(maxY[i], y0); y++) {
                for (int x = cellOf(minX[i], x0); x <= cellOf(maxX[i], x0); x++) {
                    items[count[y * across + x]++] = i;
                }
            }
        }
        this.seen = new int[n];
    }

    private int cellOf(double v, double origin) {
        return (int) Math.floor((v - origin) / cellMm);
    }

    private boolean isBig(int i) {
        long w = cellOf(maxX[i], x0) - cellOf(minX[i], x0) + 1L;
        long h = cellOf(maxY[i], y0) - cellOf(minY[i], y0) + 1L;
        return w * h > MOST_CELLS;
    }

    /** True when box j meets box i, edges included ({@code Box2.intersects}). */
    private boolean meet(int i, int j) {
        return minX[j] <= maxX[i] && maxX[j] >= minX[i] && minY[j] <= maxY[i] && maxY[j] >= minY[i];
    }

    /** The other boxes that meet box i and pass the filter, each once, in no particular order. */
    int[] meeting(int i, IntPredicate filter) {
        stamp++;
        seen[i] = stamp;
        int[] out = new int[8];
        int k = 0;
        if (isBig(i)) {
            for (int j = 0; j < seen.length; j++) {
                if (seen[j] != stamp && meet(i, j) && filter.test(j)) {
                    seen[j] = stamp;
                    out = grow(out, k);
                    out[k++] = j;
                }
            }
            return Arrays.copyOf(out, k);
        }
        for (int y = cellOf(minY[i], y0); y <= cellOf(maxY[i], y0); y++) {
            for (int x = cellOf(minX[i], x0); x <= cellOf(maxX[i], x0); x++) {
                int c = y * across + x;
                for (int m = start[c]; m < start[c + 1]; m++) {
                    int j = items[m];
                    if (seen[j] != stamp) {
                        seen[j] = stamp;
                        if (meet(i, j) && filter.test(j)) {
                            out = grow(out, k);
                            out[k++] = j;
                        }
                    }
                }
            }
        }
        for (int j : big) {
            if (seen[j] != stamp) {
                seen[j] = stamp;
                if (meet(i, j) && filter.test(j)) {
                    out = grow(out, k);
                    out[k++] = j;
                }
            }
        }
        return Arrays.copyOf(out, k);
    }

    private static int[] grow(int[] a, int k) {
        return k < a.length ? a : Arrays.copyOf(a, 2 * a.length);
    }
}
