package org.fresa.cutting;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Vec2;

/**
 * Routes rapid moves around parts that are already cut free, as nesting CAM does ("avoid cut
 * parts" in the traverse): a freed part can tip up, and a head travelling over it can strike
 * it. Each cut part is an obstacle: the convex hull of its cut path (the tool centre, half a
 * kerf off the part), grown by a clearance. A rapid that would cross an obstacle goes instead
 * along the shortest path of the visibility graph over the vertices of the obstacles in its way
 * (found incrementally: the obstacles crossing the straight move first, then any the detour
 * meets).
 *
 * <p>Where no detour exists (the rapid starts or ends inside an obstacle's hull, e.g. in the
 * mouth of a C-shaped part; the obstacle is then tried without its clearance, then left out) the
 * rapid stays straight: the head passes over the part, which is what a machine without a torch
 * lift does anyway; such moves are counted by {@link #unavoidable()}.
 */
final class RapidRouter {
    private static final double EPS = 1e-7;
    private static final int MAX_ROUNDS = 12;

    /**
     * A convex obstacle: the cut path whose counter-clockwise hull it is, and the box of the hull
     * grown by the clearance. The hull is not kept but made again from the path when a rapid comes
     * near the part (the plan holds the path anyway): a sheet of 180 000 parts would hold a hundred
     * megabytes of hull points, when the rapids only ever meet a few thousand parts at a time.
     */
    private record Obstacle(Contour path, Box2 box) {}

    /** The raw and grown hulls of the obstacles used lately: rapids meet the same parts again and again. */
    private final Map<Integer, ConvexHull[]> recent = new java.util.LinkedHashMap<>(256, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Integer, ConvexHull[]> eldest) {
            return size() > 4096;
        }
    };

    private final double clearanceMm;
    /** The clearance's offsets in eight directions: the corners of an octagon round a hull vertex. */
    private final double[] growX = new double[8];

    private final double[] growY = new double[8];
    private final List<Obstacle> obstacles = new ArrayList<>();
    private final BoxGrid grid;
    private int unavoidable;

    /** @param clearanceMm how far a detour keeps from a cut part's path (mm) */
    RapidRouter(double clearanceMm) {
        this(clearanceMm, 10);
    }

    /**
     * @param clearanceMm how far a detour keeps from a cut part's path (mm)
     * @param cellMm the side of the cells in which the cut parts are filed: about a part's size
     */
    RapidRouter(double clearanceMm, double cellMm) {
        this.clearanceMm = clearanceMm;
        this.grid = new BoxGrid(cellMm);
        double r = clearanceMm / Math.cos(Math.PI / 8);
        for (int k = 0; k < 8; k++) {
            double ang = Math.PI / 8 + k * Math.PI / 4;
            growX[k] = Math.cos(ang) * r;
            growY[k] = Math.sin(ang) * r;
        }
    }

    /** Rapids that had to stay straight over a cut part. */
    int unavoidable() {
        return unavoidable;
    }

    /** Marks a part as cut free: its path becomes an obstacle for the following rapids. */
    void cutFree(Contour path) {
        ConvexHull[] h = hullsOf(path);
        if (h[0].size() < 3) {
            return;
        }
        Obstacle o = new Obstacle(path, h[1].box());
        obstacles.add(o);
        grid.add(obstacles.size() - 1, o.box);
        recent.put(obstacles.size() - 1, h);
    }

    private ConvexHull raw(int i) {
        return hulls(i)[0];
    }

    private ConvexHull grown(int i) {
        return hulls(i)[1];
    }

    private ConvexHull[] hulls(int i) {
        ConvexHull[] h = recent.get(i);
        if (h == null) {
            h = hullsOf(obstacles.get(i).path());
            recent.put(i, h);
        }
        return h;
    }

    /**
     * A path's counter-clockwise hull and that hull grown by the clearance (the same when there is
     * none): each hull vertex moved by the clearance in eight directions, whose hull holds the grown
     * part.
     */
    private ConvexHull[] hullsOf(Contour path) {
        ConvexHull raw = ConvexHull.ofPath(path);
        return new ConvexHull[] {raw, clearanceMm > 0 && raw.size() >= 3 ? raw.grown(growX, growY) : raw};
    }

    /** The rapid from a to b: a, any detour points, b. */
    List<Vec2> route(Vec2 a, Vec2 b) {
        // obstacles whose grown hull holds a or b are planned around without their clearance,
        // or left out (null) when even the raw hull holds one of them
        Map<Integer, ConvexHull> near = new HashMap<>();
        for (int i : grid.at(a, b)) {
            ConvexHull grown = grown(i);
            ConvexHull raw = raw(i);
            if (grown.inside(a) || grown.inside(b)) {
                if (raw.inside(a) || raw.inside(b)) {
                    if (raw.crosses(a, b)) {
                        unavoidable++;
                    }
                    near.put(i, null);
                } else {
                    near.put(i, raw);
                }
            }
        }
        List<Integer> active = new ArrayList<>();
        for (int i : grid.along(a, b)) {
            ConvexHull poly = poly(near, i);
            if (poly != null && poly.crosses(a, b)) {
                active.add(i);
            }
        }
        if (active.isEmpty()) {
            return List.of(a, b);
        }
        for (int round = 0; round < MAX_ROUNDS; round++) {
            List<ConvexHull> polys = new ArrayList<>(active.size());
            List<Box2> boxes = new ArrayList<>(active.size());
            for (int i : active) {
                ConvexHull poly = poly(near, i);
                polys.add(poly);
                boxes.add(near.containsKey(i) ? poly.box() : obstacles.get(i).box);
            }
            List<Vec2> path = shortest(a, b, polys, boxes);
            if (path == null) {
                break;
            }
            boolean clean = true;
            for (int k = 0; k + 1 < path.size(); k++) {
                for (int i : grid.along(path.get(k), path.get(k + 1))) {
                    ConvexHull poly = poly(near, i);
                    if (poly != null && !active.contains(i) && poly.crosses(path.get(k), path.get(k + 1))) {
                        active.add(i);
                        clean = false;
                    }
                }
            }
            if (clean) {
                // the detour must not pass over more cut parts (those it could not plan around
                // included) than the straight move does
                return badness(path) < badness(List.of(a, b)) ? path : List.of(a, b);
            }
        }
        unavoidable++;
        return List.of(a, b);
    }

    private ConvexHull poly(Map<Integer, ConvexHull> near, int i) {
        return near.containsKey(i) ? near.get(i) : grown(i);
    }

    /** Segments of the route crossing the raw hull of a cut part, counted per part. */
    private int badness(List<Vec2> route) {
        int n = 0;
        for (int k = 0; k + 1 < route.size(); k++) {
            for (int i : grid.along(route.get(k), route.get(k + 1))) {
                if (raw(i).crosses(route.get(k), route.get(k + 1))) {
                    n++;
                }
            }
        }
        return n;
    }

    /**
     * Dijkstra over a, b and the active obstacles' vertices; edges that cross no active obstacle.
     * The nodes are coordinate arrays (node k's neighbours on its hull by index, -1 for a and b):
     * each round tries every pair of nodes, and a point record per difference made the search a
     * third of the routing's time on the 50 MB sheet.
     */
    private static List<Vec2> shortest(Vec2 a, Vec2 b, List<ConvexHull> polys, List<Box2> boxes) {
        int n = 2;
        for (ConvexHull hull : polys) {
            n += hull.size();
        }
        double[] xs = new double[n];
        double[] ys = new double[n];
        int[] before = new int[n];
        int[] after = new int[n];
        xs[0] = a.x();
        ys[0] = a.y();
        xs[1] = b.x();
        ys[1] = b.y();
        before[0] = before[1] = after[0] = after[1] = -1;
        int at = 2;
        for (ConvexHull hull : polys) {
            int m = hull.size();
            for (int k = 0; k < m; k++) {
                xs[at + k] = hull.x(k);
                ys[at + k] = hull.y(k);
                before[at + k] = at + (k + m - 1) % m;
                after[at + k] = at + (k + 1) % m;
            }
            at += m;
        }
        double[] dist = new double[n];
        int[] prev = new int[n];
        boolean[] done = new boolean[n];
        Arrays.fill(dist, Double.POSITIVE_INFINITY);
        Arrays.fill(prev, -1);
        dist[0] = 0;
        PriorityQueue<double[]> queue = new PriorityQueue<>(Comparator.comparingDouble(e -> e[0]));
        queue.add(new double[] {0, 0});
        while (!queue.isEmpty()) {
            int u = (int) queue.poll()[1];
            if (done[u]) {
                continue;
            }
            done[u] = true;
            if (u == 1) {
                break;
            }
            double ux = xs[u];
            double uy = ys[u];
            for (int v = 1; v < n; v++) {
                if (done[v]) {
                    continue;
                }
                double vx = xs[v];
                double vy = ys[v];
                double d = dist[u] + Math.hypot(ux - vx, uy - vy);
                if (d >= dist[v]
                        || !supporting(xs, ys, u, vx, vy, before[u], after[u])
                        || !supporting(xs, ys, v, ux, uy, before[v], after[v])) {
                    continue;
                }
                boolean free = true;
                for (int i = 0; i < polys.size(); i++) {
                    if (boxHit(boxes.get(i), ux, uy, vx, vy) && polys.get(i).crosses(ux, uy, vx, vy)) {
                        free = false;
                        break;
                    }
                }
                if (free) {
                    dist[v] = d;
                    prev[v] = u;
                    queue.add(new double[] {d, v});
                }
            }
        }
        if (prev[1] < 0) {
            return null;
        }
        List<Vec2> path = new ArrayList<>();
        for (int v = 1; v >= 0; v = prev[v]) {
            path.add(0, v == 0 ? a : v == 1 ? b : new Vec2(xs[v], ys[v]));
        }
        return path;
    }

    /**
     * True when the line from hull vertex p towards q leaves both of p's neighbours on one side:
     * a shortest path among convex obstacles bends only along such lines (it wraps round the
     * obstacle at p), so the other edges need no test. Free ends (a, b) have no neighbours.
     */
    private static boolean supporting(double[] xs, double[] ys, int p, double qx, double qy, int before, int after) {
        if (before < 0) {
            return true;
        }
        double px = xs[p];
        double py = ys[p];
        double dx = qx - px;
        double dy = qy - py;
        double len = Math.hypot(dx, dy);
        if (len == 0) {
            return true;
        }
        double c1 = (dx * (ys[before] - py) - dy * (xs[before] - px)) / len;
        double c2 = (dx * (ys[after] - py) - dy * (xs[after] - px)) / len;
        return c1 >= -EPS && c2 >= -EPS || c1 <= EPS && c2 <= EPS;
    }

    private static boolean boxHit(Box2 box, double ax, double ay, double bx, double by) {
        return Math.max(ax, bx) >= box.minX()
                && Math.min(ax, bx) <= box.maxX()
                && Math.max(ay, by) >= box.minY()
                && Math.min(ay, by) <= box.maxY();
    }

    /** Andrew's monotone chain: the convex hull, counter-clockwise, without collinear points. */
    static Vec2[] hull(List<Vec2> points) {
        return ConvexHull.of(points).vertices();
    }
}
