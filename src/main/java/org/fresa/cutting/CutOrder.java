package org.fresa.cutting;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.fresa.geom.Box2;
import org.fresa.geom.Vec2;

/**
 * The order of the pierces that keeps the rapid travel short under the shop's rule: every cut
 * inside a contour (the holes of a part, the parts inside a hole) comes before that contour's
 * own cut, so nothing falls out before it is cut.
 *
 * <p>Method: a nearest-neighbour tour from the machine origin over the cuts whose inner cuts
 * are all done (a hash grid of pierce points, so n cuts take about n log n), then 2-opt
 * (reversing a stretch of the order) and Or-opt (moving one cut) moves between near
 * neighbours, each kept only when it shortens the travel and keeps every inner cut before its
 * outer one, until none helps or the work budget is spent. The budget counts the moves looked
 * at, not the time, so the same drawing gets the same order on a quiet machine and a loaded one:
 * the program the Cutting tab shows is the one a run of the saved job writes. The travel from a cut to the next
 * is from its exit (end of the lead-out) to the next pierce. The result is never longer than
 * the nearest-neighbour tour.
 */
final class CutOrder {

    /** Nearest pierces looked at around each cut's exit. */
    private static final int NEIGHBOURS = 8;
    /** Longest stretch of the order a move may reverse or jump over: bounds the work of one move. */
    private static final int MAX_SPAN = 1000;

    private final Vec2[] pierce;
    private final Vec2[] exit;
    /** For each cut: the cuts that must come after it (the cuts of the contour around it). */
    private final int[][] after;
    /** For each cut: the cuts that must come before it (the cuts inside its contour). */
    private final int[][] before;

    private final int n;
    /** Moves looked at so far (a rapid compared each), the measure of the work budget. */
    private long work;

    /**
     * @param pierce each cut's pierce point
     * @param exit each cut's exit point
     * @param before for each cut, the cuts that must be done before it
     */
    CutOrder(List<Vec2> pierce, List<Vec2> exit, List<int[]> before) {
        this.n = pierce.size();
        this.pierce = pierce.toArray(new Vec2[0]);
        this.exit = exit.toArray(new Vec2[0]);
        this.before = before.toArray(new int[0][]);
        List<List<Integer>> a = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            a.add(new ArrayList<>(1));
        }
        for (int i = 0; i < n; i++) {
            for (int b : this.before[i]) {
                a.get(b).add(i);
            }
        }
        this.after = new int[n][];
        for (int i = 0; i < n; i++) {
            this.after[i] = a.get(i).stream().mapToInt(Integer::intValue).toArray();
        }
    }

    /** The rapid travel of an order from the origin, straight lines. */
    double travel(int[] seq) {
        double d = 0;
        Vec2 at = Vec2.ZERO;
        for (int c : seq) {
            d += at.distance(pierce[c]);
            at = exit[c];
        }
        return d;
    }

    /** The nearest-neighbour tour from the origin over the cuts whose inner cuts are done. */
    int[] nearestNeighbour() {
        int[] waiting = new int[n];
        for (int i = 0; i < n; i++) {
            waiting[i] = before[i].length;
        }
        PointGrid grid = new PointGrid(pierce);
        for (int i = 0; i < n; i++) {
            if (waiting[i] == 0) {
                grid.add(i);
            }
        }
        int[] seq = new int[n];
        Vec2 at = Vec2.ZERO;
        for (int k = 0; k < n; k++) {
            int c = grid.takeNearest(at);
            seq[k] = c;
            at = exit[c];
            for (int o : after[c]) {
                if (--waiting[o] == 0) {
                    grid.add(o);
                }
            }
        }
        return seq;
    }

    /** Cuts up to this many are ordered by trying every order the rule allows. */
    static final int EXACT_MAX = 8;

    /** The shortest order the rule allows, by trying them all; only for up to {@link #EXACT_MAX} cuts. */
    int[] exact() {
        if (n > EXACT_MAX) {
            throw new IllegalArgumentException(n + " cuts are too many to try every order");
        }
        int[] best = nearestNeighbour();
        double[] bestLen = {travel(best)};
        int[] cur = new int[n];
        boolean[] done = new boolean[n];
        search(cur, 0, done, -1, 0, best, bestLen);
        return best;
    }

    private void search(int[] cur, int k, boolean[] done, int last, double len, int[] best, double[] bestLen) {
        if (len >= bestLen[0] - 1e-9) {
            return;
        }
        if (k == n) {
            System.arraycopy(cur, 0, best, 0, n);
            bestLen[0] = len;
            return;
        }
        for (int c = 0; c < n; c++) {
            if (done[c] || !ready(c, done)) {
                continue;
            }
            done[c] = true;
            cur[k] = c;
            search(cur, k + 1, done, c, len + d(last, c), best, bestLen);
            done[c] = false;
        }
    }

    private boolean ready(int c, boolean[] done) {
        for (int b : before[c]) {
            if (!done[b]) {
                return false;
            }
        }
        return true;
    }

    /**
     * The tour improved by 2-opt and Or-opt moves until none helps or about {@code maxWork} moves
     * were looked at; never longer than the input.
     */
    int[] improve(int[] start, long maxWork) {
        long limit = work + maxWork;
        int[] seq = start.clone();
        int[] pos = new int[n];
        for (int k = 0; k < n; k++) {
            pos[seq[k]] = k;
        }
        int[][] near = neighbours();
        boolean improved = true;
        while (improved && work < limit) {
            improved = false;
            for (int k = 0; k < n && work < limit; k++) {
                work++;
                if (twoOpt(seq, pos, k, near) || orOpt(seq, pos, seq[k], near)) {
                    improved = true;
                }
            }
        }
        return travel(seq) <= travel(start) ? seq : start;
    }

    /** The moves looked at by this order's improvements so far. */
    long work() {
        return work;
    }

    private double d(int from, int to) {
        Vec2 a = from < 0 ? Vec2.ZERO : exit[from];
        return to < 0 || to >= n ? 0 : a.distance(pierce[to]);
    }

    /** The cut at position k, -1 before the first (the origin), n after the last (nothing). */
    private int at(int[] seq, int k) {
        return k < 0 ? -1 : k >= n ? n : seq[k];
    }

    /**
     * Reverses seq[i..j] when the rapid from seq[i - 1] to a near pierce seq[j] shortens the
     * travel: edges (i - 1, i) and (j, j + 1) become (i - 1, j) and (i, j + 1).
     */
    private boolean twoOpt(int[] seq, int[] pos, int i, int[][] near) {
        if (i == 0) {
            return false;
        }
        int a = seq[i - 1];
        for (int c : near[a]) {
            int j = pos[c];
            if (j <= i || j - i > MAX_SPAN) {
                continue;
            }
            work += j - i;
            double delta = d(a, seq[j]) + d(seq[i], at(seq, j + 1)) - d(a, seq[i]) - d(seq[j], at(seq, j + 1));
            for (int k = i; k < j; k++) {
                delta += d(seq[k + 1], seq[k]) - d(seq[k], seq[k + 1]);
            }
            if (delta < -1e-9 && reversible(seq, pos, i, j)) {
                for (int x = i, y = j; x < y; x++, y--) {
                    int t = seq[x];
                    seq[x] = seq[y];
                    seq[y] = t;
                    pos[seq[x]] = x;
                    pos[seq[y]] = y;
                }
                return true;
            }
        }
        return false;
    }

    /** A stretch may be reversed when it holds no cut together with one that must follow it. */
    private boolean reversible(int[] seq, int[] pos, int i, int j) {
        for (int k = i; k <= j; k++) {
            for (int o : after[seq[k]]) {
                if (pos[o] <= j) {
                    return false;
                }
            }
        }
        return true;
    }

    /** Moves cut c next to one of its near neighbours when that shortens the travel. */
    private boolean orOpt(int[] seq, int[] pos, int c, int[][] near) {
        int p = pos[c];
        int prev = at(seq, p - 1);
        int next = at(seq, p + 1);
        double gain = d(prev, c) + d(c, next) - d(prev, next);
        if (gain <= 1e-9) {
            return false;
        }
        int earliest = -1; // c must stay after every cut inside it
        for (int b : before[c]) {
            earliest = Math.max(earliest, pos[b]);
        }
        int latest = n; // and before the cut around it
        for (int o : after[c]) {
            latest = Math.min(latest, pos[o]);
        }
        for (int m : near[c]) {
            int q0 = pos[m];
            // insert between positions q and q + 1 (positions as they are before the move)
            work++;
            for (int q : new int[] {q0 - 1, q0}) {
                if (q == p || q == p - 1 || Math.abs(q - p) > MAX_SPAN || q < earliest || q + 1 > latest) {
                    continue;
                }
                int x = at(seq, q);
                int y = at(seq, q + 1);
                double cost = d(x, c) + d(c, y) - d(x, y);
                if (cost < gain - 1e-9) {
                    move(seq, pos, p, q);
                    return true;
                }
            }
        }
        return false;
    }

    /** Moves the cut at position p to just after position q (q as before the move). */
    private static void move(int[] seq, int[] pos, int p, int q) {
        int c = seq[p];
        if (q > p) {
            System.arraycopy(seq, p + 1, seq, p, q - p);
            seq[q] = c;
            for (int k = p; k <= q; k++) {
                pos[seq[k]] = k;
            }
        } else {
            System.arraycopy(seq, q + 1, seq, q + 2, p - q - 1);
            seq[q + 1] = c;
            for (int k = q + 1; k <= p; k++) {
                pos[seq[k]] = k;
            }
        }
    }

    /** For each cut, the cuts whose pierces are nearest its exit (the origin's: index -1 is not kept). */
    private int[][] neighbours() {
        PointGrid grid = new PointGrid(pierce);
        for (int i = 0; i < n; i++) {
            grid.add(i);
        }
        int[][] out = new int[n][];
        for (int i = 0; i < n; i++) {
            out[i] = grid.nearest(exit[i], NEIGHBOURS + 1, i);
        }
        return out;
    }

    /** Points in square cells; removal by swapping with the cell's last entry. */
    static final class PointGrid {
        private final Vec2[] pts;
        private final double cell;
        private final double minX;
        private final double minY;
        /**
         * The points of each cell (x * rows + y) and how many: dense, since the cells are about
         * as many as the points (at most the points plus 8 193). A hash map keyed by (x, y) packed
         * in a long hashed every cell of a row onto x ^ y and was a fifth of the ordering's time
         * on the 50 MB sheet.
         */
        private final int[][] cells;

        private final int[] counts;
        private int size;
        private final int cols;
        private final int rows;

        PointGrid(Vec2[] pts) {
            this.pts = pts;
            Box2 box = pts.length == 0 ? new Box2(0, 0, 0, 0) : Box2.around(Arrays.asList(pts));
            double w = Math.max(box.maxX() - box.minX(), 1e-6);
            double h = Math.max(box.maxY() - box.minY(), 1e-6);
            this.cell = Math.max(Math.sqrt(w * h / Math.max(1, pts.length)) * 1.5, Math.max(w, h) / 4096);
            this.minX = box.minX();
            this.minY = box.minY();
            this.cols = (int) Math.min(1 << 20, Math.floor(w / cell) + 1);
            this.rows = (int) Math.min(1 << 20, Math.floor(h / cell) + 1);
            this.cells = new int[Math.toIntExact((long) cols * rows)][];
            this.counts = new int[cells.length];
        }

        private int cx(double x) {
            return (int) Math.max(0, Math.min(cols - 1, Math.floor((x - minX) / cell)));
        }

        private int cy(double y) {
            return (int) Math.max(0, Math.min(rows - 1, Math.floor((y - minY) / cell)));
        }

        private int key(int x, int y) {
            return x * rows + y;
        }

        void add(int i) {
            int k = key(cx(pts[i].x()), cy(pts[i].y()));
            int[] l = cells[k];
            int c = counts[k];
            if (l == null || c == l.length) {
                l = l == null ? new int[2] : Arrays.copyOf(l, l.length * 2);
                cells[k] = l;
            }
            l[c] = i;
            counts[k] = c + 1;
            size++;
        }

        /** Removes and returns the point nearest p; the grid must not be empty. */
        int takeNearest(Vec2 p) {
            int[] best = nearestIn(p, 1, -1);
            int i = best[0];
            int k = key(cx(pts[i].x()), cy(pts[i].y()));
            int[] l = cells[k];
            int c = counts[k];
            for (int j = 0; j < c; j++) {
                if (l[j] == i) {
                    l[j] = l[c - 1];
                    break;
                }
            }
            counts[k] = c - 1;
            size--;
            return i;
        }

        /** The up to m points nearest p, nearest first, leaving out index skip (which is in the grid). */
        int[] nearest(Vec2 p, int m, int skip) {
            return nearestIn(p, m, skip);
        }

        private int[] nearestIn(Vec2 p, int m, int skip) {
            int px = cx(p.x());
            int py = cy(p.y());
            int[] idx = new int[m];
            double[] dist = new double[m];
            Arrays.fill(dist, Double.POSITIVE_INFINITY);
            int found = 0;
            int maxRing = Math.max(cols, rows);
            int available = size - (skip >= 0 ? 1 : 0);
            for (int ring = 0; ring <= maxRing && available > 0; ring++) {
                // a point in this ring or beyond is at least (ring - 1) cells from p
                double reach = (ring - 1) * cell;
                if ((found == m || found == available) && reach > dist[found - 1]) {
                    break;
                }
                for (int x = px - ring; x <= px + ring; x++) {
                    if (x < 0 || x >= cols) {
                        continue;
                    }
                    boolean edgeX = x == px - ring || x == px + ring;
                    for (int y = py - ring; y <= py + ring; y += edgeX ? 1 : 2 * ring) {
                        if (y >= 0 && y < rows) {
                            int k = key(x, y);
                            int[] l = cells[k];
                            if (l != null) {
                                int c = counts[k];
                                for (int j = 0; j < c; j++) {
                                    int i = l[j];
                                    if (i == skip) {
                                        continue;
                                    }
                                    double dd = pts[i].distance(p);
                                    if (found < m || dd < dist[m - 1]) {
                                        int at = Math.min(found, m - 1);
                                        while (at > 0 && dist[at - 1] > dd) {
                                            dist[at] = dist[at - 1];
                                            idx[at] = idx[at - 1];
                                            at--;
                                        }
                                        dist[at] = dd;
                                        idx[at] = i;
                                        found = Math.min(m, found + 1);
                                    }
                                }
                            }
                        }
                        if (ring == 0) {
                            break;
                        }
                    }
                }
            }
            return Arrays.copyOf(idx, found);
        }
    }
}
