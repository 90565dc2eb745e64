package org.fresa.pocket;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;

/**
 * The tool's engagement along a pocket's program, measured from its moves alone (not from any
 * planner's own bookkeeping): the floor of the pocket (inside its walls, outside its islands) is a
 * raster of cells of R / 100 at most 0.05 mm; the moves are sampled every cell; at each sample of a
 * move at the floor, the engagement angle is the part of the leading half of the tool's
 * circumference (within 90 degrees of the direction of travel) that meets floor not yet cut by the
 * moves before it, looked up one cell outside the circumference so that the tool's own trail is
 * never taken for material; then the disc is marked cut. A move going down (an entry: helix, ramp
 * or plunge) marks its disc cut and is not measured: the entry is the exception the load allows. A
 * move below the last floor starts a new layer with the floor uncut again. Units mm and degrees.
 *
 * <p>The width of cut equivalent to an angle theta is R (1 - cos theta): a straight cut of width
 * s engages acos(1 - s / R), a slot 180 degrees.
 *
 * @param maxDeg the largest engagement of the measured moves (deg)
 * @param meanDeg the mean engagement of the measured samples that cut (deg)
 * @param worstAt where the largest was met (XY)
 * @param finishingMaxDeg the largest engagement of the moves at the finishing feed (deg)
 * @param cuttingMm the length of the measured moves at the floor that cut (mm)
 */
public record Engagement(double maxDeg, double meanDeg, Vec2 worstAt, double finishingMaxDeg, double cuttingMm) {

    /** The finest cell of the raster (mm). */
    static final double MAX_CELL_MM = 0.05;

    /** Cells per tool radius. */
    static final double CELLS_PER_RADIUS = 40;

    /** Most cells: a larger pocket is measured on coarser cells. */
    static final long MAX_CELLS = 16_000_000;

    /** The angle (deg) of a straight cut of width s with a tool of radius r. */
    public static double angleDeg(double widthMm, double radiusMm) {
        return Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, 1 - widthMm / radiusMm))));
    }

    /** The width of a straight cut (mm) engaging this angle. */
    public static double widthMm(double angleDeg, double radiusMm) {
        return radiusMm * (1 - Math.cos(Math.toRadians(Math.min(180, angleDeg))));
    }

    /**
     * Measures one tool's moves.
     *
     * @param boundary the pocket's walls and islands (any orientation; the floor is where the
     *     winding number is odd)
     * @param radiusMm the tool radius
     * @param start where the tool is before the first move
     * @param moves the moves
     * @param finishingFeedMmPerMin moves at this feed are reported apart ({@link #finishingMaxDeg})
     */
    public static Engagement of(
            List<Contour> boundary, double radiusMm, Vec3 start, List<Move> moves, double finishingFeedMmPerMin) {
        return of(boundary, radiusMm, start, moves, finishingFeedMmPerMin, (i, p, deg) -> {});
    }

    /** Each measured sample: the index of its move, where it is, its engagement (deg). */
    @FunctionalInterface
    interface Sample {
        void at(int move, Vec2 p, double deg);
    }

    static Engagement of(
            List<Contour> boundary,
            double radiusMm,
            Vec3 start,
            List<Move> moves,
            double finishingFeedMmPerMin,
            Sample sample) {
        Box2 box = boundary.get(0).bounds();
        for (Contour c : boundary) {
            box = box.union(c.bounds());
        }
        double m = 2 * radiusMm;
        double h = Math.min(MAX_CELL_MM, radiusMm / CELLS_PER_RADIUS);
        double w = box.width() + 2 * m;
        double ht = box.height() + 2 * m;
        if (w * ht / (h * h) > MAX_CELLS) {
            h = Math.sqrt(w * ht / MAX_CELLS);
        }
        Raster g =
                new Raster(box.minX() - m, box.minY() - m, h, (int) Math.ceil(w / h) + 1, (int) Math.ceil(ht / h) + 1);
        g.fill(boundary);
        Trail trail = new Trail(g, radiusMm, h);
        double max = 0;
        double finishingMax = 0;
        Vec2 worst = null;
        double sum = 0;
        long counted = 0;
        double cutting = 0;
        double floorZ = Double.NaN;
        Vec3 at = start;
        int rays = 180;
        for (int mi = 0; mi < moves.size(); mi++) {
            Move mv = moves.get(mi);
            if (mv instanceof Move.Rapid) {
                at = mv.end();
                continue;
            }
            if (!(mv instanceof Move.Linear || mv instanceof Move.Circular)) {
                continue;
            }
            double feed = mv instanceof Move.Linear l ? l.feedMmPerMin() : ((Move.Circular) mv).feedMmPerMin();
            boolean finishing = feed == finishingFeedMmPerMin;
            List<Vec3> pts = samples(at, mv, h);
            Vec3 prev = at;
            for (Vec3 p : pts) {
                boolean level = Math.abs(p.z() - prev.z()) < 1e-9;
                if (!level && p.z() < prev.z() && !Double.isNaN(floorZ) && p.z() < floorZ - 1e-6) {
                    // below the last floor: a new layer, whose floor is uncut
                    trail.clear();
                    floorZ = Double.NaN;
                }
                Vec2 q = new Vec2(p.x(), p.y());
                Vec2 from = new Vec2(prev.x(), prev.y());
                Vec2 d = q.minus(from);
                boolean atFloor = level && (Double.isNaN(floorZ) || p.z() <= floorZ + 1e-6);
                if (atFloor && d.norm() > 1e-12) {
                    floorZ = p.z();
                    Vec2 u = d.normalized();
                    int engaged = 0;
                    for (int k = 0; k < rays; k++) {
                        double b = Math.toRadians(-90 + (k + 0.5) * 180.0 / rays);
                        if (trail.uncut(q.plus(u.rotated(b).times(radiusMm * (1 + 1e-6))))) {
                            engaged++;
                        }
                    }
                    double deg = engaged * 180.0 / rays;
                    sample.at(mi, q, deg);
                    if (finishing) {
                        finishingMax = Math.max(finishingMax, deg);
                    } else if (deg > max) {
                        max = deg;
                        worst = q;
                    }
                    if (!finishing && engaged > 0) {
                        sum += deg;
                        counted++;
                        cutting += d.norm();
                    }
                }
                if (atFloor || p.z() < prev.z()) {
                    trail.add(from, q);
                }
                prev = p;
            }
            at = mv.end();
        }
        return new Engagement(max, counted > 0 ? sum / counted : 0, worst, finishingMax, cutting);
    }

    /**
     * What the tool has cut at this layer. The last pieces of its path (the trail of
     * {@link #LAG_OF_SQRT_RH} times the square root of R times the cell) are judged exactly; the
     * pieces before them are in two rasters: the cells surely cut (within R less 3 cells of a
     * piece), and about the disc's edge (R plus or less 3 cells) the distance from each cell's
     * centre to the nearest piece, interpolated bilinearly between the four centres about a
     * point, within h^2 / 8R of the true distance, so that a circumference that only touches what
     * is left is not taken for cutting it.
     */
    private static final class Trail {
        final Raster g;
        final double r;
        final double lagMm;
        final BitSet cutIn;
        final float[] dist;
        final java.util.ArrayDeque<Vec2[]> recent = new java.util.ArrayDeque<>();
        double recentMm;

        Trail(Raster g, double r, double h) {
            this.g = g;
            this.r = r;
            this.lagMm = LAG_OF_SQRT_RH * Math.sqrt(r * h) + 2 * h;
            this.cutIn = new BitSet(g.nx * g.ny);
            this.dist = new float[g.nx * g.ny];
            java.util.Arrays.fill(dist, Float.POSITIVE_INFINITY);
        }

        void clear() {
            cutIn.clear();
            java.util.Arrays.fill(dist, Float.POSITIVE_INFINITY);
            recent.clear();
            recentMm = 0;
        }

        void add(Vec2 a, Vec2 b) {
            Vec2[] last = recent.peekLast();
            if (last != null
                    && last[1].equals(a)
                    && Coverage.nearestOnSegment(last[0], b, a).distance(a) <= MERGE_MM) {
                // a piece on in the same direction (or round an arc within a tenth of a micrometre): one piece
                recentMm += last[0].distance(b) - len(last);
                last[1] = b;
            } else {
                recent.addLast(new Vec2[] {a, b});
                recentMm += a.distance(b);
            }
            while (recent.size() > 1 && recentMm - len(recent.peekFirst()) > lagMm) {
                Vec2[] old = recent.pollFirst();
                recentMm -= len(old);
                commit(old);
            }
        }

        private static double len(Vec2[] s) {
            return s[0].distance(s[1]);
        }

        /** The piece into the rasters: row by row, the cells within R + 3h of it. */
        private void commit(Vec2[] s) {
            double h = g.h;
            double outer = r + 3 * h;
            double inner = r - 3 * h;
            Vec2 a = s[0];
            Vec2 b = s[1];
            int j0 = Math.max(0, (int) Math.floor((Math.min(a.y(), b.y()) - outer - g.y0) / h - 0.5));
            int j1 = Math.min(g.ny - 1, (int) Math.ceil((Math.max(a.y(), b.y()) + outer - g.y0) / h - 0.5));
            int i0 = Math.max(0, (int) Math.floor((Math.min(a.x(), b.x()) - outer - g.x0) / h - 0.5));
            int i1 = Math.min(g.nx - 1, (int) Math.ceil((Math.max(a.x(), b.x()) + outer - g.x0) / h - 0.5));
            double ax = a.x();
            double ay = a.y();
            double dx = b.x() - ax;
            double dy = b.y() - ay;
            double dd = dx * dx + dy * dy;
            for (int j = j0; j <= j1; j++) {
                double y = g.y0 + (j + 0.5) * h;
                for (int i = i0; i <= i1; i++) {
                    int k = j * g.nx + i;
                    if (cutIn.get(k)) {
                        continue;
                    }
                    double x = g.x0 + (i + 0.5) * h;
                    double t = dd < 1e-24 ? 0 : Math.max(0, Math.min(1, ((x - ax) * dx + (y - ay) * dy) / dd));
                    double ex = x - ax - t * dx;
                    double ey = y - ay - t * dy;
                    double d2 = ex * ex + ey * ey;
                    if (d2 <= inner * inner) {
                        cutIn.set(k);
                    } else if (d2 <= outer * outer) {
                        float d = (float) Math.sqrt(d2);
                        if (d < dist[k]) {
                            dist[k] = d;
                        }
                    }
                }
            }
        }

        boolean uncut(Vec2 p) {
            int k = g.index(p);
            if (k < 0 || !g.floor.get(k) || cutIn.get(k)) {
                return false;
            }
            double r2 = r * r;
            for (Vec2[] s : recent) {
                Vec2 q = Coverage.nearestOnSegment(s[0], s[1], p);
                double ex = q.x() - p.x();
                double ey = q.y() - p.y();
                if (ex * ex + ey * ey <= r2) {
                    return false;
                }
            }
            // bilinear between the four cell centres about p
            double fx = (p.x() - g.x0) / g.h - 0.5;
            double fy = (p.y() - g.y0) / g.h - 0.5;
            int ci = (int) Math.floor(fx);
            int cj = (int) Math.floor(fy);
            if (ci < 0 || cj < 0 || ci + 1 >= g.nx || cj + 1 >= g.ny) {
                return true;
            }
            double tx = fx - ci;
            double ty = fy - cj;
            double v = 0;
            for (int c = 0; c < 4; c++) {
                int kk = (cj + (c >> 1)) * g.nx + ci + (c & 1);
                if (cutIn.get(kk)) {
                    return false;
                }
                float d = dist[kk];
                if (d == Float.POSITIVE_INFINITY) {
                    return true;
                }
                v += d * ((c & 1) == 1 ? tx : 1 - tx) * ((c >> 1) == 1 ? ty : 1 - ty);
            }
            return v > r;
        }
    }

    /** The exactly judged trail, in units of the square root of R times the cell: beyond it the rasters tell. */
    static final double LAG_OF_SQRT_RH = 4;

    /** How far a joint may lie off the chord of two pieces merged into one (mm). */
    static final double MERGE_MM = 1e-4;

    /** Points along the move from its start, at most h apart, its end last. */
    private static List<Vec3> samples(Vec3 from, Move mv, double h) {
        List<Vec3> out = new ArrayList<>();
        if (mv instanceof Move.Circular c && Math.abs(c.normal().z() - 1) < 1e-9) {
            Vec2 ctr = new Vec2(c.center().x(), c.center().y());
            Vec2 a = new Vec2(from.x(), from.y()).minus(ctr);
            Vec2 b = new Vec2(c.end().x(), c.end().y()).minus(ctr);
            double rad = a.norm();
            double sweep = Math.atan2(a.cross(b), a.dot(b));
            if (c.ccw()) {
                if (sweep <= 1e-12) {
                    sweep += 2 * Math.PI;
                }
                sweep += 2 * Math.PI * c.turns();
            } else {
                if (sweep >= -1e-12) {
                    sweep -= 2 * Math.PI;
                }
                sweep -= 2 * Math.PI * c.turns();
            }
            int n = Math.max(1, (int) Math.ceil(Math.abs(sweep) * rad / h));
            double a0 = Math.atan2(a.y(), a.x());
            for (int k = 1; k <= n; k++) {
                double t = (double) k / n;
                double ang = a0 + sweep * t;
                out.add(new Vec3(
                        ctr.x() + rad * Math.cos(ang),
                        ctr.y() + rad * Math.sin(ang),
                        from.z() + (c.end().z() - from.z()) * t));
            }
            out.set(out.size() - 1, c.end());
            return out;
        }
        Vec3 e = mv.end();
        int n = Math.max(1, (int) Math.ceil(Math.hypot(e.x() - from.x(), e.y() - from.y()) / h));
        for (int k = 1; k <= n; k++) {
            double t = (double) k / n;
            out.add(new Vec3(
                    from.x() + (e.x() - from.x()) * t,
                    from.y() + (e.y() - from.y()) * t,
                    from.z() + (e.z() - from.z()) * t));
        }
        return out;
    }

    /** The floor's cells: inside the walls, and cut or not. */
    private static final class Raster {
        final double x0;
        final double y0;
        final double h;
        final int nx;
        final int ny;
        final BitSet floor;

        Raster(double x0, double y0, double h, int nx, int ny) {
            this.x0 = x0;
            this.y0 = y0;
            this.h = h;
            this.nx = nx;
            this.ny = ny;
            this.floor = new BitSet(nx * ny);
        }

        void fill(List<Contour> boundary) {
            List<Vec2[]> chords = new ArrayList<>();
            for (Contour c : boundary) {
                chords.addAll(Coverage.chords(c.curves()));
            }
            for (int j = 0; j < ny; j++) {
                double y = y0 + (j + 0.5) * h;
                List<Double> xs = new ArrayList<>();
                for (Vec2[] s : chords) {
                    if ((s[0].y() <= y) != (s[1].y() <= y)) {
                        xs.add(s[0].x() + (y - s[0].y()) / (s[1].y() - s[0].y()) * (s[1].x() - s[0].x()));
                    }
                }
                xs.sort(Double::compare);
                for (int k = 0; k + 1 < xs.size(); k += 2) {
                    int i0 = Math.max(0, (int) Math.ceil((xs.get(k) - x0) / h - 0.5));
                    int i1 = Math.min(nx - 1, (int) Math.floor((xs.get(k + 1) - x0) / h - 0.5));
                    if (i0 <= i1) {
                        floor.set(j * nx + i0, j * nx + i1 + 1);
                    }
                }
            }
        }

        int index(Vec2 p) {
            int i = (int) Math.floor((p.x() - x0) / h);
            int j = (int) Math.floor((p.y() - y0) / h);
            if (i < 0 || j < 0 || i >= nx || j >= ny) {
                return -1;
            }
            return j * nx + i;
        }

        void disc(BitSet cut, Vec2 c, double r) {
            int j0 = Math.max(0, (int) Math.ceil((c.y() - r - y0) / h - 0.5));
            int j1 = Math.min(ny - 1, (int) Math.floor((c.y() + r - y0) / h - 0.5));
            for (int j = j0; j <= j1; j++) {
                double dy = y0 + (j + 0.5) * h - c.y();
                double half = Math.sqrt(Math.max(0, r * r - dy * dy));
                int i0 = Math.max(0, (int) Math.ceil((c.x() - half - x0) / h - 0.5));
                int i1 = Math.min(nx - 1, (int) Math.floor((c.x() + half - x0) / h - 0.5));
                if (i0 <= i1) {
                    cut.set(j * nx + i0, j * nx + i1 + 1);
                }
            }
        }
    }
}
