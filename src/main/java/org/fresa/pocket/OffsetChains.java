package org.fresa.pocket;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;

/**
 * Chains directed pieces end to start into closed loops; pieces that do not close a loop are
 * dropped. Each loop's joints are snapped so a piece starts exactly where the previous ends.
 */
final class OffsetChains {
    private OffsetChains() {}

    /**
     * The closed loops of an offset's kept pieces, without the loops of negligible area, largest
     * area first.
     *
     * @param kept the pieces of the raw offset that lie far enough from the input
     * @param tol the caller's tolerance (loops of area below tol.linear() squared are dropped)
     * @param scale the drawing's size, at least 1: sets the chaining and area thresholds
     */
    static List<Contour> closedLoops(List<Curve2> kept, Tolerance tol, double scale) {
        List<Contour> loops = loops(kept, Math.max(1e-5, 1e-8 * scale));
        List<Contour> out = new ArrayList<>();
        for (Contour c : loops) {
            if (c.area() > Math.max(tol.linear() * tol.linear(), 1e-12 * scale * scale)) {
                out.add(c);
            }
        }
        out.sort(Comparator.comparingDouble(Contour::area).reversed());
        return out;
    }

    static List<Contour> loops(List<Curve2> pieces, double tol) {
        int n = pieces.size();
        double cell = Math.max(tol * 4, 1e-12);
        Map<Long, List<Integer>> byStart = new HashMap<>();
        for (int i = 0; i < n; i++) {
            Vec2 s = pieces.get(i).start();
            byStart.computeIfAbsent(key(s, cell), k -> new ArrayList<>()).add(i);
        }
        boolean[] used = new boolean[n];
        List<Contour> out = new ArrayList<>();
        for (int first = 0; first < n; first++) {
            if (used[first]) {
                continue;
            }
            List<Integer> chain = new ArrayList<>();
            chain.add(first);
            used[first] = true;
            Vec2 start = pieces.get(first).start();
            Vec2 at = pieces.get(first).end();
            // one piece closes a loop only when it is a whole circle: a tiny join arc also starts near its end
            boolean closed = pieces.get(first) instanceof Arc2 a0 && a0.isFullCircle();
            while (!closed) {
                int next = nearestStart(at, byStart, pieces, used, cell, tol);
                if (next < 0) {
                    break;
                }
                used[next] = true;
                chain.add(next);
                at = pieces.get(next).end();
                closed = at.distance(start) <= tol;
                if (!closed
                        && chain.size() > 1
                        && at.distance(start) <= tol * 100
                        && nearestStart(at, byStart, pieces, used, cell, tol) < 0) {
                    closed = true;
                }
            }
            if (closed) {
                out.add(snapped(chain, pieces));
            }
        }
        return out;
    }

    private static int nearestStart(
            Vec2 p, Map<Long, List<Integer>> byStart, List<Curve2> pieces, boolean[] used, double cell, double tol) {
        long cx = (long) Math.floor(p.x() / cell);
        long cy = (long) Math.floor(p.y() / cell);
        int best = -1;
        double bestD = tol;
        for (long dx = -1; dx <= 1; dx++) {
            for (long dy = -1; dy <= 1; dy++) {
                List<Integer> l = byStart.get(pack(cx + dx, cy + dy));
                if (l == null) {
                    continue;
                }
                for (int i : l) {
                    if (used[i]) {
                        continue;
                    }
                    double d = pieces.get(i).start().distance(p);
                    if (d <= bestD) {
                        bestD = d;
                        best = i;
                    }
                }
            }
        }
        return best;
    }

    private static long key(Vec2 p, double cell) {
        return pack((long) Math.floor(p.x() / cell), (long) Math.floor(p.y() / cell));
    }

    private static long pack(long x, long y) {
        return x * 0x9E3779B97F4A7C15L + y;
    }

    private static Contour snapped(List<Integer> chain, List<Curve2> pieces) {
        List<Curve2> out = new ArrayList<>(chain.size());
        int n = chain.size();
        for (int k = 0; k < n; k++) {
            Curve2 c = pieces.get(chain.get(k));
            Vec2 end = pieces.get(chain.get((k + 1) % n)).start();
            if (c instanceof Segment2 s) {
                out.add(new Segment2(s.start(), end));
            } else {
                Arc2 a = (Arc2) c;
                Arc2 moved = new Arc2(a.center(), a.start(), end, a.ccw());
                // a snap that moves a short arc's end behind its start would turn it into a whole circle
                if (n > 1 && Math.abs(moved.sweepRad() - a.sweepRad()) > 1) {
                    out.add(new Segment2(a.start(), end));
                } else {
                    out.add(moved);
                }
            }
        }
        return new Contour(out);
    }
}
