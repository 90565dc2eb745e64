package org.fresa.check;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.fresa.geom.Vec3;

/**
 * What is left of the stock as a program cuts it, seen from above: the height of the material's
 * top over a square grid of cells ({@link #CELL_MM}, the cell centres sampled), starting at the
 * stock's top inside its box and lowered under every feed move along +Z to the cutter's lower
 * envelope. It is what the {@link RapidRule} judges a rapid against: a rapid may go down into a
 * pocket the program has cleared, not into material it has not.
 *
 * <p>The model errs on the side of material: a feed move removes, between the ends of each piece
 * of at most {@link #DESCENT_PIECE_MM} of descent, only down to the piece's higher end (under
 * each end, down to that end); a drill's (or a
 * reamer's) point is taken as 118 degrees, so that a later tool going down into its hole finds
 * the cone's flanks; a ball or bull-nose cutter is taken as flat (what it leaves at its rim is
 * not modelled). Sections along another tool axis remove nothing here. The grid is sparse
 * (tiles of {@link #TILE} cells made where a cut reaches), so a stock unbounded beside the part
 * costs nothing. Units mm.
 */
final class Material {

    /** The grid's cell side (mm): the sideways resolution of the rapid rule. */
    static final double CELL_MM = 0.2;

    /**
     * How far from its axis a tool narrower than this is taken to cut and to meet material (mm):
     * three quarters of a cell, so that the axis always has a cell centre within it.
     */
    static final double AXIS_REACH_MM = 0.75 * CELL_MM;

    /** How far off a merged chord the skipped points of a level run may lie (mm). */
    static final double MERGE_MM = 0.02;

    /** The most a feed move descends in one piece of the removal (mm). */
    static final double DESCENT_PIECE_MM = 0.05;

    /** A drilling tool's point angle, as the standard twist drill's (deg). */
    static final double POINT_ANGLE_DEG = 118;

    /** Cells along a tile's side. */
    static final int TILE = 64;

    private static final double POINT_SLOPE = 1 / Math.tan(Math.toRadians(POINT_ANGLE_DEG / 2));

    private final Limits.Stock stock;
    private final Map<Long, float[]> tiles = new HashMap<>();
    private long lastKey;
    private float[] lastTile;

    private Material(Limits.Stock stock) {
        this.stock = stock;
    }

    /** The stock before any cut. */
    static Material of(Limits.Stock stock) {
        return new Material(stock);
    }

    /** Whether the stock states a top, below which material is: otherwise nothing is modelled. */
    boolean known() {
        return Double.isFinite(stock.maxZMm());
    }

    /** The stock's top before any cut (mm). */
    double stockTopZMm() {
        return stock.maxZMm();
    }

    /** Removes what the block's feed motion cuts with the tool in effect. */
    void cut(Step s, Limits limits) {
        if (!known() || !s.feedMove() || s.path().size() < 2 || !alongZ(s.axis())) {
            return;
        }
        ToolLimits t = limits.tool(s.tool());
        double slope = slope(t);
        List<Vec3> p = s.path();
        double r = t.radiusMm();
        int i = 1;
        while (i < p.size()) {
            Vec3 a = p.get(i - 1);
            Vec3 b = p.get(i);
            if (!Double.isFinite(a.x() + a.y() + a.z() + b.x() + b.y() + b.z())) {
                i++;
                continue;
            }
            if (a.z() == b.z()) {
                // a level run of an arc's chords is swept as fewer chords, each with the radius
                // less how far the points it skips lie off it, so that nothing more is removed
                int end = i;
                while (end + 1 < p.size() && p.get(end + 1).z() == a.z() && offChord(p, i - 1, end + 1) <= MERGE_MM) {
                    end++;
                }
                Vec3 e = p.get(end);
                lower(a, e, end == i ? r : Math.max(0, r - offChord(p, i - 1, end)), slope);
                i = end + 1;
                continue;
            }
            int pieces = (int) Math.min(10_000, Math.ceil(Math.abs(b.z() - a.z()) / DESCENT_PIECE_MM));
            pieces = Math.max(1, pieces);
            Vec3 from = a;
            lower(a, a, r, slope);
            for (int k = 1; k <= pieces; k++) {
                Vec3 to = k == pieces ? b : a.plus(b.minus(a).times((double) k / pieces));
                lower(from, to, r, slope);
                // where the tool stood, its disc is cut down to its own height exactly
                lower(to, to, r, slope);
                from = to;
            }
            i++;
        }
    }

    /** The farthest the points strictly between two of the path lie from the chord joining them (mm). */
    private static double offChord(List<Vec3> p, int from, int to) {
        Vec3 a = p.get(from);
        Vec3 b = p.get(to);
        double worst = 0;
        for (int k = from + 1; k < to; k++) {
            worst = Math.max(
                    worst, distanceToSegment(a, b, p.get(k).x(), p.get(k).y()));
        }
        return worst;
    }

    /**
     * The deepest the tool's bottom goes into the material along a straight move: the most the
     * material's top stands above the tool's bottom (flat, or a drill's point) under the tool's
     * disc (its radius less a cell, the grid's resolution), with the place; empty when the tool
     * stays above it.
     */
    java.util.Optional<Hit> deepest(Vec3 a, Vec3 b, double radiusMm, ToolLimits tool) {
        double slope = slope(tool);
        if (!known() || Math.min(a.z(), b.z()) >= stock.maxZMm()) {
            return java.util.Optional.empty();
        }
        // a tool of no stated radius is seen at its axis, over the cells its own cuts mark
        double r = Math.max(radiusMm - CELL_MM, AXIS_REACH_MM);
        Hit worst = null;
        double minX = Math.min(a.x(), b.x()) - r;
        double maxX = Math.max(a.x(), b.x()) + r;
        int j0 = index(Math.max(Math.min(a.y(), b.y()) - r, clampLow(stock.minYMm(), a.y(), b.y(), r)));
        int j1 = index(Math.min(Math.max(a.y(), b.y()) + r, clampHigh(stock.maxYMm(), a.y(), b.y(), r)));
        int i0 = index(Math.max(minX, clampLow(stock.minXMm(), a.x(), b.x(), r)));
        int i1 = index(Math.min(maxX, clampHigh(stock.maxXMm(), a.x(), b.x(), r)));
        for (int j = j0; j <= j1; j++) {
            double y = centre(j);
            for (int i = i0; i <= i1; i++) {
                double x = centre(i);
                double bottom = lowestOver(a, b, x, y, r);
                if (Double.isNaN(bottom)) {
                    continue;
                }
                // a drill's point stands higher off its axis (exact for a move along the axis)
                bottom += slope * distanceToSegment(a, b, x, y);
                double top = top(i, j, x, y);
                double depth = top - bottom;
                if (depth > 0 && (worst == null || depth > worst.depthMm())) {
                    worst = new Hit(new Vec3(x, y, bottom), top, depth);
                }
            }
        }
        return java.util.Optional.ofNullable(worst);
    }

    /**
     * A place where a rapid meets material.
     *
     * @param at the cell's centre at the tool's bottom there
     * @param topZMm the material's top there
     * @param depthMm how far the tool's bottom is below it
     */
    record Hit(Vec3 at, double topZMm, double depthMm) {}

    /** How much a tool's lower envelope rises per mm off its axis: a drill's point, else flat. */
    private static double slope(ToolLimits t) {
        return t.plunge() && t.kind().equals(ToolLimits.drill().kind()) ? POINT_SLOPE : 0;
    }

    static boolean alongZ(Vec3 axis) {
        return axis.distance(Vec3.UNIT_Z) <= FloorRule.AXIS_TOLERANCE;
    }

    /**
     * The lowest height of the tool's bottom over the point while its axis moves from a to b with
     * the point within r of the axis (z is linear along the move, so the least is at an end of
     * the stretch where the point is under the tool); NaN when it never is.
     */
    private static double lowestOver(Vec3 a, Vec3 b, double x, double y, double r) {
        double dx = b.x() - a.x();
        double dy = b.y() - a.y();
        double fx = a.x() - x;
        double fy = a.y() - y;
        double qa = dx * dx + dy * dy;
        double qb = 2 * (fx * dx + fy * dy);
        double qc = fx * fx + fy * fy - r * r;
        double t0;
        double t1;
        if (qa < 1e-18) {
            if (qc > 0) {
                return Double.NaN;
            }
            t0 = 0;
            t1 = 1;
        } else {
            double disc = qb * qb - 4 * qa * qc;
            if (disc < 0) {
                return Double.NaN;
            }
            double sq = Math.sqrt(disc);
            t0 = Math.max(0, (-qb - sq) / (2 * qa));
            t1 = Math.min(1, (-qb + sq) / (2 * qa));
            if (t0 > t1) {
                return Double.NaN;
            }
        }
        double z0 = a.z() + (b.z() - a.z()) * t0;
        double z1 = a.z() + (b.z() - a.z()) * t1;
        return Math.min(z0, z1);
    }

    /** Lowers the cells under a straight piece to the tool's envelope at the piece's higher end. */
    private void lower(Vec3 a, Vec3 b, double radiusMm, double slope) {
        double z = Math.max(a.z(), b.z());
        if (z >= stock.maxZMm()) {
            return;
        }
        // a tool narrower than a cell still marks the cells about its axis
        double reach = Math.max(radiusMm, AXIS_REACH_MM);
        int j0 = index(Math.min(a.y(), b.y()) - reach);
        int j1 = index(Math.max(a.y(), b.y()) + reach);
        int i0 = index(Math.min(a.x(), b.x()) - reach);
        int i1 = index(Math.max(a.x(), b.x()) + reach);
        if ((long) (j1 - j0 + 1) * (i1 - i0 + 1) > 50_000_000L) {
            return; // a move of absurd size removes nothing: the rapids after it are judged as into stock
        }
        for (int j = j0; j <= j1; j++) {
            double y = centre(j);
            double[] span = rowSpan(a, b, reach, y);
            if (span == null) {
                continue;
            }
            int from = Math.max(i0, (int) Math.ceil(span[0] / CELL_MM - 0.5));
            int to = Math.min(i1, (int) Math.floor(span[1] / CELL_MM - 0.5));
            for (int i = from; i <= to; i++) {
                double h = slope == 0 ? z : z + slope * distanceToSegment(a, b, centre(i), y);
                float[] tile = tile(i, j, true);
                int k = cellInTile(i, j);
                if (Float.isNaN(tile[k]) || h < tile[k]) {
                    tile[k] = (float) h;
                }
            }
        }
    }

    /**
     * The x interval of the row at y within r of the segment a b (a capsule is convex, so its
     * trace on a row is one interval), or null when the row misses it.
     */
    static double[] rowSpan(Vec3 a, Vec3 b, double r, double y) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (Vec3 e : new Vec3[] {a, b}) {
            double dy = y - e.y();
            if (Math.abs(dy) <= r) {
                double w = Math.sqrt(r * r - dy * dy);
                lo = Math.min(lo, e.x() - w);
                hi = Math.max(hi, e.x() + w);
            }
        }
        double dx = b.x() - a.x();
        double dy = b.y() - a.y();
        double len = Math.sqrt(dx * dx + dy * dy);
        if (len > 1e-12) {
            // the band beside the segment: 0 <= along <= len and |across| <= r, both linear in x
            double ux = dx / len;
            double uy = dy / len;
            double[] along = slab(ux, uy * (y - a.y()) - ux * a.x(), 0, len);
            double[] across = slab(-uy, ux * (y - a.y()) + uy * a.x(), -r, r);
            if (along != null && across != null) {
                double l = Math.max(along[0], across[0]);
                double h = Math.min(along[1], across[1]);
                if (l <= h) {
                    lo = Math.min(lo, l);
                    hi = Math.max(hi, h);
                }
            }
        }
        return lo <= hi ? new double[] {lo, hi} : null;
    }

    /** The x where lo <= c x + k <= hi: an interval, the whole row, or null. */
    private static double[] slab(double c, double k, double lo, double hi) {
        if (Math.abs(c) < 1e-12) {
            return k >= lo && k <= hi ? new double[] {Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY} : null;
        }
        double x0 = (lo - k) / c;
        double x1 = (hi - k) / c;
        return new double[] {Math.min(x0, x1), Math.max(x0, x1)};
    }

    /** The material's top over a cell: the stock's top where no cut has reached, none outside the box. */
    private double top(int i, int j, double x, double y) {
        if (x < stock.minXMm() || x > stock.maxXMm() || y < stock.minYMm() || y > stock.maxYMm()) {
            return Double.NEGATIVE_INFINITY;
        }
        float[] tile = tile(i, j, false);
        if (tile == null || Float.isNaN(tile[cellInTile(i, j)])) {
            return stock.maxZMm();
        }
        return Math.min(stock.maxZMm(), tile[cellInTile(i, j)]);
    }

    private float[] tile(int i, int j, boolean make) {
        long key = ((long) Math.floorDiv(i, TILE) << 32) ^ (Math.floorDiv(j, TILE) & 0xffffffffL);
        // consecutive cells are mostly in one tile: the last one found is asked first
        if (lastTile != null && key == lastKey) {
            return lastTile;
        }
        float[] t = tiles.get(key);
        if (t != null) {
            lastKey = key;
            lastTile = t;
        }
        if (t == null && make) {
            t = new float[TILE * TILE];
            java.util.Arrays.fill(t, Float.NaN);
            tiles.put(key, t);
        }
        return t;
    }

    private static int cellInTile(int i, int j) {
        return Math.floorMod(j, TILE) * TILE + Math.floorMod(i, TILE);
    }

    private static int index(double v) {
        double c = Math.floor(v / CELL_MM);
        return (int) Math.max(Integer.MIN_VALUE / 2, Math.min(Integer.MAX_VALUE / 2, c));
    }

    private static double centre(int i) {
        return (i + 0.5) * CELL_MM;
    }

    private static double clampLow(double side, double a, double b, double r) {
        return Double.isFinite(side) ? side - CELL_MM : Math.min(a, b) - r;
    }

    private static double clampHigh(double side, double a, double b, double r) {
        return Double.isFinite(side) ? side + CELL_MM : Math.max(a, b) + r;
    }

    private static double distanceToSegment(Vec3 a, Vec3 b, double x, double y) {
        double dx = b.x() - a.x();
        double dy = b.y() - a.y();
        double q = dx * dx + dy * dy;
        double t = q < 1e-18 ? 0 : Math.max(0, Math.min(1, ((x - a.x()) * dx + (y - a.y()) * dy) / q));
        double ex = a.x() + t * dx - x;
        double ey = a.y() + t * dy - y;
        return Math.sqrt(ex * ex + ey * ey);
    }
}
