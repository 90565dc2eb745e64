package org.fresa.pocket;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Intersections;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

/**
 * Zigzag pocketing of a region with islands: parallel straight lines at an angle clear the floor,
 * then the contour passes of {@link RegionPocket} (the pre-finish offset R + a, then the
 * finishing offset R, arcs as arcs) clean the walls. Units mm and degrees.
 *
 * <p>The lines are the region offset by R + a (the tool's centre never comes nearer a wall or an
 * island than the radius and the finishing allowance), cut by lines at the given angle, equally
 * spaced at no more than the stepover (and below 0.95 D, so that no ridge stands between two
 * neighbours), the outermost half a spacing in from the offset's extremes. No uncut material, by
 * construction: a point at least 2R + a from the boundary lies within half a spacing (at most R)
 * of a line whose point beside it is at least R + a from the boundary, so inside the lines'
 * region; a point nearer the boundary is within the pre-finish pass's reach (which runs on
 * delta = R + a and clears a &lt;= delta &lt;= 2R + a) or the finishing pass's (0 to 2R).
 *
 * <p>Order: the lines are taken from one side to the other, alternating in direction; from the
 * end of one line the tool follows the pre-finish offset to the next line's nearer end when that
 * stretch of the offset stays between the two lines (so it passes no other line), otherwise the
 * chain ends. A chain is joined to the next by a straight feed move when the tool's disc along it
 * stays in material already cut ({@link Coverage#clearedAlong}) or it is short and inside the
 * finishing offset, else by a retract, a rapid and an entry ({@link Entries}: a helix where the
 * pre-finish offset holds one, else a zig-zag ramp along the chain, a plunge only for a
 * centre-cutting tool asked to). The zigzag lines cut climb and conventional in turn; the contour
 * passes follow the milling direction asked for.
 */
public final class ZigzagPocket {

    private static final Tolerance TOL = Tolerance.DEFAULT;
    private static final Vec3 Z = new Vec3(0, 0, 1);
    private static final double CLEARANCE_MM = 5;

    /** The largest spacing of the lines as a fraction of the diameter: neighbours overlap, no ridge between. */
    static final double MAX_STEP_FRACTION = 0.95;

    /** A span of a line shorter than this (mm) is left to the contour passes (it grazes the offset's extreme). */
    static final double MIN_SPAN_MM = 1e-3;

    /**
     * One cut in machining order: a chain of zigzag lines and their links, or a closed contour pass.
     *
     * @param closed a contour pass (ends where it starts)
     * @param finishing the finishing pass at R (finishing feed)
     * @param curves the path of the tool's centre at the floor
     */
    public record Cut(boolean closed, boolean finishing, List<Curve2> curves) {
        public Cut {
            curves = List.copyOf(curves);
        }

        public Vec2 start() {
            return curves.get(0).start();
        }

        public Vec2 end() {
            return curves.get(curves.size() - 1).end();
        }
    }

    /**
     * The plan.
     *
     * @param finishing the loops of the finishing offset (R)
     * @param lines how many spans of zigzag lines are cut
     * @param order the cuts in machining order at each depth
     * @param toolpath the moves
     */
    public record Plan(List<Contour> finishing, int lines, List<Cut> order, Toolpath toolpath) {
        public Plan {
            finishing = List.copyOf(finishing);
            order = List.copyOf(order);
        }
    }

    /** One inside stretch of a line: from its lower to its upper end along the lines' direction. */
    private record Span(int line, Vec2 from, Vec2 to) {}

    private ZigzagPocket() {}

    /**
     * Plans the pocket.
     *
     * @param outer the outer contour (either orientation)
     * @param islands closed contours inside it (either orientation), not touching it or each other
     * @param tech the technology (tool, stepover, allowance, depths, feeds)
     * @param angleDeg the lines' direction, counter-clockwise from +X (deg)
     * @param climb climb milling of the contour passes (true) or conventional
     * @param entry the entries allowed
     * @throws ToolTooLargeException when the tool does not fit anywhere in the region, an entry
     *     has no room, or the program would have too many moves
     */
    public static Plan plan(
            Contour outer,
            List<Contour> islands,
            PocketTechnology tech,
            double angleDeg,
            boolean climb,
            EntryRule entry)
            throws ToolTooLargeException {
        return plan(RegionOffsetter.oriented(outer, islands), tech, angleDeg, climb, entry);
    }

    /**
     * Plans the pocket of a region given by its boundary.
     *
     * @param boundary the region's loops with the region on their left ({@link RegionOffsetter#oriented}),
     *     any number of faces
     * @throws ToolTooLargeException as {@link #plan(Contour, List, PocketTechnology, double, boolean, EntryRule)}
     */
    public static Plan plan(
            List<Contour> boundary, PocketTechnology tech, double angleDeg, boolean climb, EntryRule entry)
            throws ToolTooLargeException {
        double r = tech.radiusMm();
        double a = tech.finishFraction() * tech.toolDiameterMm();
        List<Contour> finishing = RegionOffsetter.inward(boundary, r, TOL);
        if (finishing.isEmpty()) {
            throw new ToolTooLargeException("the tool (" + tech.toolDiameterMm()
                    + " mm) does not fit anywhere in the pocket: use a smaller tool");
        }
        boolean preFinish = a > 1e-9;
        List<Contour> inner = preFinish ? RegionOffsetter.inward(boundary, r + a, TOL) : finishing;
        List<Cut> order = new ArrayList<>();
        int lines = 0;
        if (!inner.isEmpty()) {
            double step = Math.min(tech.effectiveCut(), MAX_STEP_FRACTION) * tech.toolDiameterMm();
            Vec2 u = Vec2.ofAngle(Math.toRadians(angleDeg));
            Vec2 n = u.leftNormal();
            double[] ys = levels(inner, n, step);
            List<List<Span>> spans = new ArrayList<>();
            for (int k = 0; k < ys.length; k++) {
                List<Span> line = spans(inner, u, n, ys[k], k);
                lines += line.size();
                spans.add(line);
            }
            chains(spans, ys, n, inner, order);
        }
        Vec2 cursor = order.isEmpty() ? null : order.get(order.size() - 1).end();
        if (preFinish && !inner.isEmpty()) {
            cursor = loops(inner, false, climb, cursor, order);
        }
        loops(finishing, true, climb, cursor, order);
        // each element once cut and once ramped down, some arcs halved, and a link or rapids and an entry per cut
        tech.checkMoves(
                order.stream().mapToLong(c -> 3L * c.curves().size() + 4).sum());
        Toolpath path = toolpath(order, finishing, inner.isEmpty() ? finishing : inner, tech, entry, climb);
        return new Plan(finishing, lines, order, path);
    }

    /** The lines' heights along n: equally spaced at most step apart, half a spacing in from the extremes. */
    static double[] levels(List<Contour> loops, Vec2 n, double step) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (Contour c : loops) {
            for (Curve2 k : c.curves()) {
                for (Vec2 p : List.of(k.start(), k.end())) {
                    lo = Math.min(lo, p.dot(n));
                    hi = Math.max(hi, p.dot(n));
                }
                if (k instanceof Arc2 arc) {
                    double rr = arc.radius();
                    double up = n.angleRad();
                    if (arc.containsAngle(up)) {
                        hi = Math.max(hi, arc.center().dot(n) + rr);
                    }
                    if (arc.containsAngle(up + Math.PI)) {
                        lo = Math.min(lo, arc.center().dot(n) - rr);
                    }
                }
            }
        }
        int count = Math.max(1, (int) Math.ceil((hi - lo) / step - 1e-9));
        double h = (hi - lo) / count;
        double[] out = new double[count];
        for (int k = 0; k < count; k++) {
            out[k] = lo + (k + 0.5) * h;
        }
        return out;
    }

    /** The stretches of the line {p : p.n = y} inside the loops, in order along u. */
    private static List<Span> spans(List<Contour> loops, Vec2 u, Vec2 n, double y, int index) {
        Box2 box = loops.get(0).bounds();
        for (Contour c : loops) {
            box = box.union(c.bounds());
        }
        double half = Math.hypot(box.width(), box.height()) + 1;
        Vec2 mid = new Vec2((box.minX() + box.maxX()) / 2, (box.minY() + box.maxY()) / 2);
        Vec2 foot = mid.plus(n.times(y - mid.dot(n)));
        Segment2 line = new Segment2(foot.minus(u.times(half)), foot.plus(u.times(half)));
        Tolerance tol = new Tolerance(1e-9, 1e-12);
        List<Vec2> hits = new ArrayList<>();
        for (Contour c : loops) {
            for (Curve2 k : c.curves()) {
                hits.addAll(Intersections.of(line, k, tol));
            }
        }
        hits.sort((p, q) -> Double.compare(p.dot(u), q.dot(u)));
        List<Vec2> xs = new ArrayList<>();
        for (Vec2 p : hits) {
            if (xs.isEmpty() || p.dot(u) - xs.get(xs.size() - 1).dot(u) > 1e-7) {
                xs.add(p);
            }
        }
        List<Span> out = new ArrayList<>();
        Vec2 open = null;
        for (int i = 0; i + 1 < xs.size(); i++) {
            Vec2 m = xs.get(i).interpolate(xs.get(i + 1), 0.5);
            int w = 0;
            for (Contour c : loops) {
                w += c.windingNumber(m);
            }
            if (w != 0) {
                // a point where the line only grazes a loop joins the stretches on either side
                open = open == null ? xs.get(i) : open;
                continue;
            }
            if (open != null) {
                addSpan(out, index, open, xs.get(i));
                open = null;
            }
        }
        if (open != null) {
            addSpan(out, index, open, xs.get(xs.size() - 1));
        }
        return out;
    }

    private static void addSpan(List<Span> out, int index, Vec2 from, Vec2 to) {
        if (from.distance(to) >= MIN_SPAN_MM) {
            out.add(new Span(index, from, to));
        }
    }

    /** The spans in chains: up from the lowest line left, each line's span joined along the offset to the next's. */
    private static void chains(List<List<Span>> spans, double[] ys, Vec2 n, List<Contour> loops, List<Cut> order) {
        List<List<Span>> left = new ArrayList<>();
        for (List<Span> l : spans) {
            left.add(new ArrayList<>(l));
        }
        Vec2 at = null;
        while (true) {
            int k = 0;
            while (k < left.size() && left.get(k).isEmpty()) {
                k++;
            }
            if (k == left.size()) {
                return;
            }
            Span first = left.get(k).get(0);
            boolean forward = true;
            if (at != null) {
                double best = Double.POSITIVE_INFINITY;
                for (Span s : left.get(k)) {
                    for (boolean fw : new boolean[] {true, false}) {
                        double d = (fw ? s.from() : s.to()).distance(at);
                        if (d < best) {
                            best = d;
                            first = s;
                            forward = fw;
                        }
                    }
                }
            }
            left.get(k).remove(first);
            List<Curve2> curves = new ArrayList<>();
            Vec2 end = forward ? first.to() : first.from();
            curves.add(new Segment2(forward ? first.from() : first.to(), end));
            while (k + 1 < left.size()) {
                List<Curve2> bestLink = null;
                Span next = null;
                boolean nextForward = true;
                double bestLen = Double.POSITIVE_INFINITY;
                for (Span s : left.get(k + 1)) {
                    for (boolean fw : new boolean[] {true, false}) {
                        Vec2 p = fw ? s.from() : s.to();
                        List<Curve2> link = alongOffset(loops, end, p, ys[k], ys[k + 1], n);
                        double len = link == null
                                ? Double.POSITIVE_INFINITY
                                : link.stream().mapToDouble(Curve2::length).sum();
                        if (len < bestLen) {
                            bestLen = len;
                            bestLink = link;
                            next = s;
                            nextForward = fw;
                        }
                    }
                }
                if (next == null) {
                    break;
                }
                left.get(k + 1).remove(next);
                curves.addAll(bestLink);
                Vec2 from = nextForward ? next.from() : next.to();
                end = nextForward ? next.to() : next.from();
                curves.add(new Segment2(from, end));
                k++;
            }
            order.add(new Cut(false, false, curves));
            at = end;
        }
    }

    /**
     * The stretch of the offset loop through both points that stays between the two lines (the
     * shorter when both ways do), or null when there is none: the points lie on different loops,
     * or each way round passes beyond a line.
     */
    static List<Curve2> alongOffset(List<Contour> loops, Vec2 e, Vec2 p, double y0, double y1, Vec2 n) {
        for (Contour loop : loops) {
            double pe = position(loop, e);
            double pp = position(loop, p);
            if (Double.isNaN(pe) || Double.isNaN(pp)) {
                continue;
            }
            double total = loop.length();
            List<Curve2> fw = stretch(loop, pe, pp < pe ? pp + total : pp, e, p);
            List<Curve2> bw = reversed(stretch(loop, pp, pe < pp ? pe + total : pe, p, e));
            double lo = Math.min(y0, y1) - 1e-6;
            double hi = Math.max(y0, y1) + 1e-6;
            List<Curve2> best = null;
            double bestLen = Double.POSITIVE_INFINITY;
            for (List<Curve2> c : List.of(fw, bw)) {
                double len = c.stream().mapToDouble(Curve2::length).sum();
                if (within(c, n, lo, hi) && len < bestLen) {
                    best = c;
                    bestLen = len;
                }
            }
            return best;
        }
        return null;
    }

    private static boolean within(List<Curve2> path, Vec2 n, double lo, double hi) {
        for (Curve2 c : path) {
            for (int i = 0; i <= 16; i++) {
                double y = c.pointAt(i / 16.0).dot(n);
                if (y < lo || y > hi) {
                    return false;
                }
            }
        }
        return true;
    }

    /** The arc-length position of p on the loop from its start, or NaN when p is not on it. */
    static double position(Contour loop, Vec2 p) {
        double best = Double.POSITIVE_INFINITY;
        double at = Double.NaN;
        double done = 0;
        for (Curve2 c : loop.curves()) {
            double d = c.distanceTo(p);
            if (d < best) {
                best = d;
                double t = Math.max(0, Math.min(1, OffsetSplit.param(c, p)));
                at = done + t * c.length();
            }
            done += c.length();
        }
        return best <= 1e-6 ? at : Double.NaN;
    }

    /** The loop from position a to position b (b >= a, b < a + length), starting exactly at pa and ending at pb. */
    private static List<Curve2> stretch(Contour loop, double a, double b, Vec2 pa, Vec2 pb) {
        List<Curve2> out = new ArrayList<>();
        double done = 0;
        for (int round = 0; round < 2; round++) {
            for (Curve2 c : loop.curves()) {
                double len = c.length();
                double s = done;
                double e = done + len;
                done = e;
                double lo = Math.max(a, s);
                double hi = Math.min(b, e);
                if (hi - lo <= 1e-9 || len <= 0) {
                    continue;
                }
                Vec2 from = lo - a <= 1e-9 ? pa : c.pointAt((lo - s) / len);
                Vec2 to = b - hi <= 1e-9 ? pb : c.pointAt((hi - s) / len);
                if (from.distance(to) > 1e-9 || (c instanceof Arc2 && hi - lo > 1e-6)) {
                    out.add(RegionPocket.piece(c, from, to));
                }
            }
        }
        return out;
    }

    private static List<Curve2> reversed(List<Curve2> path) {
        List<Curve2> out = new ArrayList<>();
        for (int i = path.size() - 1; i >= 0; i--) {
            out.add(path.get(i).reversed());
        }
        return out;
    }

    /** Adds the loops as closed cuts, nearest first, each started near the tool; returns where the tool ends. */
    static Vec2 loops(List<Contour> loops, boolean finishing, boolean climb, Vec2 cursor, List<Cut> order) {
        List<Contour> pending = new ArrayList<>(loops);
        Vec2 at = cursor;
        while (!pending.isEmpty()) {
            int best = 0;
            double bestD = Double.POSITIVE_INFINITY;
            for (int i = 0; i < pending.size() && at != null; i++) {
                double d = pending.get(i).distanceTo(at);
                if (d < bestD) {
                    bestD = d;
                    best = i;
                }
            }
            Contour l = pending.remove(best);
            Contour directed = climb ? l : l.reversed();
            Contour started = at == null ? directed : RegionPocket.startedNear(directed, at);
            order.add(new Cut(true, finishing, RegionPocket.halved(started).curves()));
            at = started.get(0).start();
        }
        return at;
    }

    private static Toolpath toolpath(
            List<Cut> order,
            List<Contour> finishing,
            List<Contour> inner,
            PocketTechnology t,
            EntryRule rule,
            boolean climb)
            throws ToolTooLargeException {
        double safe = t.zTopMm() + CLEARANCE_MM;
        Vec2 s0 = order.get(0).start();
        PocketMoves moves = new PocketMoves(new Vec3(s0.x(), s0.y(), safe));
        RegionPocket.Level finish = new RegionPocket.Level(t.radiusMm(), finishing);
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
            // what this layer has cut so far: a link through it stays down
            Coverage cleared = Coverage.of(finishing, List.of(), t.radiusMm(), RegionPocket.COVERAGE_CELL_MM);
            for (int i = 0; i < order.size(); i++) {
                Cut cut = order.get(i);
                Vec2 s = cut.start();
                double feed = cut.finishing() ? t.finishFeedMmPerMin() : t.feedMmPerMin();
                if (cursor != null
                        && (RegionPocket.feedLink(cursor, s, finish, 2 * t.toolDiameterMm())
                                || cleared.clearedAlong(cursor, s, cut.curves()))) {
                    moves.add(new Move.Linear(at(s, z), t.feedMmPerMin()));
                } else {
                    moves.add(new Move.Rapid(new Vec3(moves.at().x(), moves.at().y(), safe)));
                    moves.add(new Move.Rapid(at(s, safe)));
                    moves.add(new Move.Rapid(at(s, above)));
                    Entry entry = Entries.choose(
                                    rule,
                                    s,
                                    cut.curves(),
                                    onwards(order, i, finish, t),
                                    climb,
                                    room,
                                    room,
                                    t.radiusMm(),
                                    above - z)
                            .orElseThrow(() -> Entries.tooSmallToGoDown(s));
                    moves.addAll(entry.moves(above, z, t.feedMmPerMin()));
                }
                for (Curve2 c : cut.curves()) {
                    RegionPocket.emit(moves, c, z, z, feed);
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

    /**
     * What the tool surely follows at depth after cut i: the cuts after it joined by a straight
     * feed inside the finishing offset ({@link RegionPocket#feedLink}, which stays down whatever
     * the layer has cut), with their links, as far as a ramp's legs could need (the tool's
     * diameter, 4 times over).
     */
    private static List<Curve2> onwards(List<Cut> order, int i, RegionPocket.Level finish, PocketTechnology t) {
        List<Curve2> out = new ArrayList<>();
        double length = 0;
        for (int j = i + 1; j < order.size() && length < 4 * t.toolDiameterMm(); j++) {
            Vec2 from = order.get(j - 1).end();
            Vec2 to = order.get(j).start();
            if (!RegionPocket.feedLink(from, to, finish, 2 * t.toolDiameterMm())) {
                break;
            }
            if (from.distance(to) > 1e-9) {
                out.add(new Segment2(from, to));
            }
            out.addAll(order.get(j).curves());
            length += from.distance(to)
                    + order.get(j).curves().stream().mapToDouble(Curve2::length).sum();
        }
        return out;
    }

    private static Vec3 at(Vec2 p, double z) {
        return new Vec3(p.x(), p.y(), z);
    }
}
