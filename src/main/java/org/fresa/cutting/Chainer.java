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
 * steps. A node where more than two ends meet is counted as a junction. Then the open chains
 * left are joined end to end across gaps up to the gap tolerance, and each gap closed is
 * listed with its place and width. Joints are snapped so each element starts exactly where the
 * previous one ends, arcs keeping both ends on their circle.
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
     * @param gaps the gaps closed between open chains (wider than the joint tolerance)
     */
    public record Chains(
            List<Contour> closed,
            List<List<Curve2>> open,
            int duplicates,
            int zeroLength,
            int junctions,
            List<Gap> gaps) {
        public Chains {
            closed = List.copyOf(closed);
            open = open.stream().map(List::copyOf).toList();
            gaps = List.copyOf(gaps);
        }
    }

    /**
     * A gap closed while chaining.
     *
     * @param at the middle of the gap (mm)
     * @param widthMm the distance between the two ends joined
     */
    public record Gap(Vec2 at, double widthMm) {}

    private Chainer() {}

    /**
     * Chains at one tolerance: ends within {@code tolMm} are joined, elements shorter than it
     * dropped (as {@link #chain(List, double, double)} with both tolerances equal).
     */
    public static Chains chain(List<Curve2> curves, double tolMm) {
        return chain(curves, tolMm, tolMm);
    }

    /**
     * Chains in two steps: first the ends that meet within {@code jointMm} (the drawing's own
     * rounding; zero-length and duplicate elements are judged at this tolerance), then the open
     * chains left are joined end to end across gaps up to {@code gapMm}, nearest end first, and
     * each gap wider than {@code jointMm} that was closed is listed in {@link Chains#gaps()}.
     *
     * @param jointMm ends this close are the same point
     * @param gapMm widest gap closed between open chains (at least jointMm)
     */
    public static Chains chain(List<Curve2> curves, double jointMm, double gapMm) {
        double tol = Math.max(jointMm, 1e-9);
        double gap = Math.max(gapMm, tol);
        List<Curve2> work = new ArrayList<>(curves.size());
        int zero = 0;
        for (Curve2 c : curves) {
            if (c instanceof Arc2 a && a.isFullCircle()
                    ? a.radius() <= tol
                    : c.start().distance(c.end()) <= tol
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
            Grown g = grow(i, work, used, index, tol, junctions);
            List<Curve2> list = new ArrayList<>(g.links.size());
            for (long link : g.links) {
                Curve2 c = work.get((int) (link >> 1));
                list.add((link & 1) != 0 ? c.reversed() : c);
            }
            if (g.closed) {
                closed.add(new Contour(snap(list, true)));
            } else {
                open.add(list);
            }
        }
        List<Gap> gaps = new ArrayList<>();
        if (gap > tol && !open.isEmpty()) {
            open = joinAcrossGaps(open, tol, gap, closed, gaps, junctions);
        }
        List<List<Curve2>> snappedOpen = new ArrayList<>(open.size());
        for (List<Curve2> o : open) {
            snappedOpen.add(snap(o, false));
        }
        return new Chains(closed, snappedOpen, dups, zero, junctions[0], gaps);
    }

    /**
     * The second step: each open chain stands for a segment from its start to its end, and the
     * segments are chained as elements are, at the gap tolerance.
     */
    private static List<List<Curve2>> joinAcrossGaps(
            List<List<Curve2>> open, double tol, double gap, List<Contour> closed, List<Gap> gaps, int[] junctions) {
        List<Curve2> proxies = new ArrayList<>(open.size());
        for (List<Curve2> o : open) {
            proxies.add(new Segment2(o.get(0).start(), o.get(o.size() - 1).end()));
        }
        int n = proxies.size();
        boolean[] used = new boolean[n];
        EndIndex index = new EndIndex(gap);
        for (int i = 0; i < n; i++) {
            index.add(proxies.get(i).start(), i, false);
            index.add(proxies.get(i).end(), i, true);
        }
        List<List<Curve2>> stillOpen = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            if (used[i]) {
                continue;
            }
            Grown g = grow(i, proxies, used, index, gap, junctions);
            List<Curve2> list = new ArrayList<>();
            List<Gap> found = new ArrayList<>();
            for (long link : g.links) {
                List<Curve2> part = open.get((int) (link >> 1));
                if ((link & 1) != 0) {
                    for (int k = part.size() - 1; k >= 0; k--) {
                        list.add(part.get(k).reversed());
                    }
                } else {
                    list.addAll(part);
                }
                if (list.size() > part.size()) {
                    Vec2 a = list.get(list.size() - part.size() - 1).end();
                    Vec2 b = list.get(list.size() - part.size()).start();
                    gapBetween(a, b, tol, found);
                }
            }
            if (g.closed
                    || (g.links.size() == 1
                            && list.get(0)
                                            .start()
                                            .distance(list.get(list.size() - 1).end())
                                    <= gap
                            && list.size() > 1)) {
                gapBetween(list.get(list.size() - 1).end(), list.get(0).start(), tol, found);
                closed.add(new Contour(snap(list, true)));
                gaps.addAll(found);
            } else {
                stillOpen.add(list);
            }
        }
        return stillOpen;
    }

    private static void gapBetween(Vec2 a, Vec2 b, double tol, List<Gap> out) {
        double w = a.distance(b);
        if (w > tol) {
            out.add(new Gap(a.interpolate(b, 0.5), w));
        }
    }

    /** A chain grown from one element: links are index * 2 + (1 when reversed), in travel order. */
    private record Grown(Deque<Long> links, boolean closed) {}

    /** Grows a chain from element i both ways, each step taking the nearest free end within tol. */
    private static Grown grow(int i, List<Curve2> work, boolean[] used, EndIndex index, double tol, int[] junctions) {
        used[i] = true;
        Deque<Long> links = new ArrayDeque<>();
        links.add((long) i << 1);
        Vec2 first = work.get(i).start();
        Vec2 last = work.get(i).end();
        boolean isClosed = false;
        while (true) {
            if (links.size() > 1 && last.distance(first) <= tol) {
                isClosed = true;
                break;
            }
            long next = index.take(last, work, used, junctions);
            if (next < 0) {
                break;
            }
            links.addLast(next);
            Curve2 c = work.get((int) (next >> 1));
            last = (next & 1) != 0 ? c.start() : c.end();
        }
        if (!isClosed) {
            while (true) {
                long prev = index.take(first, work, used, junctions);
                if (prev < 0) {
                    break;
                }
                // the element found starts at the chain's first point: travelled the other way
                links.addFirst(prev ^ 1);
                Curve2 c = work.get((int) (prev >> 1));
                first = (prev & 1) != 0 ? c.start() : c.end();
                if (first.distance(last) <= tol) {
                    isClosed = true;
                    break;
                }
            }
        }
        return new Grown(links, isClosed);
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
        return new Chains(closed, open, 0, zero, 0, List.of());
    }

    private static boolean isClosedAlone(Curve2 c, double tol) {
        return c instanceof Arc2 a
                && (a.isFullCircle() || (a.start().distance(a.end()) <= tol && Math.abs(a.sweepRad()) > Math.PI));
    }

    private static Curve2 closeArc(Curve2 c) {
        Arc2 a = (Arc2) c;
        return a.isFullCircle() ? a : new Arc2(a.center(), a.start(), a.start(), a.ccw());
    }

    /**
     * Each element made to start exactly where the previous ends (cyclically when closed). A
     * joint between a line and an arc is put on the arc's end, so the arc stays exact and the
     * line moves; between two arcs it is the middle of their ends. An arc whose end moves keeps
     * its sweep and gets the centre of its new chord, so both ends stay on its circle.
     */
    static List<Curve2> snap(List<Curve2> list, boolean closed) {
        int n = list.size();
        if (n < 2) {
            return new ArrayList<>(list);
        }
        Vec2[] joint = new Vec2[n + 1]; // joint[k]: where element k starts; joint[n]: where the last ends
        for (int k = 1; k < n; k++) {
            joint[k] = jointOf(list.get(k - 1), list.get(k));
        }
        if (closed) {
            joint[0] = jointOf(list.get(n - 1), list.get(0));
            joint[n] = joint[0];
        } else {
            joint[0] = list.get(0).start();
            joint[n] = list.get(n - 1).end();
        }
        List<Curve2> out = new ArrayList<>(n);
        for (int k = 0; k < n; k++) {
            out.add(withEnds(list.get(k), joint[k], joint[k + 1]));
        }
        return out;
    }

    private static Vec2 jointOf(Curve2 before, Curve2 after) {
        Vec2 a = before.end();
        Vec2 b = after.start();
        if (a.equals(b)) {
            return a;
        }
        if (before instanceof Arc2 && after instanceof Segment2) {
            return a;
        }
        if (before instanceof Segment2 && after instanceof Arc2) {
            return b;
        }
        return before instanceof Arc2 ? a.interpolate(b, 0.5) : a;
    }

    private static Curve2 withEnds(Curve2 c, Vec2 s, Vec2 e) {
        if (c.start().equals(s) && c.end().equals(e)) {
            return c;
        }
        if (c instanceof Segment2) {
            return new Segment2(s, e);
        }
        Arc2 a = (Arc2) c;
        double sweep = a.sweepRad();
        if (s.equals(e) || Math.abs(sweep) > 2 * Math.PI - 1e-6) {
            return new Arc2(a.center(), s, e, a.ccw());
        }
        // the centre of the chord s-e seen under the same sweep:
        // mid + left normal * L (1 - b^2) / (4 b), b = tan(sweep / 4)
        double b = Math.tan(sweep / 4);
        Vec2 chord = e.minus(s);
        Vec2 centre = s.interpolate(e, 0.5).plus(chord.leftNormal().times((1 - b * b) / (4 * b)));
        return new Arc2(centre, s, e, a.ccw());
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
            grid.computeIfAbsent(
                            pack((long) Math.floor(p.x() / cell), (long) Math.floor(p.y() / cell)),
                            k -> new ArrayList<>(2))
                    .add(new long[] {index, isEnd ? 1 : 0});
        }

        /**
         * The free element with an end nearest p within tol, as a link that starts at p (index * 2,
         * plus 1 when the element must be reversed); -1 if none.
         */
        long take(Vec2 p, List<Curve2> work, boolean[] used, int[] junctions) {
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
                return -1;
            }
            if (candidates > 1) {
                junctions[0]++;
            }
            used[best] = true;
            return ((long) best << 1) | (bestEnd ? 1 : 0);
        }
    }
}
