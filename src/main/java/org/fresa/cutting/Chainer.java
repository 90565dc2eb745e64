package org.fresa.cutting;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;

/**
 * Joins an unordered heap of lines and arcs into closed contours and open chains.
 *
 * <p>Default: zero-length elements and duplicates (the same element drawn twice, either way
 * round) are removed and counted; chains grow from both ends, each step taking the nearest free
 * end within the gap tolerance from a hash grid of end points, so n elements take about n
 * steps. A node where more than two ends meet is counted as a junction. Joints are snapped so
 * each element starts exactly where the previous one ends.
 *
 * <p>Paper mode (Marques et al. 2010, section 2.2): circles are contours; every other chain
 * grows one way only from its seed's end, scanning the remaining elements in file order (first
 * match wins), so an open chain stored out of order comes out in fragments.
 */
public final class Chainer {

    /**
     * The result.
     *
     * @param closed closed contours, snapped
     * @param open open chains in order of travel
     * @param duplicates elements removed as repeats of another
     * @param zeroLength elements removed for a length within the tolerance
     * @param junctions nodes where more than two element ends meet
     */
    public record Chains(List<Contour> closed, List<List<Curve2>> open, int duplicates, int zeroLength, int junctions) {
        public Chains {
            closed = List.copyOf(closed);
            open = open.stream().map(List::copyOf).toList();
        }
    }

    private Chainer() {
    }

    public static Chains chain(List<Curve2> curves, double tolMm) {
        double tol = Math.max(tolMm, 1e-9);
        List<Curve2> work = new ArrayList<>(curves.size());
        int zero = 0;
        for (Curve2 c : curves) {
            if (c instanceof Arc2 a && a.isFullCircle() ? a.radius() <= tol : c.start().distance(c.end()) <= tol
                    && !(c instanceof Arc2 a2 && Math.abs(a2.sweepRad()) > Math.PI)) {
                zero++;
            } else {
                work.add(c);
            }
        }
        int before = work.size();
        work = withoutDuplicates(work, tol);
        int dups = before - work.size();

        List<Contour> closed = new ArrayList<>();
        List<List<Curve2>> open = new ArrayList<>();
        int n = work.size();
        boolean[] used = new boolean[n];
        EndIndex index = new EndIndex(tol);
        for (int i = 0; i < n; i++) {
            Curve2 c = work.get(i);
            if (isClosedAlone(c, tol)) {
                used[i] = true;
                closed.add(new Contour(List.of(closeArc(c))));
                continue;
            }
            index.add(c.start(), i, false);
            index.add(c.end(), i, true);
        }
        int[] junctions = {0};
        for (int i = 0; i < n; i++) {
            if (used[i]) {
                continue;
            }
            used[i] = true;
            Deque<Curve2> chain = new ArrayDeque<>();
            chain.add(work.get(i));
            boolean isClosed = false;
            // forward
            while (true) {
                Vec2 at = chain.getLast().end();
                if (chain.size() > 1 && at.distance(chain.getFirst().start()) <= tol) {
                    isClosed = true;
                    break;
                }
                Curve2 next = index.take(at, work, used, junctions);
                if (next == null) {
                    break;
                }
                chain.addLast(next);
            }
            if (!isClosed) {
                while (true) {
                    Vec2 at = chain.getFirst().start();
                    Curve2 prev = index.take(at, work, used, junctions);
                    if (prev == null) {
                        break;
                    }
                    chain.addFirst(prev.reversed());
                    if (chain.getFirst().start().distance(chain.getLast().end()) <= tol) {
                        isClosed = true;
                        break;
                    }
                }
            }
            List<Curve2> list = new ArrayList<>(chain);
            if (isClosed) {
                closed.add(new Contour(snap(list, true)));
            } else {
                open.add(snap(list, false));
            }
        }
        return new Chains(closed, open, dups, zero, junctions[0]);
    }

    /** The paper's one-way chaining: first match in file order wins, tolerance as given (1e-4 mm). */
    public static Chains chainPaper(List<Curve2> curves, double tolMm) {
        // zero-length elements have no direction (the paper's method takes NaN there): left out and counted
        List<Curve2> atemp = new ArrayList<>();
        int zero = 0;
        for (Curve2 c : curves) {
            if (c.length() <= 1e-9 || (c instanceof Arc2 a && a.radius() <= 1e-9)) {
                zero++;
            } else {
                atemp.add(c);
            }
        }
        List<Contour> closed = new ArrayList<>();
        List<List<Curve2>> open = new ArrayList<>();
        while (!atemp.isEmpty()) {
            Curve2 e = atemp.remove(0);
            if (e instanceof Arc2 a && a.isFullCircle()) {
                closed.add(new Contour(List.of(e)));
                continue;
            }
            Vec2 pin = e.start();
            List<Curve2> cj = new ArrayList<>();
            cj.add(e);
            Vec2 pat = e.end();
            boolean isClosed = false;
            boolean found = true;
            while (found) {
                found = false;
                if (pat.distance(pin) <= tolMm) {
                    isClosed = true;
                    break;
                }
                for (int i = 0; i < atemp.size(); i++) {
                    Curve2 f = atemp.get(i);
                    if (pat.distance(f.start()) <= tolMm) {
                        cj.add(f);
                        pat = f.end();
                    } else if (pat.distance(f.end()) <= tolMm) {
                        cj.add(f.reversed());
                        pat = f.start();
                    } else {
                        continue;
                    }
                    atemp.remove(i);
                    found = true;
                    break;
                }
            }
            if (isClosed) {
                closed.add(new Contour(snap(cj, true)));
            } else {
                open.add(cj);
            }
        }
        return new Chains(closed, open, 0, zero, 0);
    }

    private static boolean isClosedAlone(Curve2 c, double tol) {
        return c instanceof Arc2 a && (a.isFullCircle() || (a.start().distance(a.end()) <= tol
                && Math.abs(a.sweepRad()) > Math.PI));
    }

    private static Curve2 closeArc(Curve2 c) {
        Arc2 a = (Arc2) c;
        return a.isFullCircle() ? a : new Arc2(a.center(), a.start(), a.start(), a.ccw());
    }

    /** Each element made to start exactly where the previous ends (cyclically when closed). */
    static List<Curve2> snap(List<Curve2> list, boolean closed) {
        List<Curve2> out = new ArrayList<>(list);
        for (int k = 1; k < out.size(); k++) {
            out.set(k, withStart(out.get(k), out.get(k - 1).end()));
        }
        if (closed && out.size() > 1) {
            out.set(0, withStart(out.get(0), out.get(out.size() - 1).end()));
        }
        return out;
    }

    private static Curve2 withStart(Curve2 c, Vec2 s) {
        if (c.start().equals(s)) {
            return c;
        }
        if (c instanceof Segment2 seg) {
            return new Segment2(s, seg.end());
        }
        Arc2 a = (Arc2) c;
        return new Arc2(a.center(), s, a.end(), a.ccw());
    }

    private static List<Curve2> withoutDuplicates(List<Curve2> in, double tol) {
        double cell = Math.max(tol * 4, 1e-6);
        Map<Long, List<Integer>> byMid = new HashMap<>();
        List<Curve2> out = new ArrayList<>(in.size());
        for (Curve2 c : in) {
            Vec2 m = c.pointAt(0.5);
            long cx = (long) Math.floor(m.x() / cell);
            long cy = (long) Math.floor(m.y() / cell);
            boolean dup = false;
            for (long dx = -1; dx <= 1 && !dup; dx++) {
                for (long dy = -1; dy <= 1 && !dup; dy++) {
                    List<Integer> l = byMid.get(pack(cx + dx, cy + dy));
                    if (l != null) {
                        for (int j : l) {
                            if (same(out.get(j), c, tol)) {
                                dup = true;
                                break;
                            }
                        }
                    }
                }
            }
            if (!dup) {
                byMid.computeIfAbsent(pack(cx, cy), k -> new ArrayList<>()).add(out.size());
                out.add(c);
            }
        }
        return out;
    }

    private static boolean same(Curve2 a, Curve2 b, double tol) {
        if (a.getClass() != b.getClass() || !within(a.pointAt(0.5), b.pointAt(0.5), tol)) {
            return false;
        }
        boolean forward = within(a.start(), b.start(), tol) && within(a.end(), b.end(), tol);
        boolean backward = within(a.start(), b.end(), tol) && within(a.end(), b.start(), tol);
        return forward || backward;
    }

    /** |a - b| <= tol, without the square root (Math.hypot is slow and this is the hot test). */
    private static boolean within(Vec2 a, Vec2 b, double tol) {
        return distanceSquared(a, b) <= tol * tol;
    }

    private static double distanceSquared(Vec2 a, Vec2 b) {
        double dx = a.x() - b.x();
        double dy = a.y() - b.y();
        return dx * dx + dy * dy;
    }

    static long pack(long x, long y) {
        return x * 0x9E3779B97F4A7C15L ^ (y + 0x632BE59BD9B4E019L);
    }

    /** Element ends in a hash grid with cells of the gap tolerance. */
    private static final class EndIndex {
        private final double tol;
        private final double cell;
        private final Map<Long, List<long[]>> grid = new HashMap<>();

        EndIndex(double tol) {
            this.tol = tol;
            this.cell = Math.max(tol, 1e-9);
        }

        void add(Vec2 p, int index, boolean isEnd) {
            grid.computeIfAbsent(pack((long) Math.floor(p.x() / cell), (long) Math.floor(p.y() / cell)),
                    k -> new ArrayList<>(2)).add(new long[] {index, isEnd ? 1 : 0});
        }

        /** The free element with an end nearest p within tol, oriented to start at p; null if none. */
        Curve2 take(Vec2 p, List<Curve2> work, boolean[] used, int[] junctions) {
            long cx = (long) Math.floor(p.x() / cell);
            long cy = (long) Math.floor(p.y() / cell);
            int best = -1;
            boolean bestEnd = false;
            double tol2 = tol * tol;
            double bestD = tol2;
            int candidates = 0;
            for (long dx = -1; dx <= 1; dx++) {
                for (long dy = -1; dy <= 1; dy++) {
                    List<long[]> l = grid.get(pack(cx + dx, cy + dy));
                    if (l == null) {
                        continue;
                    }
                    for (long[] e : l) {
                        int i = (int) e[0];
                        if (used[i]) {
                            continue;
                        }
                        Curve2 c = work.get(i);
                        double d = distanceSquared(e[1] == 1 ? c.end() : c.start(), p);
                        if (d <= tol2) {
                            candidates++;
                            if (d <= bestD) {
                                bestD = d;
                                best = i;
                                bestEnd = e[1] == 1;
                            }
                        }
                    }
                }
            }
            if (best < 0) {
                return null;
            }
            if (candidates > 1) {
                junctions[0]++;
            }
            used[best] = true;
            Curve2 c = work.get(best);
            return bestEnd ? c.reversed() : c;
        }
    }
}
