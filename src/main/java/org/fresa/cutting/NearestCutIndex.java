package org.fresa.cutting;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.fresa.geom.Box2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;

/**
 * The cuts in a uniform grid, for "which cut that may be cut now is nearest this point": a cut
 * that may start anywhere on its path is filed under its path's elements (its distance is to the
 * nearest point of the path), one with a fixed pierce under that point. A query looks at rings of
 * cells around the point until no nearer cut can lie further out, so a nearest-neighbour tour over
 * n cuts takes about n log n on a drawing of parts of like size.
 */
final class NearestCutIndex {

    /** The elements filed under one cut: curves, or none (then its fixed point). */
    private final List<Curve2>[] curves;

    private final Vec2[] fixed;
    private final boolean[] open;
    private final double cell;
    private final double minX;
    private final double minY;
    private final int cols;
    private final int rows;
    /** Cell key to the cuts filed there (an element's cut once per cell it covers). */
    private final Map<Long, int[]> cells = new HashMap<>();

    private final Map<Long, Integer> counts = new HashMap<>();
    /** Cuts too large for the grid, looked at by every query. */
    private final List<Integer> big = new ArrayList<>();

    private final int[] stamp;
    private int query;

    /**
     * @param curves per cut, the path it may start anywhere on, or null for a fixed pierce
     * @param fixed per cut, the fixed pierce (used when curves is null)
     */
    @SuppressWarnings("unchecked")
    NearestCutIndex(List<List<Curve2>> curves, List<Vec2> fixed) {
        int n = fixed.size();
        @SuppressWarnings("unchecked")
        List<Curve2>[] byContour = (List<Curve2>[]) curves.toArray(new List<?>[0]);
        this.curves = byContour;
        this.fixed = fixed.toArray(new Vec2[0]);
        this.open = new boolean[n];
        this.stamp = new int[n];
        Box2 ext = null;
        int items = 0;
        for (int i = 0; i < n; i++) {
            Box2 b = box(i);
            ext = ext == null ? b : ext.union(b);
            items += this.curves[i] == null ? 1 : this.curves[i].size();
        }
        if (ext == null) {
            ext = new Box2(0, 0, 1, 1);
        }
        double w = Math.max(ext.width(), 1e-6);
        double h = Math.max(ext.height(), 1e-6);
        this.cell = Math.max(Math.sqrt(w * h / Math.max(1, items)) * 2, Math.max(w, h) / 4096);
        this.minX = ext.minX();
        this.minY = ext.minY();
        this.cols = (int) Math.floor(w / cell) + 1;
        this.rows = (int) Math.floor(h / cell) + 1;
        for (int i = 0; i < n; i++) {
            if (this.curves[i] == null) {
                file(i, Box2.of(this.fixed[i], this.fixed[i]), true);
            } else {
                boolean ok = true;
                for (Curve2 c : this.curves[i]) {
                    ok &= file(i, c.bounds(), false);
                }
                if (!ok) {
                    big.add(i);
                }
            }
        }
    }

    private Box2 box(int i) {
        if (curves[i] == null) {
            return Box2.of(fixed[i], fixed[i]);
        }
        Box2 b = null;
        for (Curve2 c : curves[i]) {
            b = b == null ? c.bounds() : b.union(c.bounds());
        }
        return b == null ? Box2.of(fixed[i], fixed[i]) : b;
    }

    private int cx(double x) {
        return (int) Math.max(0, Math.min(cols - 1, Math.floor((x - minX) / cell)));
    }

    private int cy(double y) {
        return (int) Math.max(0, Math.min(rows - 1, Math.floor((y - minY) / cell)));
    }

    private static long key(int x, int y) {
        return ((long) x << 32) | (y & 0xFFFFFFFFL);
    }

    /** Files cut i under the cells of box b; false when b covers too many cells (then it is not filed). */
    private boolean file(int i, Box2 b, boolean force) {
        int x0 = cx(b.minX());
        int x1 = cx(b.maxX());
        int y0 = cy(b.minY());
        int y1 = cy(b.maxY());
        if (!force && (long) (x1 - x0 + 1) * (y1 - y0 + 1) > 256) {
            return false;
        }
        for (int x = x0; x <= x1; x++) {
            for (int y = y0; y <= y1; y++) {
                long k = key(x, y);
                int[] l = cells.get(k);
                int c = counts.getOrDefault(k, 0);
                if (l == null || c == l.length) {
                    l = l == null ? new int[2] : Arrays.copyOf(l, l.length * 2);
                    cells.put(k, l);
                }
                l[c] = i;
                counts.put(k, c + 1);
            }
        }
        return true;
    }

    /** Cut i may be cut now. */
    void open(int i) {
        open[i] = true;
    }

    /** Cut i is done. */
    void close(int i) {
        open[i] = false;
    }

    /** The distance from p to cut i: to the nearest point of its path, or to its fixed pierce. */
    double distance(int i, Vec2 p) {
        if (curves[i] == null) {
            return fixed[i].distance(p);
        }
        double best = Double.POSITIVE_INFINITY;
        for (Curve2 c : curves[i]) {
            best = Math.min(best, c.distanceTo(p));
        }
        return best;
    }

    /** The open cut nearest p, or -1 when none is open. */
    int nearest(Vec2 p) {
        query++;
        int best = -1;
        double bestD = Double.POSITIVE_INFINITY;
        for (int i : big) {
            if (open[i]) {
                stamp[i] = query;
                double d = distance(i, p);
                if (d < bestD) {
                    bestD = d;
                    best = i;
                }
            }
        }
        int px = (int) Math.max(-(1 << 29), Math.min(1 << 29, Math.floor((p.x() - minX) / cell)));
        int py = (int) Math.max(-(1 << 29), Math.min(1 << 29, Math.floor((p.y() - minY) / cell)));
        // rings beyond this one hold no cell of the grid
        int maxRing = Math.max(
                Math.max(Math.abs(px), Math.abs(px - cols + 1)), Math.max(Math.abs(py), Math.abs(py - rows + 1)));
        // a point off the grid (the machine origin, say) starts at the nearest ring that touches it
        int gx = px < 0 ? -px : px >= cols ? px - cols + 1 : 0;
        int gy = py < 0 ? -py : py >= rows ? py - rows + 1 : 0;
        for (int ring = Math.max(gx, gy); ring <= maxRing; ring++) {
            // everything not yet seen is at least (ring - 1) cells away: p may lie anywhere in its cell
            if (best >= 0 && (ring - 1) * cell > bestD) {
                break;
            }
            for (int x = Math.max(0, px - ring); x <= Math.min(cols - 1, px + ring); x++) {
                boolean edgeX = x == px - ring || x == px + ring;
                for (int y = py - ring; y <= py + ring; y += edgeX || ring == 0 ? 1 : 2 * ring) {
                    if (y < 0 || y >= rows) {
                        continue;
                    }
                    long k = key(x, y);
                    int[] l = cells.get(k);
                    if (l == null) {
                        continue;
                    }
                    int c = counts.get(k);
                    for (int j = 0; j < c; j++) {
                        int i = l[j];
                        if (!open[i] || stamp[i] == query) {
                            continue;
                        }
                        stamp[i] = query;
                        double d = distance(i, p);
                        if (d < bestD || d == bestD && i < best) {
                            bestD = d;
                            best = i;
                        }
                    }
                }
            }
        }
        return best;
    }
}
