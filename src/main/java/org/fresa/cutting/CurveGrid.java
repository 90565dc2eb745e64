package org.fresa.cutting;

import java.util.List;
import org.fresa.geom.Box2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;

/**
 * Curves in a uniform grid of their boxes, for "is anything closer than d to p" questions. Each
 * cell holds its curves' indices in an int array (slot 0 the count): a sheet of 180 000 parts
 * files some two million of them, which as boxed lists would cost more than the curves.
 */
final class CurveGrid {
    private final List<Curve2> curves;
    private final double cell;
    private final CellTable cells = new CellTable();
    private final int[] stamp;
    private int query;

    CurveGrid(List<Curve2> curves, double cellMm) {
        this.curves = curves;
        this.cell = cellMm;
        this.stamp = new int[curves.size()];
        for (int i = 0; i < curves.size(); i++) {
            Box2 b = curves.get(i).bounds();
            long x0 = (long) Math.floor(b.minX() / cell);
            long x1 = (long) Math.floor(b.maxX() / cell);
            long y0 = (long) Math.floor(b.minY() / cell);
            long y1 = (long) Math.floor(b.maxY() / cell);
            if ((x1 - x0 + 1) * (y1 - y0 + 1) > 4096) {
                // a huge curve: file it under a coarse key checked by every query
                file(Long.MIN_VALUE, i);
                continue;
            }
            for (long x = x0; x <= x1; x++) {
                for (long y = y0; y <= y1; y++) {
                    file(Chainer.pack(x, y), i);
                }
            }
        }
    }

    private void file(long key, int i) {
        int[] l = cells.get(key);
        if (l == null) {
            l = new int[4];
            cells.put(key, l);
        } else if (l[0] + 1 == l.length) {
            l = java.util.Arrays.copyOf(l, l.length * 2);
            cells.put(key, l);
        }
        l[++l[0]] = i;
    }

    /** The distance from p to the nearest curve, if it is below limit; otherwise limit. */
    double distance(Vec2 p, double limit) {
        query++;
        double best = limit;
        long x0 = (long) Math.floor((p.x() - limit) / cell);
        long x1 = (long) Math.floor((p.x() + limit) / cell);
        long y0 = (long) Math.floor((p.y() - limit) / cell);
        long y1 = (long) Math.floor((p.y() + limit) / cell);
        int[] big = cells.get(Long.MIN_VALUE);
        if (big != null) {
            best = scan(big, p, best);
        }
        if ((x1 - x0 + 1) * (y1 - y0 + 1) > 10_000) {
            for (int i = 0; i < curves.size(); i++) {
                best = Math.min(best, curves.get(i).distanceTo(p));
            }
            return best;
        }
        for (long x = x0; x <= x1; x++) {
            for (long y = y0; y <= y1; y++) {
                int[] l = cells.get(Chainer.pack(x, y));
                if (l != null) {
                    best = scan(l, p, best);
                }
            }
        }
        return best;
    }

    private double scan(int[] l, Vec2 p, double best) {
        for (int k = 1; k <= l[0]; k++) {
            int i = l[k];
            if (stamp[i] == query) {
                continue;
            }
            stamp[i] = query;
            best = Math.min(best, curves.get(i).distanceTo(p));
        }
        return best;
    }
}
