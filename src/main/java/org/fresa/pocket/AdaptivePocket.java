package org.fresa.pocket;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

/**
 * Adaptive (constant-engagement) clearing of a region with islands: the tool's centre walks the
 * pre-finish offset's faces (R + a, islands included, their sharp corners rounded to
 * {@link #CORNER_OF_RADIUS} R) in short steps, each in the direction whose
 * newly cut area is the stepover's, so that the tool never takes a full-width cut at its first
 * cut, in corners or in necks; then the contour passes of {@link RegionPocket} (pre-finish at
 * R + a, finishing at R, arcs as arcs) clean the walls, as the other strategies do. Units mm.
 *
 * <p>The load: the stepover s (the cut fraction times D) is the radial width of cut of a straight
 * cut; a step of length L then cuts L s of floor. The floor is a raster of cut and uncut cells
 * (about R / {@link #CELLS_PER_RADIUS} on a side, at most {@link #MAX_CELLS} cells). Each step of
 * L = R / 10 searches the direction by bisection between one that cuts more than L s (towards the
 * material) and one that cuts less (towards the cleared floor), starting from the last direction
 * so that the material stays on one side: on the right for climb milling (a right-hand cutter
 * turning clockwise cuts down into it), on the left for conventional. A position outside the
 * pre-finish faces counts as cutting too much: the walk turns away from the walls. The engagement
 * is judged at the step's start (in its new direction), halfway and at its end, on the leading
 * half of the circumference against the distance to the cut interpolated between cells, as
 * {@link Engagement} judges the program.
 *
 * <p>Entry: at the point of the faces farthest from their boundary, a helix (of the largest radius
 * {@link Entries} allows there, up to R) and a full circle at depth clear a disc; the walk starts on
 * that circle. A walk ends where no direction cuts (nothing left within reach), where every
 * direction cuts too much (the load cannot be held), or after 2 R of steps that cut next to
 * nothing; the tool then feeds to the nearest place beside uncut floor along cells whose tool disc
 * is cut (staying down), else retracts and enters again where such a place is (the entry judged as
 * into stock), else enters by a helix into the uncut floor farthest from the boundary. Material no
 * walk reached and the pre-finish pass cannot reach is refused, naming the place: a plan that
 * leaves material is never written. What the walks cannot take at the stepover (floor in a face
 * too small for an entry, a narrow end, a face of the offset too narrow to round, where only a
 * full-width cut reaches the floor) the contour passes take in a wider cut; the program's moves
 * are then measured and each move that engages more than the bound is fed slower in proportion
 * ({@link EngagementFeed}), so that no move removes more material per minute than a cut of the
 * bound's width at the programmed feed.
 */
public final class AdaptivePocket {

    private static final Tolerance TOL = Tolerance.DEFAULT;
    private static final Vec3 Z = new Vec3(0, 0, 1);
    private static final double CLEARANCE_MM = 5;

    /** Raster cells per tool radius: the floor is known to about R / 20. */
    static final double CELLS_PER_RADIUS = 25;

    /** The coarsest raster allowed, cells per tool radius: coarser would misjudge the load by more than 10 %. */
    static final double MIN_CELLS_PER_RADIUS = 10;

    /** Most cells of the raster. */
    static final long MAX_CELLS = 4_000_000;

    /** The step of a walk as a fraction of the tool radius. */
    static final double STEP_OF_RADIUS = 0.1;

    /** How far a walk's polyline may be simplified (mm). */
    static final double SIMPLIFY_MM = 0.005;

    /** The shortest move written (mm): below the program's resolution. */
    static final double MIN_MOVE_MM = 1e-3;

    /** The directions tried, one way round from the last, before the bisection (10 degrees apart). */
    private static final int SCAN_STEPS = 36;

    private static final int BISECTIONS = 10;

    /** How far below the bound (deg) the walk holds the engagement on its own raster. */
    static final double ANGLE_MARGIN_DEG = 4;

    /**
     * The radius (a fraction of the tool radius) to which the corners of the faces the tool's
     * centre keeps to are rounded. At a sharp corner of angle phi the centre cannot come without
     * engaging 180 - phi degrees of the tool, however little it cuts (every direction away from the
     * corner's faces is uncut floor), so a walk or the pre-finish pass reaching a 40 degree corner
     * engages 140 degrees, far beyond the stepover's angle; round the corner, it engages what the
     * walks left. The corner's floor, up to 1 / sin(phi / 2) - 1 times the radius beyond the
     * allowance, goes to the finishing pass, which meets two walls' allowance there anyway.
     */
    static final double CORNER_OF_RADIUS = 0.25;

    /** Where along a step (fractions of it) the engagement is judged: its start, halfway, its end. */
    private static final double[] ALONG_STEP = {0.1, 0.5, 1};

    /**
     * The plan.
     *
     * @param finishing the loops of the finishing offset (R)
     * @param walks how many walks clear the floor
     * @param entries how many times the tool goes down into the floor at one depth (the first
     *     helix included)
     * @param cellMm the raster's cell
     * @param order the cuts in machining order at each depth: chains of walks (each from an
     *     entry), then the contour passes
     * @param toolpath the moves
     * @param slowed the moves whose feed drops where the geometry forces a wider cut than the
     *     stepover's
     */
    public record Plan(
            List<Contour> finishing,
            int walks,
            int entries,
            double cellMm,
            List<ZigzagPocket.Cut> order,
            Toolpath toolpath,
            EngagementFeed.Slowed slowed) {
        public Plan {
            finishing = List.copyOf(finishing);
            order = List.copyOf(order);
        }
    }

    private AdaptivePocket() {}

    /**
     * Plans the pocket.
     *
     * @param outer the outer contour (either orientation)
     * @param islands closed contours inside it (either orientation), not touching it or each other
     * @param tech the technology (tool, stepover, allowance, depths, feeds)
     * @param climb climb milling (the material on the walk's right) or conventional
     * @param entry the entries allowed
     * @throws ToolTooLargeException when the tool does not fit, an entry has no room, the raster
     *     would be too coarse, or material would be left
     */
    public static Plan plan(Contour outer, List<Contour> islands, PocketTechnology tech, boolean climb, EntryRule entry)
            throws ToolTooLargeException {
        return plan(RegionOffsetter.oriented(outer, islands), tech, climb, entry);
    }

    /**
     * Plans the pocket of a region given by its boundary (any number of faces).
     *
     * @param boundary the region's loops with the region on their left ({@link RegionOffsetter#oriented})
     * @throws ToolTooLargeException as {@link #plan(Contour, List, PocketTechnology, boolean, EntryRule)}
     */
    public static Plan plan(List<Contour> boundary, PocketTechnology tech, boolean climb, EntryRule entry)
            throws ToolTooLargeException {
        return plan(boundary, tech, climb, entry, f -> {});
    }

    /**
     * Plans the pocket, telling how far the walks are.
     *
     * @param progress told the fraction (0 to 1) of the floor the walks have cleared, now and then
     * @throws ToolTooLargeException as {@link #plan(Contour, List, PocketTechnology, boolean, EntryRule)}
     */
    public static Plan plan(
            List<Contour> boundary,
            PocketTechnology tech,
            boolean climb,
            EntryRule entry,
            java.util.function.DoubleConsumer progress)
            throws ToolTooLargeException {
        double r = tech.radiusMm();
        double a = tech.finishFraction() * tech.toolDiameterMm();
        List<Contour> finishing = RegionOffsetter.inward(boundary, r, TOL);
        if (finishing.isEmpty()) {
            throw new ToolTooLargeException("the tool (" + tech.toolDiameterMm()
                    + " mm) does not fit anywhere in the pocket: use a smaller tool");
        }
        // the faces the walks and the pre-finish pass keep the tool's centre in: the region offset by
        // R + a with its corners rounded (see CORNER_OF_RADIUS)
        double rho = CORNER_OF_RADIUS * r;
        List<Contour> inner = opened(boundary, r + a, rho);
        List<ZigzagPocket.Cut> order = new ArrayList<>();
        int walks = 0;
        int entries = 0;
        double cell = 0;
        Walker walker = null;
        if (!inner.isEmpty()) {
            double stepover = Math.min(1, tech.cutFraction()) * tech.toolDiameterMm();
            // the planner holds the angle a little below the bound, for its coarser raster
            double limit = Math.min(
                    Engagement.angleDeg(stepover, r), Engagement.angleDeg(1.1 * stepover, r) - ANGLE_MARGIN_DEG);
            Walker w = new Walker(inner, r, stepover, limit, climb);
            w.run(progress);
            walker = w;
            walks = w.walks;
            entries = w.chains.size();
            cell = w.h;
            for (Chain c : w.chains) {
                order.add(new ZigzagPocket.Cut(false, false, c.curves()));
            }
        }
        Vec2 cursor = order.isEmpty() ? null : order.get(order.size() - 1).end();
        if (!inner.isEmpty()) {
            int first = order.size();
            cursor = ZigzagPocket.loops(inner, false, climb, cursor, order);
            if (walker != null) {
                for (ZigzagPocket.Cut c : order.subList(first, order.size())) {
                    walker.pass(c.curves());
                }
            }
        }
        ZigzagPocket.loops(finishing, true, climb, cursor, order);
        tech.checkMoves(
                order.stream().mapToLong(c -> 3L * c.curves().size() + 4).sum());
        List<Contour> room = inner.isEmpty() ? finishing : inner;
        List<Object> owners = new ArrayList<>();
        Toolpath path = toolpath(order, finishing, room, tech, entry, climb, EngagementFeed.NONE, owners);
        double stepover = Math.min(1, tech.cutFraction()) * tech.toolDiameterMm();
        EngagementFeed feed =
                EngagementFeed.of(boundary, tech, stepover, path.sections().get(0), owners);
        if (feed.slowed().any()) {
            path = toolpath(order, finishing, room, tech, entry, climb, feed, null);
        }
        return new Plan(finishing, walks, entries, cell, order, path, feed.slowed());
    }

    /**
     * The region offset inwards by d with its convex corners rounded to radius rho (and any part of
     * it narrower than 2 rho dropped): the region offset by d + rho, grown again by rho. The
     * growing is the inward offset of the complement, the offset loops reversed inside a frame.
     */
    static List<Contour> opened(List<Contour> boundary, double d, double rho) {
        List<Contour> shrunk = RegionOffsetter.inward(boundary, d + rho, TOL);
        if (shrunk.isEmpty() || rho <= 0) {
            return shrunk;
        }
        Box2 box = shrunk.get(0).bounds();
        for (Contour c : shrunk) {
            box = box.union(c.bounds());
        }
        double m = 4 * rho + 10;
        List<Contour> complement = new ArrayList<>();
        complement.add(Contour.polygon(List.of(
                new Vec2(box.minX() - m, box.minY() - m),
                new Vec2(box.maxX() + m, box.minY() - m),
                new Vec2(box.maxX() + m, box.maxY() + m),
                new Vec2(box.minX() - m, box.maxY() + m))));
        for (Contour c : shrunk) {
            complement.add(c.reversed());
        }
        List<Contour> out = new ArrayList<>();
        for (Contour c : RegionOffsetter.inward(complement, rho, TOL)) {
            Box2 b = c.bounds();
            if (b.minX() < box.minX() - m / 2 || b.maxX() > box.maxX() + m / 2) {
                continue;
            }
            out.add(c.reversed());
        }
        out.sort((p, q) -> Double.compare(q.area(), p.area()));
        return out;
    }

    /** One chain of walks from an entry: the circle the entry clears (if any) and the polyline. */
    private record Chain(Vec2 circleCentre, double circleRadiusMm, List<Vec2> points) {
        List<Curve2> curves() {
            List<Curve2> out = new ArrayList<>();
            List<Vec2> pts = simplified(points, SIMPLIFY_MM);
            if (circleCentre != null) {
                Vec2 s = pts.get(0);
                Vec2 opposite = circleCentre.times(2).minus(s);
                boolean ccw = circleRadiusMm > 0;
                out.add(new Arc2(circleCentre, s, opposite, ccw));
                out.add(new Arc2(circleCentre, opposite, s, ccw));
            }
            for (int i = 0; i + 1 < pts.size(); i++) {
                out.add(new Segment2(pts.get(i), pts.get(i + 1)));
            }
            if (out.isEmpty()) {
                out.add(new Segment2(pts.get(0), pts.get(0)));
            }
            return out;
        }
    }

    /** The floor raster and the walks over it. */
    private static final class Walker {
        final List<Contour> faces;
        final double r;
        final double h;
        final double stepMm;
        final double targetCells;
        final double sense;
        final double x0;
        final double y0;
        final int nx;
        final int ny;
        final long[] strict;
        final float[] toInside;
        final double angleLimitDeg;
        final long[] material;
        final long[] cut;
        final boolean[] dead;
        final float[] clear;
        /** For cells about the cut's edge, the distance to the nearest disc's centre less its excess over R (mm). */
        final float[] toCut;

        final List<Chain> chains = new ArrayList<>();
        int walks;
        long steps;
        final long maxSteps;

        Walker(List<Contour> faces, double r, double stepoverMm, double angleLimitDeg, boolean climb)
                throws ToolTooLargeException {
            this.angleLimitDeg = angleLimitDeg;
            this.faces = faces;
            this.r = r;
            Box2 box = faces.get(0).bounds();
            for (Contour c : faces) {
                box = box.union(c.bounds());
            }
            double margin = 1.2 * r;
            double w = box.width() + 2 * margin;
            double hgt = box.height() + 2 * margin;
            double cell = r / CELLS_PER_RADIUS;
            if (w * hgt / (cell * cell) > MAX_CELLS) {
                cell = Math.sqrt(w * hgt / MAX_CELLS);
            }
            if (cell > r / MIN_CELLS_PER_RADIUS) {
                throw new ToolTooLargeException(String.format(
                        Locale.ROOT,
                        "the pocket (%.1f x %.1f mm) is too large for adaptive clearing with a %.3f mm tool: its"
                                + " floor would need more than %d cells of %.4f mm; use a larger tool or the offset"
                                + " or zigzag strategy",
                        box.width(),
                        box.height(),
                        2 * r,
                        MAX_CELLS,
                        r / MIN_CELLS_PER_RADIUS));
            }
            this.h = cell;
            this.x0 = box.minX() - margin;
            this.y0 = box.minY() - margin;
            this.nx = (int) Math.ceil(w / h) + 1;
            this.ny = (int) Math.ceil(hgt / h) + 1;
            this.stepMm = STEP_OF_RADIUS * r;
            this.targetCells = stepMm * stepoverMm / (h * h);
            this.sense = climb ? 1 : -1;
            int n = nx * ny;
            boolean[] inside = new boolean[n];
            fillInside(inside);
            this.clear = edt(nx, ny, i -> !inside[i]);
            this.strict = new long[(n + 63) / 64];
            for (int i = 0; i < n; i++) {
                // at least 2.5 cells from any cell outside: a point anywhere in it is over a cell inside
                if (inside[i] && clear[i] >= 6.25f) {
                    strict[i >>> 6] |= 1L << i;
                }
            }
            // a cell centre inside the faces is a place the tool's centre may be: what lies within R of one is
            // reachable
            this.toInside = edt(nx, ny, i -> inside[i]);
            double reach = r / h;
            this.material = new long[strict.length];
            // the floor within R of the faces, exactly about the disc's edge: cell centres inside the
            // faces stop up to several cells short of an acute corner of theirs, and the material about
            // that corner is what a walk or the pre-finish pass takes there
            boolean[] touched = new boolean[n];
            for (Contour c : faces) {
                for (Vec2[] ch : Coverage.chords(c.curves())) {
                    int k = Math.max(1, (int) Math.ceil(ch[0].distance(ch[1]) / (0.5 * h)));
                    for (int t = 0; t <= k; t++) {
                        int ci = cellOf(ch[0].interpolate(ch[1], (double) t / k));
                        if (ci >= 0) {
                            touched[ci] = true;
                        }
                    }
                }
            }
            float[] toFaces = edt(nx, ny, i -> inside[i] || touched[i]);
            double lo = Math.max(0, reach - 2);
            double hi = reach + 2;
            for (int i = 0; i < n; i++) {
                boolean m;
                if (toFaces[i] <= lo * lo) {
                    m = true;
                } else if (toFaces[i] > hi * hi) {
                    m = false;
                } else {
                    Vec2 c = centre(i);
                    m = room(c) > 0 || distanceToFaces(c) <= r;
                }
                if (m) {
                    material[i >>> 6] |= 1L << i;
                }
            }
            this.cut = new long[strict.length];
            this.toCut = new float[n];
            Arrays.fill(toCut, Float.POSITIVE_INFINITY);
            this.dead = new boolean[n];
            // each step cuts a cell or ends its walk; every walk either cuts or marks its start dead
            this.maxSteps = 4L * n + 1000;
        }

        private void fillInside(boolean[] inside) {
            List<Vec2[]> chords = new ArrayList<>();
            for (Contour c : faces) {
                chords.addAll(Coverage.chords(c.curves()));
            }
            for (int j = 0; j < ny; j++) {
                double y = y0 + (j + 0.5) * h;
                List<double[]> xs = new ArrayList<>();
                for (Vec2[] s : chords) {
                    Vec2 a = s[0];
                    Vec2 b = s[1];
                    if ((a.y() <= y) != (b.y() <= y)) {
                        double x = a.x() + (y - a.y()) / (b.y() - a.y()) * (b.x() - a.x());
                        xs.add(new double[] {x, b.y() > a.y() ? 1 : -1});
                    }
                }
                xs.sort((p, q) -> Double.compare(p[0], q[0]));
                int wn = 0;
                for (int k = 0; k + 1 < xs.size(); k++) {
                    wn += (int) xs.get(k)[1];
                    if (wn != 0) {
                        int i0 = Math.max(0, (int) Math.ceil((xs.get(k)[0] - x0) / h - 0.5));
                        int i1 = Math.min(nx - 1, (int) Math.floor((xs.get(k + 1)[0] - x0) / h - 0.5));
                        for (int i = i0; i <= i1; i++) {
                            inside[j * nx + i] = true;
                        }
                    }
                }
            }
        }

        boolean isStrict(int i) {
            return (strict[i >>> 6] & (1L << i)) != 0;
        }

        int cellOf(Vec2 p) {
            int i = (int) Math.floor((p.x() - x0) / h);
            int j = (int) Math.floor((p.y() - y0) / h);
            if (i < 0 || j < 0 || i >= nx || j >= ny) {
                return -1;
            }
            return j * nx + i;
        }

        Vec2 centre(int idx) {
            return new Vec2(x0 + (idx % nx + 0.5) * h, y0 + (idx / nx + 0.5) * h);
        }

        /** Uncut material cells within rr of c (counted), or marked cut. */
        private int disc(Vec2 c, double rr, boolean mark) {
            int j0 = Math.max(0, (int) Math.ceil((c.y() - rr - y0) / h - 0.5));
            int j1 = Math.min(ny - 1, (int) Math.floor((c.y() + rr - y0) / h - 0.5));
            int count = 0;
            for (int j = j0; j <= j1; j++) {
                double dy = y0 + (j + 0.5) * h - c.y();
                double half = Math.sqrt(Math.max(0, rr * rr - dy * dy));
                int i0 = Math.max(0, (int) Math.ceil((c.x() - half - x0) / h - 0.5));
                int i1 = Math.min(nx - 1, (int) Math.floor((c.x() + half - x0) / h - 0.5));
                if (i0 > i1) {
                    continue;
                }
                int from = j * nx + i0;
                int to = j * nx + i1 + 1;
                if (mark) {
                    setRange(cut, from, to);
                } else {
                    count += uncutIn(from, to);
                }
            }
            return count;
        }

        private int uncutIn(int from, int to) {
            int count = 0;
            int w0 = from >>> 6;
            int w1 = (to - 1) >>> 6;
            for (int wi = w0; wi <= w1; wi++) {
                long m = material[wi] & ~cut[wi];
                if (wi == w0) {
                    m &= -1L << (from & 63);
                }
                if (wi == w1) {
                    int e = to & 63;
                    if (e != 0) {
                        m &= (1L << e) - 1;
                    }
                }
                count += Long.bitCount(m);
            }
            return count;
        }

        private static void setRange(long[] bits, int from, int to) {
            for (int i = from; i < to; ) {
                int wi = i >>> 6;
                int end = Math.min(to, (wi + 1) << 6);
                long m = -1L << (i & 63);
                if ((end & 63) != 0 && (end >>> 6) == wi) {
                    m &= (1L << (end & 63)) - 1;
                }
                bits[wi] |= m;
                i = end;
            }
        }

        /** Whether the tool's centre may be at p: inside the faces (exactly, near their boundary). */
        boolean valid(Vec2 p) {
            int c = cellOf(p);
            if (c < 0) {
                return false;
            }
            if (isStrict(c)) {
                return true;
            }
            return toInside[c] <= 4.5f && room(p) >= 1e-3;
        }

        /**
         * The cells a step from at in direction u would cut, or infinity where its end is outside
         * the faces or the tool's circumference would meet uncut floor over more than the angle
         * allowed anywhere along it: at its start (a turn towards the material swings the leading
         * half of the circumference into it before the tool has moved), halfway and at its end.
         */
        private double load(Vec2 at, Vec2 u) {
            Vec2 p = at.plus(u.times(stepMm));
            if (!valid(p)) {
                return Double.POSITIVE_INFINITY;
            }
            int cells = disc(p, r, false);
            if (cells > 0) {
                for (double f : ALONG_STEP) {
                    if (engagedDeg(at.plus(u.times(f * stepMm)), u) > angleLimitDeg) {
                        return Double.POSITIVE_INFINITY;
                    }
                }
            }
            return cells;
        }

        /**
         * Marks the disc of R + extra about c cut, and about its edge the distance to it, so that
         * the circumference is judged within a fraction of a cell ({@link #uncutAt}).
         */
        void cutDisc(Vec2 c, double extra) {
            disc(c, r + extra, true);
            double outer = r + extra + 2 * h;
            int j0 = Math.max(0, (int) Math.ceil((c.y() - outer - y0) / h - 0.5));
            int j1 = Math.min(ny - 1, (int) Math.floor((c.y() + outer - y0) / h - 0.5));
            for (int j = j0; j <= j1; j++) {
                double dy = y0 + (j + 0.5) * h - c.y();
                double half = Math.sqrt(Math.max(0, outer * outer - dy * dy));
                int i0 = Math.max(0, (int) Math.ceil((c.x() - half - x0) / h - 0.5));
                int i1 = Math.min(nx - 1, (int) Math.floor((c.x() + half - x0) / h - 0.5));
                for (int i = i0; i <= i1; i++) {
                    double dx = x0 + (i + 0.5) * h - c.x();
                    float d = (float) Math.max(0, Math.sqrt(dx * dx + dy * dy) - extra);
                    int k = j * nx + i;
                    if (d < toCut[k]) {
                        toCut[k] = d;
                    }
                }
            }
        }

        /**
         * Whether the floor at q is uncut: a material cell, and farther than R from every disc
         * cut, by the distance interpolated between the four cell centres about q (the cell alone
         * would misjudge a sliver thinner than it, which the program's moves do cut or leave).
         */
        boolean uncutAt(Vec2 q) {
            int c = cellOf(q);
            if (c < 0 || (material[c >>> 6] & (1L << c)) == 0) {
                return false;
            }
            double fx = (q.x() - x0) / h - 0.5;
            double fy = (q.y() - y0) / h - 0.5;
            int ci = (int) Math.floor(fx);
            int cj = (int) Math.floor(fy);
            if (ci < 0 || cj < 0 || ci + 1 >= nx || cj + 1 >= ny) {
                return (cut[c >>> 6] & (1L << c)) == 0;
            }
            double tx = fx - ci;
            double ty = fy - cj;
            double v = 0;
            for (int k = 0; k < 4; k++) {
                float d = toCut[(cj + (k >> 1)) * nx + ci + (k & 1)];
                if (d == Float.POSITIVE_INFINITY) {
                    return true;
                }
                v += d * ((k & 1) == 1 ? tx : 1 - tx) * ((k >> 1) == 1 ? ty : 1 - ty);
            }
            return v > r;
        }

        /** The leading half of the circumference over uncut floor (deg). */
        double engagedDeg(Vec2 p, Vec2 u) {
            int n = 90;
            int engaged = 0;
            for (int k = 0; k < n; k++) {
                double b = Math.toRadians(-90 + (k + 0.5) * 180.0 / n);
                if (uncutAt(p.plus(u.rotated(b).times(r * (1 + 1e-6))))) {
                    engaged++;
                }
            }
            return engaged * 180.0 / n;
        }

        private double load(Vec2 at, Vec2 dir, double angleRad) {
            return load(at, direction(dir, angleRad));
        }

        private Vec2 direction(Vec2 d, double angleRad) {
            return d.rotated(sense * angleRad);
        }

        /** Walks from p in direction d, adding the positions to pts; returns the last direction, or null if no step. */
        private Vec2 walk(Vec2 p, Vec2 d, List<Vec2> pts) throws ToolTooLargeException {
            Vec2 at = p;
            Vec2 dir = d;
            double lowRun = 0;
            double total = 0;
            int first = pts.size();
            while (true) {
                if (++steps > maxSteps) {
                    throw new ToolTooLargeException("the adaptive walk did not end within " + maxSteps
                            + " steps: use the offset or zigzag strategy for this pocket");
                }
                double step = 10 * Math.PI / 180;
                double lo = Double.NaN;
                double hi = Double.NaN;
                double g0 = load(at, dir, 0);
                if (g0 > targetCells) {
                    for (int k = 1; k <= SCAN_STEPS; k++) {
                        if (load(at, dir, k * step) <= targetCells) {
                            lo = (k - 1) * step;
                            hi = k * step;
                            break;
                        }
                    }
                    if (Double.isNaN(hi)) {
                        // every direction cuts too much (or leaves the faces): the load cannot be held here
                        break;
                    }
                } else {
                    double best = g0;
                    double bestA = 0;
                    for (int k = 1; k <= SCAN_STEPS; k++) {
                        double g = load(at, dir, -k * step);
                        if (g > targetCells) {
                            lo = -k * step;
                            hi = -(k - 1) * step;
                            break;
                        }
                        if (g > best) {
                            best = g;
                            bestA = -k * step;
                        }
                    }
                    if (Double.isNaN(hi)) {
                        if (best < 1) {
                            break;
                        }
                        lo = bestA;
                        hi = bestA;
                    }
                }
                for (int b = 0; b < BISECTIONS && hi != lo; b++) {
                    double mid = (lo + hi) / 2;
                    if (load(at, dir, mid) > targetCells) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                Vec2 nd = direction(dir, hi).normalized();
                Vec2 next = at.plus(nd.times(stepMm));
                double g = load(at, nd);
                if (g == Double.POSITIVE_INFINITY) {
                    break;
                }
                if (g < 0.05 * targetCells) {
                    lowRun += stepMm;
                    if (lowRun > 2 * r) {
                        break;
                    }
                } else {
                    lowRun = 0;
                }
                total += g;
                cutDisc(next, 0);
                pts.add(next);
                at = next;
                dir = nd;
            }
            if (total < 1) {
                // a walk that cut nothing marked nothing: it is taken back
                while (pts.size() > first) {
                    pts.remove(pts.size() - 1);
                }
                return null;
            }
            return dir;
        }

        /** The breadth-first search's parents, -2 where not reached (reset after each search). */
        private int[] parent;

        private float[] memo;
        private int[] memoStamp;
        private int stamp;

        /**
         * The squared distance (cells) from a cell to the nearest uncut material cell, as far as the
         * frontier's reach (beyond it, infinity: the walks only ask whether a cell is within it). A
         * link's search asks about the cells near the tool: they are found in the raster's rows
         * about the cell. A search that asks about more than an eighth of the raster, and the scans
         * of every cell for a new entry, take the whole distance transform instead. What it buys:
         * the transform of the whole raster at every walk's end took cavity 02 with a 6 mm tool
         * (4 million cells) 415 s to plan, this 53 s, for the same program.
         */
        private final class UncutDistance {
            private final int reach;
            private float[] full;
            private long asked;

            UncutDistance(double frontierSq) {
                this.reach = (int) Math.ceil(Math.sqrt(frontierSq));
                if (memo == null) {
                    memo = new float[nx * ny];
                    memoStamp = new int[nx * ny];
                }
                stamp++;
            }

            float sq(int i) {
                if (full != null) {
                    return full[i];
                }
                if (memoStamp[i] == stamp) {
                    return memo[i];
                }
                if (++asked > (long) nx * ny / 8) {
                    full = toUncut();
                    return full[i];
                }
                float d = near(i);
                memo[i] = d;
                memoStamp[i] = stamp;
                return d;
            }

            /** The whole transform, for scans of every cell. */
            float[] all() {
                if (full == null) {
                    full = toUncut();
                }
                return full;
            }

            private float near(int idx) {
                int ci = idx % nx;
                int cj = idx / nx;
                long best = Long.MAX_VALUE;
                for (int dj = -reach; dj <= reach; dj++) {
                    int j = cj + dj;
                    if (j < 0 || j >= ny) {
                        continue;
                    }
                    long dj2 = (long) dj * dj;
                    if (dj2 >= best) {
                        continue;
                    }
                    int from = j * nx + Math.max(0, ci - reach);
                    int to = j * nx + Math.min(nx - 1, ci + reach) + 1;
                    int centre = j * nx + ci;
                    for (int wi = from >>> 6; wi <= (to - 1) >>> 6; wi++) {
                        long m = material[wi] & ~cut[wi];
                        if (wi == from >>> 6) {
                            m &= -1L << (from & 63);
                        }
                        if (wi == (to - 1) >>> 6 && (to & 63) != 0) {
                            m &= (1L << (to & 63)) - 1;
                        }
                        while (m != 0) {
                            int bit = (wi << 6) + Long.numberOfTrailingZeros(m);
                            m &= m - 1;
                            long di = bit - centre;
                            best = Math.min(best, di * di + dj2);
                        }
                    }
                }
                return best <= (long) reach * reach ? best : Float.POSITIVE_INFINITY;
            }
        }

        /** The squared distance (cells) from each cell to the nearest uncut material cell. */
        private float[] toUncut() {
            return edt(nx, ny, i -> (material[i >>> 6] & ~cut[i >>> 6] & (1L << i)) != 0);
        }

        void run(java.util.function.DoubleConsumer progress) throws ToolTooLargeException {
            long floor = 0;
            for (long m : material) {
                floor += Long.bitCount(m);
            }
            long told = System.nanoTime();
            Vec2 at = null;
            Vec2 dir = Vec2.UNIT_X;
            List<Vec2> pts = null;
            Vec2 circleC = null;
            double circleR = 0;
            double reachCells = r / h;
            // a link feeds only where the tool's disc stays a cell clear of uncut floor: its moves are
            // not judged, and one ending within a cell of the floor took that cell's sliver across the
            // tool's front (the first planner's links, up to 38 degrees over the bound)
            double clearedSq = (reachCells + 1) * (reachCells + 1);
            double frontierSq = (reachCells + 1 + 0.5 * stepMm / h) * (reachCells + 1 + 0.5 * stepMm / h);
            while (true) {
                if (Thread.currentThread().isInterrupted()) {
                    // the window's Cancel: the walks stop at their next start
                    throw new java.util.concurrent.CancellationException("adaptive clearing cancelled");
                }
                if (floor > 0 && System.nanoTime() - told > 200_000_000L) {
                    long done = 0;
                    for (int k = 0; k < material.length; k++) {
                        done += Long.bitCount(material[k] & cut[k]);
                    }
                    progress.accept((double) done / floor);
                    told = System.nanoTime();
                }
                UncutDistance du = new UncutDistance(frontierSq);
                int start = -1;
                List<Vec2> link = null;
                if (at != null) {
                    link = linkTo(at, du, clearedSq, frontierSq);
                    if (link != null) {
                        start = cellOf(link.get(link.size() - 1));
                    }
                }
                if (link == null) {
                    if (pts != null && (circleC != null || pts.size() > 1)) {
                        chains.add(new Chain(circleC, circleR, pts));
                    }
                    pts = null;
                    circleC = null;
                    // another place beside uncut floor, reached by a retract and an entry
                    start = nearestFrontier(at, du, clearedSq, frontierSq);
                    if (start >= 0) {
                        pts = new ArrayList<>(List.of(centre(start)));
                    } else {
                        Entry e = newEntry(du, clearedSq);
                        if (e == null) {
                            break;
                        }
                        circleC = e.centre;
                        circleR = climbSense() * e.radius;
                        Vec2 s = e.centre.plus(new Vec2(e.radius, 0));
                        cutDisc(e.centre, e.radius);
                        pts = new ArrayList<>(List.of(s));
                        dir = climbSense() > 0 ? Vec2.UNIT_Y : Vec2.UNIT_Y.negated();
                        at = s;
                        Vec2 end = walk(s, dir, pts);
                        walks++;
                        if (end != null) {
                            dir = end;
                        }
                        at = pts.get(pts.size() - 1);
                        continue;
                    }
                } else {
                    for (int k = 1; k < link.size(); k++) {
                        pts.add(link.get(k));
                    }
                    if (link.size() >= 2) {
                        dir = link.get(link.size() - 1)
                                .minus(link.get(link.size() - 2))
                                .normalized();
                    }
                }
                Vec2 from = pts.get(pts.size() - 1);
                int before = pts.size();
                Vec2 end = walk(from, dir, pts);
                if (end == null) {
                    dead[start] = true;
                    if (link != null) {
                        // the link led nowhere: take it back
                        while (pts.size() > before - link.size() + 1) {
                            pts.remove(pts.size() - 1);
                        }
                    }
                } else {
                    walks++;
                    dir = end;
                }
                at = pts.get(pts.size() - 1);
            }
            leftover();
        }

        private double climbSense() {
            return sense;
        }

        private record Entry(Vec2 centre, double radius) {}

        /** A helix into uncut floor: where the faces leave most room, among places with uncut floor within reach. */
        private Entry newEntry(UncutDistance du, double clearedSq) {
            du.all();
            int n = nx * ny;
            Integer[] order = new Integer[0];
            List<Integer> cand = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                if (isStrict(i) && !dead[i] && du.sq(i) < clearedSq) {
                    cand.add(i);
                }
            }
            order = cand.toArray(order);
            Arrays.sort(order, (p, q) -> {
                int c = Float.compare(clear[q], clear[p]);
                return c != 0 ? c : Integer.compare(p, q);
            });
            for (int k = 0; k < order.length; k++) {
                if (Math.sqrt(clear[order[k]]) * h < 0.5 * r + h) {
                    // by the raster, no place further down the list leaves room for the least helix
                    break;
                }
                Vec2 c = centre(order[k]);
                double room = room(c);
                for (double f : new double[] {1, 0.75, 0.5}) {
                    double rh = f * r;
                    if (room >= rh + 2 * h) {
                        return new Entry(c, rh);
                    }
                }
                dead[order[k]] = true;
            }
            return null;
        }

        /** Whether a helix of half the tool radius about the cell's centre stays inside the faces. */
        private boolean enterable(int i) {
            double need = (0.5 * r + 2 * h) / h;
            return clear[i] >= need * need && room(centre(i)) >= 0.5 * r + 1e-3;
        }

        /** Distance from p to the faces' boundary, inside or out. */
        double distanceToFaces(Vec2 p) {
            double d = Double.POSITIVE_INFINITY;
            for (Contour c : faces) {
                d = Math.min(d, c.distanceTo(p));
            }
            return d;
        }

        /** Distance from p to the faces' boundary, 0 outside. */
        double room(Vec2 p) {
            int wn = 0;
            double d = Double.POSITIVE_INFINITY;
            for (Contour c : faces) {
                wn += c.windingNumber(p);
                d = Math.min(d, c.distanceTo(p));
            }
            return wn != 0 ? d : 0;
        }

        private boolean cleared(UncutDistance du, int i, double clearedSq) {
            return toInside[i] == 0 && du.sq(i) >= clearedSq;
        }

        private boolean frontier(UncutDistance du, int i, double clearedSq, double frontierSq) {
            return cleared(du, i, clearedSq) && !dead[i] && du.sq(i) <= frontierSq;
        }

        /** The positions from at to the nearest frontier along cleared cells (string-pulled), or null. */
        private List<Vec2> linkTo(Vec2 at, UncutDistance du, double clearedSq, double frontierSq) {
            int s = cellOf(at);
            if (s < 0) {
                return null;
            }
            if (parent == null) {
                parent = new int[nx * ny];
                Arrays.fill(parent, -2);
            }
            ArrayDeque<Integer> q = new ArrayDeque<>();
            List<Integer> seen = new ArrayList<>();
            parent[s] = -1;
            seen.add(s);
            q.add(s);
            int found = -1;
            while (!q.isEmpty()) {
                int c = q.poll();
                if (c != s && frontier(du, c, clearedSq, frontierSq)) {
                    found = c;
                    break;
                }
                int ci = c % nx;
                int cj = c / nx;
                for (int dj = -1; dj <= 1; dj++) {
                    for (int di = -1; di <= 1; di++) {
                        int i = ci + di;
                        int j = cj + dj;
                        if ((di | dj) == 0 || i < 0 || j < 0 || i >= nx || j >= ny) {
                            continue;
                        }
                        int k = j * nx + i;
                        if (parent[k] == -2 && cleared(du, k, clearedSq)) {
                            parent[k] = c;
                            seen.add(k);
                            q.add(k);
                        }
                    }
                }
            }
            List<Vec2> path = new ArrayList<>();
            for (int c = found; found >= 0 && c != s && c >= 0; c = parent[c]) {
                path.add(centre(c));
            }
            for (int c : seen) {
                parent[c] = -2;
            }
            if (found < 0) {
                return null;
            }
            path.add(at);
            java.util.Collections.reverse(path);
            // string pulling: the farthest point seen straight along cleared cells
            List<Vec2> out = new ArrayList<>();
            out.add(at);
            int i = 0;
            while (i < path.size() - 1) {
                int j = path.size() - 1;
                while (j > i + 1 && !straightCleared(path.get(i), path.get(j), du, clearedSq)) {
                    j--;
                }
                out.add(path.get(j));
                i = j;
            }
            return out;
        }

        private boolean straightCleared(Vec2 a, Vec2 b, UncutDistance du, double clearedSq) {
            int k = Math.max(1, (int) Math.ceil(a.distance(b) / (h / 3)));
            for (int t = 1; t < k; t++) {
                int c = cellOf(a.interpolate(b, (double) t / k));
                if (c < 0 || !cleared(du, c, clearedSq)) {
                    return false;
                }
            }
            return true;
        }

        /** The frontier cell nearest p anywhere (or the first when p is null), or -1. */
        private int nearestFrontier(Vec2 p, UncutDistance du, double clearedSq, double frontierSq) {
            du.all();
            int best = -1;
            double bestD = Double.POSITIVE_INFINITY;
            for (int i = 0; i < nx * ny; i++) {
                if (frontier(du, i, clearedSq, frontierSq) && enterable(i)) {
                    double d = p == null ? 0 : centre(i).distance(p);
                    if (d < bestD) {
                        bestD = d;
                        best = i;
                    }
                }
            }
            return best;
        }

        /**
         * Follows the pre-finish pass over what the walks left, marking it cut: what a walk could
         * not take at the stepover (a face too small for an entry, the narrow end of a face, a
         * corner the walks turned away from) the pass takes in a wider cut, up to a slot, which
         * the program's measure slows ({@link EngagementFeed}).
         */
        void pass(List<Curve2> curves) {
            for (Vec2[] ch : Coverage.chords(curves)) {
                double len = ch[0].distance(ch[1]);
                if (len < 1e-9) {
                    continue;
                }
                Vec2 u = ch[1].minus(ch[0]).times(1 / len);
                int n = Math.max(1, (int) Math.ceil(len / h));
                for (int k = 1; k <= n; k++) {
                    Vec2 q = ch[0].interpolate(ch[1], (double) k / n);
                    cutDisc(q, 0);
                }
            }
        }

        /** Refuses a plan that leaves material neither a walk nor the pre-finish pass reaches. */
        private void leftover() throws ToolTooLargeException {
            double passReach = (r + 3 * h) / h;
            for (int i = 0; i < nx * ny; i++) {
                boolean uncut = (material[i >>> 6] & ~cut[i >>> 6] & (1L << i)) != 0;
                if (uncut && clear[i] > passReach * passReach) {
                    Vec2 c = centre(i);
                    throw new ToolTooLargeException(String.format(
                            Locale.ROOT,
                            "adaptive clearing cannot reach the floor about X%.3f Y%.3f without a full-width cut"
                                    + " (a neck narrower than the tool can pass at its stepover): use the offset or"
                                    + " zigzag strategy, or a smaller tool",
                            c.x(),
                            c.y()));
                }
            }
        }
    }

    /**
     * The squared Euclidean distance transform (in cells squared) to the nearest feature cell
     * (Felzenszwalb and Huttenlocher's lower envelope of parabolas, rows then columns).
     */
    static float[] edt(int nx, int ny, java.util.function.IntPredicate feature) {
        int n = nx * ny;
        float[] f = new float[n];
        float inf = 1e20f;
        for (int i = 0; i < n; i++) {
            f[i] = feature.test(i) ? 0 : inf;
        }
        int m = Math.max(nx, ny);
        float[] line = new float[m];
        float[] out = new float[m];
        int[] v = new int[m];
        float[] z = new float[m + 1];
        for (int i = 0; i < nx; i++) {
            for (int j = 0; j < ny; j++) {
                line[j] = f[j * nx + i];
            }
            dt(line, ny, out, v, z);
            for (int j = 0; j < ny; j++) {
                f[j * nx + i] = out[j];
            }
        }
        for (int j = 0; j < ny; j++) {
            System.arraycopy(f, j * nx, line, 0, nx);
            dt(line, nx, out, v, z);
            System.arraycopy(out, 0, f, j * nx, nx);
        }
        return f;
    }

    private static void dt(float[] f, int n, float[] d, int[] v, float[] z) {
        int k = 0;
        v[0] = 0;
        z[0] = Float.NEGATIVE_INFINITY;
        z[1] = Float.POSITIVE_INFINITY;
        for (int q = 1; q < n; q++) {
            float s;
            while (true) {
                int p = v[k];
                s = ((f[q] + (float) q * q) - (f[p] + (float) p * p)) / (2f * q - 2f * p);
                if (s <= z[k] && k > 0) {
                    k--;
                } else {
                    break;
                }
            }
            if (s <= z[k]) {
                // k == 0 and the new parabola is lower everywhere
                v[0] = q;
                z[0] = Float.NEGATIVE_INFINITY;
                z[1] = Float.POSITIVE_INFINITY;
                continue;
            }
            k++;
            v[k] = q;
            z[k] = s;
            z[k + 1] = Float.POSITIVE_INFINITY;
        }
        k = 0;
        for (int q = 0; q < n; q++) {
            while (z[k + 1] < q) {
                k++;
            }
            float dq = q - v[k];
            d[q] = dq * dq + f[v[k]];
        }
    }

    /** Douglas-Peucker within tol, then points closer than {@link #MIN_MOVE_MM} to the last kept dropped. */
    static List<Vec2> simplified(List<Vec2> pts, double tol) {
        if (pts.size() <= 2) {
            return dedup(pts);
        }
        boolean[] keep = new boolean[pts.size()];
        keep[0] = true;
        keep[pts.size() - 1] = true;
        ArrayDeque<int[]> stack = new ArrayDeque<>();
        stack.push(new int[] {0, pts.size() - 1});
        while (!stack.isEmpty()) {
            int[] s = stack.pop();
            double worst = -1;
            int at = -1;
            for (int i = s[0] + 1; i < s[1]; i++) {
                double d = Coverage.nearestOnSegment(pts.get(s[0]), pts.get(s[1]), pts.get(i))
                        .distance(pts.get(i));
                if (d > worst) {
                    worst = d;
                    at = i;
                }
            }
            if (at >= 0 && worst > tol) {
                keep[at] = true;
                stack.push(new int[] {s[0], at});
                stack.push(new int[] {at, s[1]});
            }
        }
        List<Vec2> out = new ArrayList<>();
        for (int i = 0; i < pts.size(); i++) {
            if (keep[i]) {
                out.add(pts.get(i));
            }
        }
        return dedup(out);
    }

    private static List<Vec2> dedup(List<Vec2> pts) {
        List<Vec2> out = new ArrayList<>();
        for (Vec2 p : pts) {
            if (out.isEmpty() || out.get(out.size() - 1).distance(p) >= MIN_MOVE_MM) {
                out.add(p);
            }
        }
        if (out.size() > 1 && out.get(out.size() - 1).distance(pts.get(pts.size() - 1)) > 0) {
            out.set(out.size() - 1, pts.get(pts.size() - 1));
        }
        return out;
    }

    private static Toolpath toolpath(
            List<ZigzagPocket.Cut> order,
            List<Contour> finishing,
            List<Contour> inner,
            PocketTechnology t,
            EntryRule rule,
            boolean climb,
            EngagementFeed slow,
            List<Object> owners)
            throws ToolTooLargeException {
        double safe = t.zTopMm() + CLEARANCE_MM;
        Vec2 s0 = order.get(0).start();
        PocketMoves moves = new PocketMoves(new Vec3(s0.x(), s0.y(), safe));
        // a finishing loop in a face of the offset too narrow for the walks goes down inside the
        // finishing faces: anywhere there the tool's centre cuts no wall
        Entries.Room legRoom = (centre, radius) -> {
            int w = 0;
            double d = Double.POSITIVE_INFINITY;
            for (Contour c : finishing) {
                w += c.windingNumber(centre);
                d = Math.min(d, c.distanceTo(centre));
            }
            return w != 0 && d >= radius + 1e-6;
        };
        Entries.Room room = (centre, radius) -> {
            int w = 0;
            double d = Double.POSITIVE_INFINITY;
            for (Contour c : inner) {
                w += c.windingNumber(centre);
                d = Math.min(d, c.distanceTo(centre));
            }
            return w != 0 && d >= radius + 1e-6;
        };
        for (int j = 1; j <= t.depthPasses(); j++) {
            double z = t.zTopMm() - j * t.depthStepMm();
            double above = PocketToolpath.entryTop(t, j);
            Vec2 cursor = null;
            // what this layer has cut so far: a link through it, and only through it, stays down
            Coverage cleared = Coverage.of(finishing, List.of(), t.radiusMm(), RegionPocket.COVERAGE_CELL_MM);
            for (ZigzagPocket.Cut cut : order) {
                Vec2 s = cut.start();
                double feed = cut.finishing() ? t.finishFeedMmPerMin() : t.feedMmPerMin();
                own(owners, j, moves, null);
                if (cursor != null && cursor.distance(s) < MIN_MOVE_MM) {
                    // the cut goes on from where the last ended
                } else if (cursor != null && cleared.clearedAlong(cursor, s, List.of())) {
                    if (cursor.distance(s) >= MIN_MOVE_MM) {
                        moves.add(
                                new Move.Linear(at(s, z), EngagementFeed.feed(t.feedMmPerMin(), slow.linkFactor(cut))));
                        own(owners, j, moves, cut);
                    }
                } else {
                    moves.add(new Move.Rapid(new Vec3(moves.at().x(), moves.at().y(), safe)));
                    moves.add(new Move.Rapid(at(s, safe)));
                    moves.add(new Move.Rapid(at(s, above)));
                    org.fresa.pocket.Entry entry = Entries.choose(
                                    rule, s, cut.curves(), List.of(), climb, room, legRoom, t.radiusMm(), above - z)
                            .orElseThrow(() -> Entries.tooSmallToGoDown(s));
                    moves.addAll(entry.moves(above, z, t.feedMmPerMin()));
                }
                own(owners, j, moves, null);
                for (Curve2 c : cut.curves()) {
                    if (c.length() >= MIN_MOVE_MM) {
                        for (EngagementFeed.Piece piece : slow.pieces(c)) {
                            RegionPocket.emit(moves, piece.curve(), z, z, EngagementFeed.feed(feed, piece.factor()));
                        }
                        own(owners, j, moves, c);
                    }
                }
                if (moves.size() > PocketTechnology.MAX_MOVES) {
                    throw new ToolTooLargeException("the program would have more than " + PocketTechnology.MAX_MOVES
                            + " moves: use a larger depth per pass, a larger entry angle or a larger tool");
                }
                cleared.cutAlong(cut.curves());
                cursor = cut.end();
            }
        }
        moves.add(new Move.Rapid(new Vec3(moves.at().x(), moves.at().y(), safe)));
        ToolpathSection section = new ToolpathSection(
                "pocket", Z, t.toolDiameterMm(), 1, t.spindleRpm(), new Vec3(s0.x(), s0.y(), safe), moves.list());
        return new Toolpath(List.of(section));
    }

    /** Records, at the first depth layer, what the moves from {@code from} on were made for. */
    private static void own(List<Object> owners, int layer, PocketMoves moves, Object owner) {
        if (owners == null || layer != 1) {
            return;
        }
        for (int i = owners.size(); i < moves.size(); i++) {
            owners.add(owner);
        }
    }

    private static Vec3 at(Vec2 p, double z) {
        return new Vec3(p.x(), p.y(), z);
    }
}
