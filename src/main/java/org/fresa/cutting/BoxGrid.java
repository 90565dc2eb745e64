package org.fresa.cutting;

import java.util.Arrays;
import org.fresa.geom.Box2;
import org.fresa.geom.Vec2;

/**
 * Boxes filed in square cells, added one by one, for "which boxes may hold this point" and
 * "which may a straight move cross": a move looks only at the cells along it, so routing a rapid
 * among n cut parts costs about its length in cells, not n.
 */
final class BoxGrid {
    /** A box covering more cells than this is kept aside and returned by every query. */
    private static final int MAX_CELLS = 1024;

    private final double cell;
    private final CellTable cells = new CellTable();
    private int[] big = new int[0];
    /** Per id, the query that last returned it (so an id is returned once per query). */
    private int[] stamp = new int[64];

    private int query;
    private int[] found = new int[64];
    private int nFound;

    BoxGrid(double cellMm) {
        this.cell = cellMm > 0 && Double.isFinite(cellMm) ? cellMm : 10;
    }

    private long cx(double x) {
        return (long) Math.floor(x / cell);
    }

    private static long key(long x, long y) {
        return Chainer.pack(x, y);
    }

    void add(int id, Box2 b) {
        if (id >= stamp.length) {
            stamp = Arrays.copyOf(stamp, Math.max(id + 1, stamp.length * 2));
        }
        long x0 = cx(b.minX());
        long x1 = cx(b.maxX());
        long y0 = cx(b.minY());
        long y1 = cx(b.maxY());
        if ((x1 - x0 + 1) * (y1 - y0 + 1) > MAX_CELLS) {
            big = Arrays.copyOf(big, big.length + 1);
            big[big.length - 1] = id;
            return;
        }
        for (long x = x0; x <= x1; x++) {
            for (long y = y0; y <= y1; y++) {
                long k = key(x, y);
                int[] l = cells.get(k);
                // slot 0 holds the count
                if (l == null) {
                    l = new int[4];
                    cells.put(k, l);
                } else if (l[0] + 1 == l.length) {
                    l = Arrays.copyOf(l, l.length * 2);
                    cells.put(k, l);
                }
                l[++l[0]] = id;
            }
        }
    }

    private void begin() {
        query++;
        nFound = 0;
        for (int id : big) {
            take(id);
        }
    }

    private void take(int id) {
        if (stamp[id] == query) {
            return;
        }
        stamp[id] = query;
        if (nFound == found.length) {
            found = Arrays.copyOf(found, found.length * 2);
        }
        found[nFound++] = id;
    }

    private void takeCell(long x, long y) {
        int[] l = cells.get(key(x, y));
        if (l != null) {
            for (int k = 1; k <= l[0]; k++) {
                take(l[k]);
            }
        }
    }

    private int[] done() {
        int[] out = Arrays.copyOf(found, nFound);
        Arrays.sort(out);
        return out;
    }

    /** The ids of the boxes that may hold a or b, ascending. */
    int[] at(Vec2 a, Vec2 b) {
        begin();
        takeCell(cx(a.x()), cx(a.y()));
        takeCell(cx(b.x()), cx(b.y()));
        return done();
    }

    /**
     * The ids of the boxes that may meet the segment a-b, ascending: the cells around points
     * at most half a cell apart along it (every cell the segment touches is next to the cell of
     * one of them).
     */
    int[] along(Vec2 a, Vec2 b) {
        begin();
        double len = a.distance(b);
        int steps = (int) Math.min(1 << 22, Math.ceil(len / (cell / 2)));
        long lastX = Long.MIN_VALUE;
        long lastY = Long.MIN_VALUE;
        for (int s = 0; s <= steps; s++) {
            double t = steps == 0 ? 0 : (double) s / steps;
            long x = cx(a.x() + (b.x() - a.x()) * t);
            long y = cx(a.y() + (b.y() - a.y()) * t);
            if (x == lastX && y == lastY) {
                continue;
            }
            lastX = x;
            lastY = y;
            for (long dx = -1; dx <= 1; dx++) {
                for (long dy = -1; dy <= 1; dy++) {
                    takeCell(x + dx, y + dy);
                }
            }
        }
        return done();
    }
}
