package org.fresa.cutting;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.pocket.LineArcOffsetter;

/**
 * Plans the cutting of a sheet drawing: chains the drawing's curves (per layer) into contours,
 * sorts them into parts and holes by containment (even nesting depth: outside of a part; odd:
 * hole; a part inside a hole is cut before that hole), orients them (outer contours clockwise
 * and holes counter-clockwise by default, so the scrap is on the left), offsets each by half the
 * kerf into the scrap with {@link LineArcOffsetter}, chooses pierce points and leads that stay in
 * the scrap, orders the pierces ({@link CutOrder}: holes before their part, a nearest-neighbour
 * tour improved by 2-opt and Or-opt moves between parts, never longer than the plain
 * nearest-neighbour tour) and produces the tool-centre path.
 *
 * <p>Pierce point rule: the middle of the longest straight element of the cut path, then the
 * next longest, then corners, then the middle of arcs; the first where a lead fits (tried at its
 * full length, a half and a quarter) wins. A lead fits when every point of it stays at least half
 * the kerf from every drawn contour, so the jet never touches a part.
 */
public final class CutPlanner {

    private static final Tolerance TOL = Tolerance.DEFAULT;
    /** Most elements one contour may have to be offset. */
    static final int MAX_CONTOUR_ELEMENTS = 20_000;
    /**
     * Most moves looked at while shortening the cut order once the nearest-neighbour order is
     * found: about 3 s of CPU here (70 ns a move on random tours of 2 000 to 100 000 cuts).
     * A drawing of 20 000 cuts still stops when no move helps; 2 000 random cuts need 9 million.
     */
    static final long ORDER_MAX_WORK = 45_000_000L;

    private CutPlanner() {}

    /** A closed contour with its place in the containment tree. */
    private static final class Node {
        final Contour contour;
        final double area;
        final Box2 box;
        Node parent;
        int depth;
        final List<Node> children = new ArrayList<>();
        final List<CutPath> cuts = new ArrayList<>();
        int index;

        Node(Contour c, double area) {
            this.contour = c;
            this.area = area;
            this.box = c.bounds();
        }

        boolean outer() {
            return depth % 2 == 0;
        }
    }

    public static CutPlan plan(Map<String, List<Curve2>> layers, CuttingOptions o) {
        return plan(layers, o, (f, what) -> {});
    }

    /** How far the planning is: a fraction from 0 to 1 and the step under way, in the planner's words. */
    @FunctionalInterface
    public interface Progress {
        void at(double fraction, String step);
    }

    /** Plans as {@link #plan(Map, CuttingOptions)}, telling how far it is (a big sheet takes a while). */
    public static CutPlan plan(Map<String, List<Curve2>> layers, CuttingOptions o, Progress progress) {
        return plan(layers, o, CutOrderOverride.NONE, progress);
    }

    /**
     * Plans as {@link #plan(Map, CuttingOptions, Progress)}, then lays the planner's own order and
     * start points over the automatic ones ({@link CutOrderOverride}).
     *
     * @throws CutOrderOverride.Refused when the override cuts a contour before one inside it
     */
    public static CutPlan plan(
            Map<String, List<Curve2>> layers, CuttingOptions o, CutOrderOverride override, Progress progress) {
        progress.at(0, "chaining the drawing into contours");
        List<String> warnings = new ArrayList<>();
        List<Contour> closed = new ArrayList<>();
        List<List<Curve2>> open = new ArrayList<>();
        int dups = 0;
        int zero = 0;
        int junctions = 0;
        List<Chainer.Gap> gaps = new ArrayList<>();
        double joint = Math.min(CuttingOptions.JOINT_MM, o.gapToleranceMm());
        for (Map.Entry<String, List<Curve2>> e : layers.entrySet()) {
            Chainer.Chains ch = o.paperMode()
                    ? Chainer.chainPaper(e.getValue(), 1e-4)
                    : Chainer.chain(e.getValue(), joint, o.gapToleranceMm());
            closed.addAll(ch.closed());
            open.addAll(ch.open());
            dups += ch.duplicates();
            zero += ch.zeroLength();
            junctions += ch.junctions();
            gaps.addAll(ch.gaps());
        }
        for (Chainer.Gap g : gaps) {
            warnings.add(String.format(
                    Locale.ROOT,
                    "gap of %.4f mm between two ends closed at (%.3f, %.3f)",
                    g.widthMm(),
                    g.at().x(),
                    g.at().y()));
        }
        if (dups > 0) {
            warnings.add(dups + " duplicate elements removed");
        }
        if (zero > 0) {
            warnings.add(zero + " zero-length elements removed");
        }
        if (junctions > 0) {
            warnings.add(junctions + " nodes where more than two element ends meet (the nearest end was followed)");
        }
        List<Vec2> ends = new ArrayList<>();
        for (List<Curve2> chain : open) {
            ends.add(chain.get(0).start());
            ends.add(chain.get(chain.size() - 1).end());
        }
        for (int k = 0; k < open.size(); k++) {
            List<Curve2> chain = open.get(k);
            Vec2 a = ends.get(2 * k);
            Vec2 b = ends.get(2 * k + 1);
            String why = String.format(Locale.ROOT, "its ends are %.4g mm apart", a.distance(b));
            if (ends.size() <= 4000) {
                // the gap tolerance that would join both ends to something: the farther of their nearest other ends
                double need = Math.max(nearestOther(ends, 2 * k), nearestOther(ends, 2 * k + 1));
                why = String.format(
                        Locale.ROOT,
                        "its ends are %.4g mm from the nearest other end (a gap tolerance of"
                                + " %.4g mm would join them)",
                        need,
                        need * 1.001);
            }
            warnings.add(String.format(
                    Locale.ROOT,
                    "open chain of %d elements from (%.3f, %.3f) to (%.3f, %.3f) not cut: %s",
                    chain.size(),
                    a.x(),
                    a.y(),
                    b.x(),
                    b.y(),
                    why));
        }
        progress.at(0.1, "nesting " + closed.size() + " contours into parts and holes");
        List<Node> nodes = classify(closed, o.paperMode());
        List<Curve2> all = new ArrayList<>();
        for (Contour c : closed) {
            all.addAll(c.curves());
        }
        double half = o.kerfMm() / 2;
        Box2 ext = null;
        for (Curve2 c : all) {
            ext = ext == null ? c.bounds() : ext.union(c.bounds());
        }
        double cell =
                ext == null ? 10 : Math.max(1, Math.sqrt(ext.width() * ext.height() / Math.max(1, all.size())) * 2);
        CurveGrid grid = new CurveGrid(all, cell);
        List<Vec2> invalid = new ArrayList<>();
        List<Contour> uncut = new ArrayList<>();
        List<CutPlan.NotCut> notCut = new ArrayList<>();
        List<Contour> outers = new ArrayList<>();
        List<Contour> holes = new ArrayList<>();
        int partNo = 0;
        for (Node n : nodes) {
            if (n.outer()) {
                n.index = ++partNo;
            }
        }
        int done = 0;
        for (Node n : nodes) {
            if (++done % 5000 == 0) {
                progress.at(
                        0.15 + 0.35 * done / nodes.size(),
                        "offsetting by the kerf and placing leads: contour " + done + " of " + nodes.size());
            }
            boolean outer = n.outer();
            (outer ? outers : holes).add(n.contour);
            String label = outer
                    ? "part " + n.index
                    : "part " + n.parent.index + " hole " + (n.parent.children.indexOf(n) + 1);
            if (n.contour.size() > MAX_CONTOUR_ELEMENTS) {
                // the offset compares every piece with every element: such a contour would not finish
                notCut(
                        label,
                        n.contour,
                        "has " + n.contour.size() + " elements, more than the " + MAX_CONTOUR_ELEMENTS
                                + " a contour may have (simplify the drawing)",
                        uncut,
                        notCut,
                        warnings);
                continue;
            }
            Contour oriented =
                    o.paperMode() ? n.contour : orient(n.contour, outer ? o.outerClockwise() : o.holesClockwise());
            if (o.paperMode()) {
                boolean toolLeft = outer ^ oriented.isCcw();
                if (!outer) {
                    oriented = startNearCorner(oriented);
                }
                PaperCrc.Result r = half > 0
                        ? PaperCrc.offset(oriented, half, toolLeft)
                        : new PaperCrc.Result(java.util.Optional.of(oriented), List.of());
                invalid.addAll(r.invalidVertices());
                for (Vec2 v : r.invalidVertices()) {
                    warnings.add(String.format(
                            Locale.ROOT,
                            "invalid vertex of %s at (%.3f, %.3f): a corner the kerf"
                                    + " cannot follow on the nozzle's side (round it with an arc in the drawing)",
                            label,
                            v.x(),
                            v.y()));
                }
                if (r.path().isEmpty()) {
                    notCut(label, n.contour, "collapses under the kerf", uncut, notCut, warnings);
                } else {
                    n.cuts.add(new CutPath(label, outer, n.contour, r.path().get(), List.of(), List.of(), 0));
                }
                continue;
            }
            boolean scrapLeft = outer ? !oriented.isCcw() : oriented.isCcw();
            List<Contour> loops =
                    half > 0 ? LineArcOffsetter.offset(oriented, outer ? half : -half, TOL) : List.of(oriented);
            if (o.controllerCompensation() && !loops.isEmpty()) {
                // G41/G42 on the drawn contour, when the controller can do it: no arc on the tool's
                // side tighter than the kerf radius, and an entry move longer than that radius
                CutPath cp = tighterArc(oriented, scrapLeft, half)
                        ? null
                        : withLeads(
                                label,
                                outer,
                                n.contour,
                                oriented,
                                scrapLeft,
                                o,
                                half,
                                grid,
                                warnings,
                                scrapLeft ? 41 : 42,
                                Optional.empty());
                if (cp != null && (!cp.leadIn().isEmpty() || half == 0)) {
                    n.cuts.add(cp);
                    continue;
                }
                warnings.add(label + place(n.contour)
                        + ": cannot be cut under G41/G42 (an arc tighter than the kerf radius, or no room"
                        + " for an entry move longer than it); cut on the offset path instead");
            }
            List<Contour> same = new ArrayList<>();
            for (Contour l : loops) {
                if (l.isCcw() == oriented.isCcw()) {
                    same.add(l);
                }
            }
            if (same.isEmpty()) {
                notCut(
                        label,
                        n.contour,
                        String.format(Locale.ROOT, "is too small for a %.3f mm kerf", o.kerfMm()),
                        uncut,
                        notCut,
                        warnings);
                continue;
            }
            if (outer && loops.size() > same.size()) {
                warnings.add(label + place(n.contour)
                        + " has a slot or gap narrower than the kerf: it closes up and is not cut");
            }
            if (!outer && same.size() > 1) {
                warnings.add(label + place(n.contour) + " has a waist narrower than the kerf: cut as " + same.size()
                        + " separate loops");
            }
            for (int k = 0; k < same.size(); k++) {
                String l = same.size() > 1 ? label + "." + (k + 1) : label;
                n.cuts.add(withLeads(
                        l, outer, n.contour, same.get(k), scrapLeft, o, half, grid, warnings, 0, Optional.empty()));
            }
        }
        List<Asked> asked = resolve(override, nodes, warnings);
        java.util.Set<String> pinned = startsAsked(asked, o, half, grid, warnings);
        // the lead test's grid and its list of every drawn curve are done with: on a big sheet
        // they are 40 MB the ordering, the routing and the post need
        grid = null;
        all = null;
        progress.at(0.5, "looking for contours that cross");
        crossings(nodes, warnings);
        progress.at(0.55, "ordering the pierces");
        List<CutPath> order = o.paperMode() ? paperOrder(nodes) : order(nodes, pinned);
        if (!override.isEmpty()) {
            order = overridden(order, asked, nodes, o, pinned, warnings);
        }
        progress.at(0.75, "routing the rapids around cut parts");
        List<List<Vec2>> rapids = rapids(order, o, warnings);
        return new CutPlan(
                order,
                outers,
                holes,
                open,
                invalid,
                warnings,
                uncut,
                dups,
                zero,
                rapids,
                notCut,
                o.feedMmPerMin(),
                o.kerfMm());
    }

    /** The distance from end i to the nearest other end of an open chain (its own other end included). */
    private static double nearestOther(List<Vec2> ends, int i) {
        double best = Double.POSITIVE_INFINITY;
        for (int j = 0; j < ends.size(); j++) {
            if (j != i) {
                best = Math.min(best, ends.get(i).distance(ends.get(j)));
            }
        }
        return best;
    }

    /** " (W x H mm at X, Y)": a contour's size and the lower left corner of its box, for messages. */
    static String place(Contour c) {
        Box2 b = c.bounds();
        return String.format(Locale.ROOT, " (%.3f x %.3f mm at %.3f, %.3f)", b.width(), b.height(), b.minX(), b.minY());
    }

    private static void notCut(
            String label,
            Contour c,
            String reason,
            List<Contour> uncut,
            List<CutPlan.NotCut> notCut,
            List<String> warnings) {
        uncut.add(c);
        notCut.add(new CutPlan.NotCut(label, c, reason));
        warnings.add(label + place(c) + " " + reason + ": not cut");
    }

    // ------------------------------------------------------------------ classification

    /**
     * Warns about drawn contours that cross each other: their cuts cannot avoid touching. The
     * pairs of curves are taken in the order of a sweep along x (by the left side of their boxes),
     * each curve with the later ones whose boxes meet its own; those are found in a grid of cells
     * about a curve's size, since a sweep alone meets every curve of a column of parts: on the
     * 181 750 squares of the 50 MB sheet, whose columns share their left sides, it made 900
     * million box tests (12 s).
     */
    private static void crossings(List<Node> nodes, List<String> warnings) {
        List<Curve2> curves = new ArrayList<>();
        for (Node node : nodes) {
            curves.addAll(node.contour.curves());
        }
        int n = curves.size();
        int[] owner = new int[n];
        double[] minX = new double[n];
        double[] minY = new double[n];
        double[] maxX = new double[n];
        double[] maxY = new double[n];
        for (int i = 0, c = 0; i < nodes.size(); i++) {
            for (int k = nodes.get(i).contour.size(); k > 0; k--, c++) {
                owner[c] = i;
                Box2 b = curves.get(c).bounds();
                minX[c] = b.minX();
                minY[c] = b.minY();
                maxX[c] = b.maxX();
                maxY[c] = b.maxY();
            }
        }
        int[] order = IndexSort.byKey(minX);
        int[] rank = new int[n];
        for (int a = 0; a < n; a++) {
            rank[order[a]] = a;
        }
        SweepGrid grid = new SweepGrid(minX, minY, maxX, maxY);
        Tolerance t = new Tolerance(1e-7, 1e-12);
        java.util.Set<Long> reported = new java.util.HashSet<>();
        for (int a = 0; a < n; a++) {
            int i = order[a];
            // the curves after i in the sweep that it would meet before the sweep passes its right side
            int[] later = grid.meeting(i, j -> rank[j] > rank[i] && minX[j] <= maxX[i]);
            for (int m = 0; m < later.length; m++) {
                later[m] = rank[later[m]];
            }
            java.util.Arrays.sort(later);
            for (int b : later) {
                int j = order[b];
                int oi = owner[i];
                int oj = owner[j];
                if (oi == oj) {
                    continue;
                }
                long key = ((long) Math.min(oi, oj) << 32) + Math.max(oi, oj);
                if (reported.contains(key)
                        || org.fresa.geom.Intersections.of(curves.get(i), curves.get(j), t)
                                .isEmpty()) {
                    continue;
                }
                reported.add(key);
                if (reported.size() <= 20) {
                    Vec2 p = org.fresa.geom.Intersections.of(curves.get(i), curves.get(j), t)
                            .get(0);
                    warnings.add(String.format(
                            Locale.ROOT,
                            "two drawn contours cross or touch at (%.3f, %.3f): "
                                    + "their cuts cannot keep the kerf off both",
                            p.x(),
                            p.y()));
                }
            }
        }
        if (reported.size() > 20) {
            warnings.add((reported.size() - 20) + " more pairs of crossing contours");
        }
    }

    private static List<Node> classify(List<Contour> closed, boolean paper) {
        List<Node> nodes = new ArrayList<>();
        for (Contour c : closed) {
            nodes.add(new Node(c, paper ? Math.abs(PaperCrc.triangleArea(c)) : c.area()));
        }
        nodes.sort(Comparator.comparingDouble((Node n) -> n.area).reversed());
        if (paper) {
            // the paper: the largest contour is the outside, every other one a hole in it
            for (int i = 1; i < nodes.size(); i++) {
                nodes.get(i).parent = nodes.get(0);
                nodes.get(i).depth = 1;
                nodes.get(0).children.add(nodes.get(i));
            }
            return nodes;
        }
        // a contour's container holds the lower left corner of its box: only the contours whose
        // boxes share that corner's cell are candidates
        double sizes = 0;
        for (Node n : nodes) {
            sizes += Math.max(n.box.width(), n.box.height());
        }
        BoxGrid grid = new BoxGrid(Math.max(1e-3, sizes / Math.max(1, nodes.size())));
        for (int i = 0; i < nodes.size(); i++) {
            grid.add(i, nodes.get(i).box);
        }
        for (int i = 0; i < nodes.size(); i++) {
            Node n = nodes.get(i);
            Node best = null;
            Vec2 corner = new Vec2(n.box.minX(), n.box.minY());
            int[] candidates = grid.at(corner, corner);
            for (int c = candidates.length - 1; c >= 0; c--) {
                int j = candidates[c];
                if (j >= i) {
                    continue;
                }
                Node m = nodes.get(j);
                if (m.area <= n.area || !contains(m.box, n.box)) {
                    continue;
                }
                if (insideOf(m.contour, n.contour)) {
                    best = m; // nodes are sorted by decreasing area: the first found going back is the smallest
                    break;
                }
            }
            if (best != null) {
                n.parent = best;
                n.depth = best.depth + 1;
                best.children.add(n);
            }
        }
        return nodes;
    }

    private static boolean contains(Box2 a, Box2 b) {
        return b.minX() >= a.minX() - 1e-9
                && b.maxX() <= a.maxX() + 1e-9
                && b.minY() >= a.minY() - 1e-9
                && b.maxY() <= a.maxY() + 1e-9;
    }

    private static boolean insideOf(Contour outer, Contour inner) {
        Tolerance t = new Tolerance(1e-7, 1e-9);
        for (Curve2 c : inner.curves()) {
            for (double f : new double[] {0.5, 0.25, 0.75}) {
                Vec2 p = c.pointAt(f);
                if (outer.distanceTo(p) > 1e-6) {
                    return outer.contains(p, t);
                }
            }
        }
        return false;
    }

    private static Contour orient(Contour c, boolean clockwise) {
        return c.isCcw() != clockwise ? c : c.reversed();
    }

    /** Paper mode: an internal contour starts at the vertex nearest its bounding box's lower-left corner. */
    private static Contour startNearCorner(Contour c) {
        Vec2 corner = new Vec2(c.bounds().minX(), c.bounds().minY());
        int best = 0;
        for (int i = 1; i < c.size(); i++) {
            if (c.get(i).start().distance(corner) < c.get(best).start().distance(corner)) {
                best = i;
            }
        }
        return rotate(c, best);
    }

    private static Contour rotate(Contour c, int k) {
        List<Curve2> l = new ArrayList<>(c.curves().subList(k, c.size()));
        l.addAll(c.curves().subList(0, k));
        return new Contour(l);
    }

    // ------------------------------------------------------------------ pierce and leads

    /**
     * True when the controller's compensation would reject the contour: an arc curving round the
     * tool's side with a radius not above the tool radius, or an element shorter than the tool
     * diameter next to a corner that is concave for the tool (LinuxCNC: "cannot be reached by
     * the tool without gouging"; a conservative test).
     */
    private static boolean tighterArc(Contour c, boolean toolLeft, double toolRadius) {
        int n = c.size();
        for (int i = 0; i < n; i++) {
            Curve2 cv = c.get(i);
            if (cv instanceof Arc2 a && a.ccw() == toolLeft && a.radius() <= toolRadius + 1e-6) {
                return true;
            }
            Curve2 prev = c.get((i + n - 1) % n);
            if (n > 1 && prev.length() > 0 && cv.length() > 0) {
                double cross = prev.endTangent().cross(cv.startTangent());
                boolean concave = toolLeft ? cross > 1e-9 : cross < -1e-9;
                if (concave && (prev.length() < 2 * toolRadius || cv.length() < 2 * toolRadius)) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * The cut with its leads at the first candidate (curve index, fraction) where they fit; with
     * {@code forced} candidates, null when no lead fits at any of them.
     */
    private static CutPath withLeads(
            String label,
            boolean outer,
            Contour part,
            Contour path,
            boolean scrapLeft,
            CuttingOptions o,
            double half,
            CurveGrid grid,
            List<String> warnings,
            int comp,
            Optional<List<double[]>> forced) {
        double leadIn = comp != 0 ? Math.max(o.leadInMm(), half * 1.5 + 0.1) : o.leadInMm();
        boolean arcs = o.arcLeads() && comp == 0;
        double clearance = Math.max(0, half - 1e-6);
        List<double[]> candidates = forced.orElseGet(() -> candidates(path));
        for (double[] cand : candidates) {
            for (double scale : new double[] {1, 0.5, 0.25}) {
                double len = leadIn * scale;
                if (comp != 0 && len <= half * 1.05 + 0.05) {
                    continue; // LinuxCNC: the entry move must be longer than the tool radius
                }
                Contour started = startAt(path, (int) cand[0], cand[1]);
                if (comp != 0 && shortBeforeConcave(started, scrapLeft, half)) {
                    // LinuxCNC: after the entry, a straight piece shorter than the tool's diameter
                    // into a corner concave for the tool "cannot be reached without gouging"
                    continue;
                }
                Vec2 s = started.get(0).start();
                Vec2 t = started.get(0).startTangent();
                List<Curve2> in = leadIn <= 0 ? List.of() : List.of(lead(s, t, len, scrapLeft, arcs, true));
                // under G41/G42 the programmed entry ends on the part; the tool centre ends half a kerf off it
                Vec2 side = scrapLeft ? t.leftNormal() : t.leftNormal().negated();
                List<Curve2> centre = comp == 0 || in.isEmpty()
                        ? in
                        : List.of(lead(s.plus(side.times(half)), t, len - half, scrapLeft, false, true));
                if (!clear(centre, grid, clearance, part, outer)) {
                    continue;
                }
                List<Curve2> tail = tail(started, o, half, scrapLeft, arcs, grid, clearance, part, outer);
                return SharedPoints.of(new CutPath(label, outer, part, started, in, tail, comp));
            }
        }
        if (forced.isPresent() && (leadIn > 0 || comp != 0)) {
            return null;
        }
        Contour started = startAt(path, (int) candidates.get(0)[0], candidates.get(0)[1]);
        if (leadIn > 0 && comp == 0) {
            warnings.add(label + ": no room for a lead-in; pierced on the contour");
        }
        return SharedPoints.of(new CutPath(
                label,
                outer,
                part,
                started,
                List.of(),
                tail(started, o, half, scrapLeft, arcs, grid, clearance, part, outer),
                comp));
    }

    /**
     * True when the path's first element is shorter than the tool's diameter and turns into a
     * corner concave for the tool, or its last element comes out of such a corner and is as short.
     */
    private static boolean shortBeforeConcave(Contour path, boolean toolLeft, double toolRadius) {
        int n = path.size();
        if (n < 2) {
            return false;
        }
        return shortAndConcave(path.get(0), path.get(0), path.get(1), toolLeft, toolRadius)
                || shortAndConcave(path.get(n - 1), path.get(n - 2), path.get(n - 1), toolLeft, toolRadius);
    }

    private static boolean shortAndConcave(Curve2 piece, Curve2 a, Curve2 b, boolean toolLeft, double toolRadius) {
        if (piece.length() > 2 * toolRadius + 1e-3 || a.length() == 0 || b.length() == 0) {
            return false;
        }
        double cross = a.endTangent().cross(b.startTangent());
        return toolLeft ? cross > 1e-9 : cross < -1e-9;
    }

    /** (curve index, fraction) pairs: longest lines' middles, then corners, then arcs' middles. */
    private static List<double[]> candidates(Contour path) {
        List<Integer> lines = new ArrayList<>();
        List<Integer> arcs = new ArrayList<>();
        for (int i = 0; i < path.size(); i++) {
            (path.get(i) instanceof Segment2 ? lines : arcs).add(i);
        }
        Comparator<Integer> byLength =
                Comparator.comparingDouble(i -> -path.get(i).length());
        lines.sort(byLength);
        arcs.sort(byLength);
        List<double[]> out = new ArrayList<>();
        for (int k = 0; k < Math.min(4, lines.size()); k++) {
            out.add(new double[] {lines.get(k), 0.5});
        }
        for (int k = 0; k < Math.min(4, lines.size()); k++) {
            out.add(new double[] {lines.get(k), 0});
        }
        for (int k = 0; k < Math.min(4, arcs.size()); k++) {
            out.add(new double[] {arcs.get(k), 0.5});
        }
        if (out.isEmpty()) {
            out.add(new double[] {0, 0});
        }
        return out;
    }

    /** The closed path re-started at fraction f of curve i. */
    static Contour startAt(Contour path, int i, double f) {
        Curve2 c = path.get(i);
        List<Curve2> l = new ArrayList<>();
        if (f <= 0) {
            return rotate(path, i);
        }
        Vec2 s = c.pointAt(f);
        Curve2[] parts = split(c, s);
        l.add(parts[1]);
        for (int k = 1; k < path.size(); k++) {
            l.add(path.get((i + k) % path.size()));
        }
        l.add(parts[0]);
        return new Contour(l);
    }

    private static Curve2[] split(Curve2 c, Vec2 p) {
        if (c instanceof Segment2 s) {
            return new Curve2[] {new Segment2(s.start(), p), new Segment2(p, s.end())};
        }
        Arc2 a = (Arc2) c;
        return new Curve2[] {new Arc2(a.center(), a.start(), p, a.ccw()), new Arc2(a.center(), p, a.end(), a.ccw())};
    }

    /** A lead touching the path at p with tangent t: entering (ends at p) or leaving (starts at p). */
    private static Curve2 lead(Vec2 p, Vec2 t, double len, boolean scrapLeft, boolean arc, boolean entering) {
        Vec2 n = scrapLeft ? t.leftNormal() : t.leftNormal().negated();
        if (!arc) {
            Vec2 q = p.plus(n.times(len));
            return entering ? new Segment2(q, p) : new Segment2(p, q);
        }
        Vec2 c = p.plus(n.times(len));
        if (entering) {
            return new Arc2(c, c.minus(t.times(len)), p, scrapLeft);
        }
        return new Arc2(c, p, c.plus(t.times(len)), scrapLeft);
    }

    private static boolean clear(List<Curve2> leads, CurveGrid grid, double clearance, Contour part, boolean outer) {
        for (Curve2 c : leads) {
            for (int k = 0; k < 32; k++) {
                Vec2 p = c.pointAt(c.start().equals(c.end()) ? 0 : (c instanceof Arc2 ? k / 32.0 : k / 32.0));
                double limit = clearance + 1;
                double d = grid.distance(p, limit);
                if (d < clearance) {
                    return false;
                }
                if (k == 0 && clearance <= 0 && part.contains(p, TOL) == outer) {
                    return false;
                }
            }
        }
        return true;
    }

    private static List<Curve2> tail(
            Contour path,
            CuttingOptions o,
            double half,
            boolean scrapLeft,
            boolean arcs,
            CurveGrid grid,
            double clearance,
            Contour part,
            boolean outer) {
        List<Curve2> tail = new ArrayList<>();
        double left = o.overcutMm();
        for (int k = 0; k < path.size() && left > 1e-9; k++) {
            Curve2 c = path.get(k);
            if (c.length() <= left) {
                tail.add(c);
                left -= c.length();
            } else {
                tail.add(split(c, c.pointAt(left / c.length()))[0]);
                left = 0;
            }
        }
        Vec2 e = tail.isEmpty()
                ? path.get(path.size() - 1).end()
                : tail.get(tail.size() - 1).end();
        Vec2 t = tail.isEmpty()
                ? path.get(path.size() - 1).endTangent()
                : tail.get(tail.size() - 1).endTangent();
        if (o.leadOutMm() > 0 && !o.paperMode()) {
            for (double scale : new double[] {1, 0.5, 0.25}) {
                Curve2 out = lead(e, t, o.leadOutMm() * scale, scrapLeft, arcs, false);
                if (clear(List.of(out.reversed()), grid, clearance, part, outer)) {
                    tail.add(out);
                    break;
                }
            }
        }
        return tail;
    }

    // ------------------------------------------------------------------ order

    private static List<CutPath> paperOrder(List<Node> nodes) {
        List<CutPath> out = new ArrayList<>();
        if (nodes.isEmpty()) {
            return out;
        }
        List<Node> internal = new ArrayList<>(nodes.subList(1, nodes.size()));
        Vec2 at = Vec2.ZERO;
        while (!internal.isEmpty()) {
            Node best = null;
            for (Node n : internal) {
                if (best == null
                        || n.box.center().distance(at) < best.box.center().distance(at)) {
                    best = n;
                }
            }
            internal.remove(best);
            out.addAll(best.cuts);
            at = best.box.center();
        }
        out.addAll(nodes.get(0).cuts);
        return out;
    }

    /**
     * The cuts in the order of {@link CutOrder}: every cut inside a contour (its holes, the parts
     * in a hole) before the contour's own cut.
     */
    private static List<CutPath> order(List<Node> nodes, java.util.Set<String> pinned) {
        List<CutPath> cuts = new ArrayList<>();
        Map<Node, int[]> ids = new java.util.IdentityHashMap<>();
        for (Node n : nodes) {
            int[] id = new int[n.cuts.size()];
            for (int k = 0; k < id.length; k++) {
                id[k] = cuts.size();
                cuts.add(n.cuts.get(k));
            }
            ids.put(n, id);
        }
        List<Vec2> pierce = new ArrayList<>(cuts.size());
        List<Vec2> exit = new ArrayList<>(cuts.size());
        for (CutPath c : cuts) {
            pierce.add(c.pierce());
            exit.add(c.exit());
        }
        List<int[]> before = new ArrayList<>(cuts.size());
        for (Node n : nodes) {
            int m = 0;
            for (Node child : n.children) {
                m += ids.get(child).length;
            }
            int[] inner = new int[m];
            int k = 0;
            for (Node child : n.children) {
                for (int id : ids.get(child)) {
                    inner[k++] = id;
                }
            }
            for (int unused : ids.get(n)) {
                before.add(inner);
            }
        }
        CutOrder co = new CutOrder(pierce, exit, before);
        int[] nn = co.nearestNeighbour();
        // a part with everything inside it is one stop of the tour, its cuts in their nearest-neighbour
        // order: between parts there is no rule, so the stops can be reordered freely
        Map<Node, List<Integer>> byPart = new java.util.LinkedHashMap<>();
        Map<Integer, Node> partOf = new HashMap<>();
        for (Node n : nodes) {
            Node top = n;
            while (top.parent != null) {
                top = top.parent;
            }
            for (int id : ids.get(n)) {
                partOf.put(id, top);
            }
        }
        for (int id : nn) {
            byPart.computeIfAbsent(partOf.get(id), k -> new ArrayList<>()).add(id);
        }
        List<List<Integer>> stops = new ArrayList<>(byPart.values());
        List<Vec2> stopIn = new ArrayList<>(stops.size());
        List<Vec2> stopOut = new ArrayList<>(stops.size());
        List<int[]> free = new ArrayList<>(stops.size());
        for (List<Integer> stop : stops) {
            stopIn.add(pierce.get(stop.get(0)));
            stopOut.add(exit.get(stop.get(stop.size() - 1)));
            free.add(new int[0]);
        }
        CutOrder so = new CutOrder(stopIn, stopOut, free);
        int[] stopSeq = so.improve(so.nearestNeighbour(), Math.min(ORDER_MAX_WORK, 20_000_000L + 2_000L * cuts.size()));
        int[] seq = new int[cuts.size()];
        int k = 0;
        for (int st : stopSeq) {
            for (int id : stops.get(st)) {
                seq[k++] = id;
            }
        }
        // then single cuts moved within the rule (a hole nearer the part's next neighbour, ...)
        seq = co.improve(seq, Math.min(ORDER_MAX_WORK, 15_000_000L + 1_000L * cuts.size()));
        if (cuts.size() <= CutOrder.EXACT_MAX) {
            seq = co.exact();
        }
        if (co.travel(nn) < co.travel(seq)) {
            seq = nn;
        }
        return withStartPoints(cuts, seq, before, Math.min(ORDER_MAX_WORK, 15_000_000L + 1_000L * cuts.size()), pinned);
    }

    /**
     * The cuts in order, those without leads started where the rapids to and from them are
     * shortest (anywhere on the path, not only at a vertex). Two tours are refined, alternating
     * the choice of start points with 2-opt and Or-opt moves of the order, and the shorter kept:
     * the order found so far, and the nearest-neighbour tour that goes from the origin to the
     * nearest point of the nearest cut whose inner cuts are done. So the travel is never longer
     * than that tour's.
     */
    private static List<CutPath> withStartPoints(
            List<CutPath> cuts, int[] seq, List<int[]> before, long maxWork, java.util.Set<String> pinned) {
        int n = cuts.size();
        boolean[] free = new boolean[n];
        boolean any = false;
        for (int i = 0; i < n; i++) {
            CutPath c = cuts.get(i);
            free[i] =
                    c.leadIn().isEmpty() && c.tail().isEmpty() && c.compensation() == 0 && !pinned.contains(c.label());
            any |= free[i];
        }
        if (!any) {
            List<CutPath> out = new ArrayList<>(n);
            for (int i : seq) {
                out.add(cuts.get(i));
            }
            return out;
        }
        // the second tour may use what the first left of its budget
        long[] left = {maxWork};
        CutPath[] a = cuts.toArray(new CutPath[0]);
        int[] seqA = refine(a, seq, free, before, left);
        left[0] += maxWork;
        CutPath[] b = cuts.toArray(new CutPath[0]);
        int[] seqB = refine(b, nearestPointTour(b, free, before), free, before, left);
        CutPath[] best = travel(a, seqA) <= travel(b, seqB) ? a : b;
        int[] bestSeq = best == a ? seqA : seqB;
        List<CutPath> out = new ArrayList<>(n);
        for (int i : bestSeq) {
            out.add(best[i]);
        }
        return out;
    }

    private static double travel(CutPath[] cs, int[] seq) {
        double d = 0;
        Vec2 at = Vec2.ZERO;
        for (int c : seq) {
            d += at.distance(cs[c].pierce());
            at = cs[c].exit();
        }
        return d;
    }

    /**
     * Start points, then the order, then start points again, until neither changes or the work
     * left (taken from {@code left[0]}) is spent.
     */
    private static int[] refine(CutPath[] cs, int[] seq, boolean[] free, List<int[]> before, long[] left) {
        for (int round = 0; round < 6 && left[0] > 0; round++) {
            boolean moved = placeStarts(cs, seq, free);
            List<Vec2> pierce = new ArrayList<>(cs.length);
            List<Vec2> exit = new ArrayList<>(cs.length);
            for (CutPath c : cs) {
                pierce.add(c.pierce());
                exit.add(c.exit());
            }
            CutOrder order = new CutOrder(pierce, exit, before);
            int[] next = order.improve(seq, left[0]);
            left[0] -= order.work();
            if (!moved && java.util.Arrays.equals(next, seq)) {
                break;
            }
            seq = next;
        }
        placeStarts(cs, seq, free);
        return seq;
    }

    /** Moves the start of every cut without leads to where the rapids in and out of it are shortest. */
    private static boolean placeStarts(CutPath[] cs, int[] seq, boolean[] free) {
        boolean moved = false;
        for (int k = 0; k < seq.length; k++) {
            int c = seq[k];
            if (!free[c]) {
                continue;
            }
            Vec2 from = k == 0 ? Vec2.ZERO : cs[seq[k - 1]].exit();
            Vec2 to = k + 1 < seq.length ? cs[seq[k + 1]].pierce() : null;
            Vec2 now = cs[c].pierce();
            double cost = from.distance(now) + (to == null ? 0 : now.distance(to));
            PathPoints.OnPath o = PathPoints.bestLink(cs[c].path(), from, to);
            if (o.cost() < cost - 1e-6) {
                cs[c] = restarted(cs[c], o);
                moved = true;
            }
        }
        return moved;
    }

    private static CutPath restarted(CutPath c, PathPoints.OnPath at) {
        return new CutPath(
                c.label(),
                c.outer(),
                c.part(),
                PathPoints.restart(c.path(), at),
                c.leadIn(),
                c.tail(),
                c.compensation());
    }

    /**
     * The nearest-neighbour tour from the origin over the cuts whose inner cuts are done, to the
     * nearest point of each cut without leads (started there) or to the pierce of one with leads.
     */
    private static int[] nearestPointTour(CutPath[] cs, boolean[] free, List<int[]> before) {
        int n = cs.length;
        List<List<Curve2>> curves = new ArrayList<>(n);
        List<Vec2> fixed = new ArrayList<>(n);
        int[] waiting = new int[n];
        List<List<Integer>> after = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            curves.add(free[i] ? cs[i].path().curves() : null);
            fixed.add(cs[i].pierce());
            after.add(new ArrayList<>(1));
        }
        NearestCutIndex index = new NearestCutIndex(curves, fixed);
        for (int i = 0; i < n; i++) {
            waiting[i] = before.get(i).length;
            for (int b : before.get(i)) {
                after.get(b).add(i);
            }
            if (waiting[i] == 0) {
                index.open(i);
            }
        }
        int[] seq = new int[n];
        Vec2 at = Vec2.ZERO;
        for (int k = 0; k < n; k++) {
            int c = index.nearest(at);
            seq[k] = c;
            index.close(c);
            if (free[c]) {
                cs[c] = restarted(cs[c], PathPoints.nearest(cs[c].path(), at));
            }
            at = cs[c].exit();
            for (int o : after.get(c)) {
                if (--waiting[o] == 0) {
                    index.open(o);
                }
            }
        }
        return seq;
    }

    // ------------------------------------------------------------------ the planner's own order

    /** A cut of the override and the contour it names. */
    private record Asked(CutOrderOverride.Cut cut, Node node) {}

    /**
     * The contours the override names, in its order: each the contour whose drawn outline passes
     * nearest its point, within {@link CutOrderOverride#MATCH_MM}. A point on no contour is warned
     * about and left out.
     */
    private static List<Asked> resolve(CutOrderOverride override, List<Node> nodes, List<String> warnings) {
        List<Asked> out = new ArrayList<>();
        if (override.isEmpty() || nodes.isEmpty()) {
            for (CutOrderOverride.Cut c : override.cuts()) {
                warnings.add("cut order: no contour of the drawing passes through " + c.named() + ": ignored");
            }
            return out;
        }
        double sizes = 0;
        for (Node n : nodes) {
            sizes += Math.max(n.box.width(), n.box.height());
        }
        double m = CutOrderOverride.MATCH_MM;
        // cells at least twice the match distance: the cells around a point's hold every contour near enough
        BoxGrid grid = new BoxGrid(Math.max(2 * m, sizes / nodes.size()));
        for (int i = 0; i < nodes.size(); i++) {
            grid.add(i, nodes.get(i).box);
        }
        for (CutOrderOverride.Cut c : override.cuts()) {
            Vec2 p = c.atMm();
            Node best = null;
            double bestD = Double.POSITIVE_INFINITY;
            for (int i : grid.along(p, p)) {
                Node n = nodes.get(i);
                double d = n.contour.distanceTo(p);
                if (d <= m && d < bestD) {
                    best = n;
                    bestD = d;
                }
            }
            if (best == null) {
                warnings.add("cut order: no contour of the drawing passes through " + c.named() + ": ignored");
            } else {
                out.add(new Asked(c, best));
            }
        }
        return out;
    }

    /**
     * Starts the cuts the override gives a start point where it says: at the point of the tool
     * path nearest it, the leads (if any) placed there. Where no lead fits, the automatic start
     * stays and a warning says so. Returns the labels of the cuts so started, which the automatic
     * order must not move.
     */
    private static java.util.Set<String> startsAsked(
            List<Asked> asked, CuttingOptions o, double half, CurveGrid grid, List<String> warnings) {
        java.util.Set<String> pinned = new java.util.HashSet<>();
        for (Asked a : asked) {
            if (a.cut().startMm().isEmpty() || a.node().cuts.isEmpty()) {
                continue;
            }
            Vec2 want = a.cut().startMm().get();
            List<CutPath> cuts = a.node().cuts;
            int k = 0;
            for (int i = 1; i < cuts.size(); i++) {
                if (cuts.get(i).label().equals(a.cut().contour())
                        || cuts.get(i).path().distanceTo(want)
                                        < cuts.get(k).path().distanceTo(want)
                                && !cuts.get(k).label().equals(a.cut().contour())) {
                    k = i;
                }
            }
            CutPath c = cuts.get(k);
            if (pinned.contains(c.label())) {
                continue;
            }
            CutPath s = startedAt(c, want, o, half, grid, warnings);
            if (s == null) {
                warnings.add(String.format(
                        Locale.ROOT,
                        "cut order: no room for a lead at the start (%.3f, %.3f) asked for"
                                + " %s: started where the planner chose",
                        want.x(),
                        want.y(),
                        c.label()));
                continue;
            }
            cuts.set(k, s);
            pinned.add(c.label());
        }
        return pinned;
    }

    /** The cut started at the point of its path nearest p, its leads there; null when they do not fit. */
    private static CutPath startedAt(
            CutPath c, Vec2 p, CuttingOptions o, double half, CurveGrid grid, List<String> warnings) {
        PathPoints.OnPath at = PathPoints.nearest(c.path(), p);
        if (o.paperMode()) {
            return restarted(c, at);
        }
        Curve2 e = c.path().get(at.index());
        double[] cand = {at.index(), at.fraction()};
        if (at.fraction() * e.length() < 1e-4) {
            cand = new double[] {at.index(), 0};
        } else if ((1 - at.fraction()) * e.length() < 1e-4) {
            cand = new double[] {(at.index() + 1) % c.path().size(), 0};
        }
        boolean scrapLeft = c.outer() ? !c.path().isCcw() : c.path().isCcw();
        return withLeads(
                c.label(),
                c.outer(),
                c.part(),
                c.path(),
                scrapLeft,
                o,
                half,
                grid,
                warnings,
                c.compensation(),
                Optional.of(List.<double[]>of(cand)));
    }

    /**
     * The automatic order with the override laid over it: the named cuts in the override's order,
     * each preceded by the cuts not named that lie inside it; the other cuts not named after them,
     * in the automatic order. Refused when a contour comes before one inside it.
     */
    private static List<CutPath> overridden(
            List<CutPath> order,
            List<Asked> asked,
            List<Node> nodes,
            CuttingOptions o,
            java.util.Set<String> pinned,
            List<String> warnings) {
        Map<String, CutPath> byLabel = new HashMap<>();
        for (CutPath c : order) {
            byLabel.put(c.label(), c);
        }
        Map<String, Node> nodeOf = new HashMap<>();
        for (Node n : nodes) {
            for (CutPath c : n.cuts) {
                nodeOf.put(c.label(), n);
            }
        }
        List<String> listed = new ArrayList<>();
        Map<String, Integer> rank = new HashMap<>();
        for (Asked a : asked) {
            List<String> labels = new ArrayList<>();
            for (CutPath c : a.node().cuts) {
                if (c.label().equals(a.cut().contour())) {
                    labels = new ArrayList<>(List.of(c.label()));
                    break;
                }
                labels.add(c.label());
            }
            if (labels.isEmpty()) {
                warnings.add("cut order: " + a.cut().named() + " is not cut: ignored");
                continue;
            }
            for (String l : labels) {
                if (rank.containsKey(l)) {
                    warnings.add("cut order: " + l + " named twice: the first place kept");
                } else if (byLabel.containsKey(l)) {
                    rank.put(l, listed.size());
                    listed.add(l);
                }
            }
        }
        // the cuts not named: just before the first named cut around them, else at the end
        Map<Integer, List<String>> before = new HashMap<>();
        List<String> end = new ArrayList<>();
        for (CutPath c : order) {
            if (rank.containsKey(c.label())) {
                continue;
            }
            int first = Integer.MAX_VALUE;
            for (Node up = nodeOf.get(c.label()).parent; up != null; up = up.parent) {
                for (CutPath u : up.cuts) {
                    first = Math.min(first, rank.getOrDefault(u.label(), Integer.MAX_VALUE));
                }
            }
            (first == Integer.MAX_VALUE ? end : before.computeIfAbsent(first, k -> new ArrayList<>())).add(c.label());
        }
        List<CutPath> out = new ArrayList<>(order.size());
        for (int i = 0; i < listed.size(); i++) {
            for (String l : before.getOrDefault(i, List.of())) {
                out.add(byLabel.get(l));
            }
            out.add(byLabel.get(listed.get(i)));
        }
        for (String l : end) {
            out.add(byLabel.get(l));
        }
        refuseInnerAfterOuter(out, nodeOf);
        // cuts without leads and without a start of the planner's own: started where the rapids
        // of the new order are shortest
        CutPath[] cs = out.toArray(new CutPath[0]);
        boolean[] free = new boolean[cs.length];
        int[] seq = new int[cs.length];
        for (int i = 0; i < cs.length; i++) {
            seq[i] = i;
            free[i] = !o.paperMode()
                    && cs[i].leadIn().isEmpty()
                    && cs[i].tail().isEmpty()
                    && cs[i].compensation() == 0
                    && !pinned.contains(cs[i].label());
        }
        placeStarts(cs, seq, free);
        return List.of(cs);
    }

    /** Refuses an order that cuts a contour before a contour inside it (its hole, or the part in its hole). */
    private static void refuseInnerAfterOuter(List<CutPath> order, Map<String, Node> nodeOf) {
        Map<Node, Integer> first = new java.util.IdentityHashMap<>();
        for (int i = 0; i < order.size(); i++) {
            first.putIfAbsent(nodeOf.get(order.get(i).label()), i);
        }
        for (int i = 0; i < order.size(); i++) {
            Node inner = nodeOf.get(order.get(i).label());
            if (inner.parent == null) {
                continue;
            }
            Integer outer = first.get(inner.parent);
            if (outer != null && outer < i) {
                CutPath o = order.get(outer);
                CutPath c = order.get(i);
                throw new CutOrderOverride.Refused(String.format(
                        Locale.ROOT,
                        "the cut order cuts %s%s (cut %d) before"
                                + " %s%s (cut %d) inside it: whatever lies inside a contour is cut before it, so nothing falls"
                                + " out uncut",
                        o.label(),
                        place(o.part()),
                        outer + 1,
                        c.label(),
                        place(c.part()),
                        i + 1));
            }
        }
    }

    // ------------------------------------------------------------------ rapids

    /**
     * The rapid travel before each cut: straight in paper mode; otherwise around the parts
     * already cut free ({@link RapidRouter}), keeping half a kerf (at least 0.25 mm) off their paths.
     */
    private static List<List<Vec2>> rapids(List<CutPath> order, CuttingOptions o, List<String> warnings) {
        List<List<Vec2>> out = new ArrayList<>();
        // cells about the size of a part; at most 2048 across the sheet
        Box2 ext = null;
        double sizes = 0;
        for (CutPath c : order) {
            Box2 b = c.path().bounds();
            ext = ext == null ? b : ext.union(b);
            sizes += Math.max(b.width(), b.height());
        }
        double cell = ext == null ? 10 : Math.max(sizes / order.size(), Math.max(ext.width(), ext.height()) / 2048);
        RapidRouter router = new RapidRouter(Math.max(0.25, o.kerfMm() / 2), Math.max(cell, 1e-3));
        Vec2 at = Vec2.ZERO;
        boolean straight = o.paperMode() || !o.avoidCutParts();
        for (CutPath c : order) {
            out.add(straight ? List.of(at, c.pierce()) : router.route(at, c.pierce()));
            if (c.outer() && !straight) {
                router.cutFree(c.path());
            }
            at = c.exit();
        }
        if (router.unavoidable() > 0) {
            warnings.add(router.unavoidable() + " rapid moves pass over a part already cut (no way around it)");
        }
        return out;
    }
}
