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
 * Fresa's default contour-parallel pocketing of a region with islands and any number of sub-areas
 * (beyond the thesis): offsets of the whole region (outer contour and islands together,
 * {@link RegionOffsetter}) at R (finishing), R + a (pre-finish), then by the stepover, cut from
 * the inside out, climb by default.
 *
 * <p>No uncut material, by construction, and checked. Let delta(p) be the distance of p from the region's
 * boundary; the pass at offset d runs on {delta = d} and clears every point with
 * d &lt;= delta &lt;= d + R. So a step s &lt;= R between consecutive offsets leaves nothing; a
 * larger step (up to the nominal stepover) is taken only when no corner of the next offset is
 * sharper than the thesis's rule allows: s &lt;= R (1 + sin(alpha / 2)) for its smallest interior
 * corner angle alpha (with a 3 % margin for curved fronts), and cut to no less than 0.98 R. The
 * rule misses a sliver where the last pass round an island meets a sharp corner of the outer
 * passes (the step there grows beyond R), and where the offsets change topology within a step (a
 * neck pinched, a sub-area vanishing), so the plan's coverage is checked on a grid
 * ({@link Coverage}) and each patch left gets a clean-up spur ({@link #cleanedUp}). (A step cut
 * to 0.98 R at every change of topology cost a whole pass per change and 2 % of the machining
 * time on the libarea bench's island pockets, for slivers the clean-up clears anyway.)
 *
 * <p>Order: the offsets form a tree of faces (a face of one offset lies in exactly one face of
 * the previous one). Each face's subtree is cut before the face itself (inside out), each face's
 * loops nearest first; a link between loops is a straight feed move when it stays inside the
 * finishing offset (so the tool never touches a wall or island) and is no longer than 2 D or than
 * the ramp that a retract would need to enter the next loop ({@link #linkLimitMm}), or when the
 * tool's disc along it stays in material this layer has already cut or the next loop cuts
 * (whatever its length; {@link Coverage#clearedAlong}), or, when an island's offset cuts the
 * straight link off, straight moves by corners beside the finishing loops ({@link #detour}),
 * otherwise a retract, a rapid and a helix beside the next loop's start ({@link #helixOnto}) or a
 * ramp down along the loop, no steeper than the entry angle (no vertical plunge into material
 * unless a centre-cutting tool is asked to).
 */
public final class RegionPocket {

    private static final Tolerance TOL = Tolerance.DEFAULT;
    private static final Vec3 Z = new Vec3(0, 0, 1);
    private static final double CLEARANCE_MM = 5;

    /** One offset level: its distance from the region boundary and its loops (faces CCW, holes CW). */
    public record Level(double offsetMm, List<Contour> loops) {
        public Level {
            loops = List.copyOf(loops);
        }
    }

    /** A loop in cutting order, with its level index (0 = finishing). */
    public record Cut(int level, Contour loop) {}

    /** The plan: the levels outside in, the loops in cutting order, and the toolpath. */
    public record Plan(List<Level> levels, List<Cut> order, Toolpath toolpath) {
        public Plan {
            levels = List.copyOf(levels);
            order = List.copyOf(order);
        }
    }

    private record Face(int level, Contour outer, List<Contour> holes, List<Face> children) {}

    private RegionPocket() {}

    /**
     * Plans the pocket.
     *
     * @param outer the outer contour (either orientation)
     * @param islands closed contours inside it (either orientation), not touching it or each other
     * @param tech the technology (tool, stepover, allowance, depths, feeds)
     * @param climb climb milling (true) or conventional
     * @throws ToolTooLargeException when the tool does not fit anywhere in the region
     */
    public static Plan plan(Contour outer, List<Contour> islands, PocketTechnology tech, boolean climb)
            throws ToolTooLargeException {
        return plan(outer, islands, tech, climb, EntryRule.DEFAULT);
    }

    /**
     * Plans the pocket with the given entries: each loop that is not joined to the previous one at
     * depth is entered by a ramp along the loop itself, round it as many times as the entry angle
     * needs (a helix is this ramp too: the loop is the region's own path), or, for a centre-cutting
     * tool asked to, by a plunge.
     *
     * @throws ToolTooLargeException as {@link #plan(Contour, List, PocketTechnology, boolean)}, or
     *     when a loop is so short that its ramp would need more than {@link Entries#MAX_STEPS} rounds
     */
    public static Plan plan(Contour outer, List<Contour> islands, PocketTechnology tech, boolean climb, EntryRule entry)
            throws ToolTooLargeException {
        return plan(outer, islands, tech, climb, entry, true);
    }

    /** As {@link #plan(Contour, List, PocketTechnology, boolean, EntryRule)}; cleanUp false leaves the remaining material. */
    static Plan plan(
            Contour outer,
            List<Contour> islands,
            PocketTechnology tech,
            boolean climb,
            EntryRule entry,
            boolean cleanUp)
            throws ToolTooLargeException {
        return plan(RegionOffsetter.oriented(outer, islands), tech, climb, entry, cleanUp, false);
    }

    /**
     * Plans the pocket of a region given by its boundary.
     *
     * @param boundary the region's loops with the region on their left ({@link RegionOffsetter#oriented}),
     *     any number of faces
     * @param outsideIn the roughing passes from the outermost inwards, the finishing pass last (the
     *     pre-finish pass first); false: inside out
     * @throws ToolTooLargeException as {@link #plan(Contour, List, PocketTechnology, boolean, EntryRule)}
     */
    public static Plan plan(
            List<Contour> boundary,
            PocketTechnology tech,
            boolean climb,
            EntryRule entry,
            boolean cleanUp,
            boolean outsideIn)
            throws ToolTooLargeException {
        List<Level> levels = levels(boundary, tech);
        List<Face> roots = faces(levels);
        List<Cut> order = new ArrayList<>();
        Vec2[] cursor = {null};
        List<Face> pending = new ArrayList<>(roots);
        while (!pending.isEmpty()) {
            Face f = nearestFace(pending, cursor[0]);
            pending.remove(f);
            if (outsideIn) {
                cutOutsideIn(f, order, cursor);
            } else {
                cutSubtree(f, order, cursor);
            }
        }
        List<Cut> directed = new ArrayList<>();
        for (Cut c : order) {
            if (cleanUp && c.level() > 0 && c.loop().length() < tech.toolDiameterMm()) {
                // a loop shorter than the tool's diameter encloses a face a fraction of the tool's
                // disc wide, which the loop round it sweeps nearly all of; entered on its own it
                // takes a ramp of hundreds of rounds (a block per element each): the coverage
                // check below clears what it alone would have cut by a spur from another loop
                continue;
            }
            directed.add(new Cut(c.level(), halved(climb ? c.loop() : c.loop().reversed())));
        }
        if (cleanUp) {
            directed = cleanedUp(directed, levels.get(0).loops(), tech.radiusMm());
        }
        // each element once cut and once ramped down, some arcs joined by short lines, and a link
        // or rapids and a plunge per loop
        tech.checkMoves(
                directed.stream().mapToLong(c -> 3L * c.loop().size() + 4).sum());
        Toolpath path = toolpath(directed, levels.get(0), tech, entry);
        return new Plan(levels, directed, path);
    }

    /** The grid cell of the coverage check (mm): fine enough to see a sliver of a few hundredths of a mm2. */
    static final double COVERAGE_CELL_MM = 0.1;

    /**
     * The loops with a clean-up spur wherever material the tool can reach is left: the passes'
     * coverage is checked ({@link Coverage}) and each remaining patch is visited from the nearest
     * point of a loop by a straight move out and back (the tool's centre kept inside the finishing
     * offset, so no wall is touched), at every depth, as the loop is cut. The spots are chosen so
     * that each covers every remaining cell within the tool radius of it; a patch no loop can reach
     * straight is left (none in the tests). Two rounds: a spur's own disc is checked again.
     */
    static List<Cut> cleanedUp(List<Cut> cuts, List<Contour> faces, double radiusMm) {
        List<Cut> out = new ArrayList<>(cuts);
        for (int round = 0; round < 2; round++) {
            List<List<Curve2>> passes = out.stream().map(c -> c.loop().curves()).toList();
            Coverage cov = Coverage.of(faces, passes, radiusMm, COVERAGE_CELL_MM);
            List<Vec2> left = cov.uncut();
            if (left.isEmpty()) {
                return out;
            }
            boolean[] covered = new boolean[left.size()];
            boolean changed = false;
            for (int i = 0; i < left.size(); i++) {
                if (covered[i]) {
                    continue;
                }
                Vec2 p = left.get(i);
                Vec2 spot = p;
                if (!cov.insideFaces(p)) {
                    // the nearest place the centre may go, a hair inside
                    Vec2 q = cov.nearestOnFaces(p);
                    Vec2 in = q.minus(p);
                    spot = in.norm() < 1e-12 ? q : q.plus(in.times(1e-4 / in.norm()));
                }
                for (int k = i; k < left.size(); k++) {
                    if (left.get(k).distance(spot) <= radiusMm - 2 * cov.cellMm()) {
                        covered[k] = true;
                    }
                }
                covered[i] = true;
                changed |= spur(out, spot, cov);
            }
            if (!changed) {
                return out;
            }
        }
        return out;
    }

    /** Adds a straight spur out to the spot and back on the nearest loop that reaches it inside the faces. */
    private static boolean spur(List<Cut> cuts, Vec2 spot, Coverage cov) {
        record Candidate(int cut, int curve, Vec2 at, double distance) {}
        List<Candidate> candidates = new ArrayList<>();
        for (int k = 0; k < cuts.size(); k++) {
            Contour loop = cuts.get(k).loop();
            for (int i = 0; i < loop.size(); i++) {
                Curve2 c = loop.get(i);
                double t = Math.max(0, Math.min(1, OffsetSplit.param(c, spot)));
                Vec2 q = c.pointAt(t);
                candidates.add(new Candidate(k, i, q, q.distance(spot)));
            }
        }
        candidates.sort(java.util.Comparator.comparingDouble(Candidate::distance));
        for (Candidate cand : candidates) {
            if (cand.distance() < 1e-6) {
                return false;
            }
            if (!cov.staysInside(cand.at(), spot)) {
                continue;
            }
            Cut cut = cuts.get(cand.cut());
            Contour loop = cut.loop();
            Curve2 c = loop.get(cand.curve());
            List<Curve2> curves = new ArrayList<>(loop.curves().subList(0, cand.curve()));
            if (cand.at().distance(c.start()) > 1e-9) {
                curves.add(piece(c, c.start(), cand.at()));
            }
            curves.add(new Segment2(cand.at(), spot));
            curves.add(new Segment2(spot, cand.at()));
            if (cand.at().distance(c.end()) > 1e-9) {
                curves.add(piece(c, cand.at(), c.end()));
            }
            curves.addAll(loop.curves().subList(cand.curve() + 1, loop.size()));
            cuts.set(cand.cut(), new Cut(cut.level(), new Contour(curves)));
            return true;
        }
        return false;
    }

    static List<Level> levels(List<Contour> boundary, PocketTechnology tech) throws ToolTooLargeException {
        double r = tech.radiusMm();
        double a = tech.finishFraction() * tech.toolDiameterMm();
        List<Level> out = new ArrayList<>();
        List<Contour> first = RegionOffsetter.inward(boundary, r, TOL);
        if (first.isEmpty()) {
            throw new ToolTooLargeException("the tool (" + tech.toolDiameterMm()
                    + " mm) does not fit anywhere in the pocket: use a smaller tool");
        }
        out.add(new Level(r, first));
        double d = r;
        if (a > 1e-9) {
            List<Contour> pre = RegionOffsetter.inward(boundary, r + a, TOL);
            if (pre.isEmpty()) {
                return out;
            }
            d = r + a;
            out.add(new Level(d, pre));
        }
        double nominal = tech.effectiveCut() * tech.toolDiameterMm();
        double safeStep = 0.98 * r;
        while (true) {
            List<Contour> prev = out.get(out.size() - 1).loops();
            double s = nominal;
            List<Contour> next = RegionOffsetter.inward(boundary, d + s, TOL);
            for (int k = 0; k < 6 && s > safeStep; k++) {
                double limit;
                if (next.isEmpty()) {
                    limit = safeStep;
                } else {
                    double alpha = minCornerAngleRad(next);
                    limit = 0.97 * r * (1 + Math.sin(alpha / 2));
                    if (s <= limit) {
                        break;
                    }
                }
                s = Math.max(safeStep, Math.min(limit, s));
                next = RegionOffsetter.inward(boundary, d + s, TOL);
            }
            if (next.isEmpty()) {
                return out;
            }
            d += s;
            out.add(new Level(d, next));
            if (out.size() > 100000) {
                throw new IllegalStateException("pocket offsets do not end");
            }
        }
    }

    /** The smallest interior angle at a tangent break of any loop (pi when there is none). */
    static double minCornerAngleRad(List<Contour> loops) {
        double min = Math.PI;
        for (Contour c : loops) {
            int n = c.size();
            for (int i = 0; i < n; i++) {
                Curve2 a = c.get(i);
                Curve2 b = c.get((i + 1) % n);
                if (a.length() < 1e-9 || b.length() < 1e-9) {
                    continue;
                }
                Vec2 t1 = a.endTangent();
                Vec2 t2 = b.startTangent();
                double turn = Math.atan2(t1.cross(t2), t1.dot(t2));
                if (turn > 1e-6) {
                    min = Math.min(min, Math.PI - turn);
                }
            }
        }
        return min;
    }

    private static int containing(List<Contour> faces, Vec2 p) {
        int best = -1;
        double bestArea = Double.POSITIVE_INFINITY;
        for (int i = 0; i < faces.size(); i++) {
            Contour f = faces.get(i);
            if (f.windingNumber(p) != 0 && f.area() < bestArea) {
                best = i;
                bestArea = f.area();
            }
        }
        return best;
    }

    /** The faces of each level, linked to their parents; the roots are the finishing level's faces. */
    private static List<Face> faces(List<Level> levels) {
        List<List<Face>> byLevel = new ArrayList<>();
        for (int k = 0; k < levels.size(); k++) {
            List<Contour> loops = levels.get(k).loops();
            List<Contour> outers = loops.stream().filter(Contour::isCcw).toList();
            List<Face> faces = new ArrayList<>();
            for (Contour o : outers) {
                faces.add(new Face(k, o, new ArrayList<>(), new ArrayList<>()));
            }
            for (Contour h : loops) {
                if (h.isCcw()) {
                    continue;
                }
                int i = containing(outers, RegionOffsetter.probe(h));
                if (i >= 0) {
                    faces.get(i).holes().add(h);
                }
            }
            if (k > 0) {
                List<Face> parents = byLevel.get(k - 1);
                List<Contour> parentOuters = parents.stream().map(Face::outer).toList();
                for (Face f : faces) {
                    int p = containing(parentOuters, RegionOffsetter.probe(f.outer()));
                    if (p >= 0) {
                        parents.get(p).children().add(f);
                    }
                }
            }
            byLevel.add(faces);
        }
        return byLevel.get(0);
    }

    private static void cutSubtree(Face f, List<Cut> order, Vec2[] cursor) {
        List<Face> pending = new ArrayList<>(f.children());
        while (!pending.isEmpty()) {
            Face c = nearestFace(pending, cursor[0]);
            pending.remove(c);
            cutSubtree(c, order, cursor);
        }
        loopsNearestFirst(f, order, cursor);
    }

    /**
     * A finishing face's subtree from the outside in: each roughing face's loops before its
     * children's (the nearest child first), the finishing face's own loops last.
     */
    private static void cutOutsideIn(Face f, List<Cut> order, Vec2[] cursor) {
        if (f.level() > 0) {
            loopsNearestFirst(f, order, cursor);
        }
        List<Face> pending = new ArrayList<>(f.children());
        while (!pending.isEmpty()) {
            Face c = nearestFace(pending, cursor[0]);
            pending.remove(c);
            cutOutsideIn(c, order, cursor);
        }
        if (f.level() == 0) {
            loopsNearestFirst(f, order, cursor);
        }
    }

    private static void loopsNearestFirst(Face f, List<Cut> order, Vec2[] cursor) {
        List<Contour> loops = new ArrayList<>();
        loops.add(f.outer());
        loops.addAll(f.holes());
        while (!loops.isEmpty()) {
            int best = 0;
            double bestD = Double.POSITIVE_INFINITY;
            for (int i = 0; i < loops.size() && cursor[0] != null; i++) {
                double dd = loops.get(i).distanceTo(cursor[0]);
                if (dd < bestD) {
                    bestD = dd;
                    best = i;
                }
            }
            Contour l = loops.remove(best);
            Contour started = cursor[0] == null ? l : startedNear(l, cursor[0]);
            order.add(new Cut(f.level(), started));
            cursor[0] = started.get(0).start();
        }
    }

    private static Face nearestFace(List<Face> faces, Vec2 p) {
        if (p == null) {
            return faces.get(0);
        }
        Face best = faces.get(0);
        double bestD = Double.POSITIVE_INFINITY;
        for (Face f : faces) {
            double d = innermost(f).distanceTo(p);
            if (d < bestD) {
                bestD = d;
                best = f;
            }
        }
        return best;
    }

    private static Contour innermost(Face f) {
        Face at = f;
        while (!at.children().isEmpty()) {
            at = at.children().get(0);
        }
        return at.outer();
    }

    /** The loop starting at its point nearest p. */
    static Contour startedNear(Contour loop, Vec2 p) {
        int bestI = 0;
        double bestT = 0;
        double bestD = Double.POSITIVE_INFINITY;
        for (int i = 0; i < loop.size(); i++) {
            Curve2 c = loop.get(i);
            double t = Math.max(0, Math.min(1, OffsetSplit.param(c, p)));
            if (c instanceof Arc2 a && a.isFullCircle()) {
                t = 0;
            }
            double d = c.pointAt(t).distance(p);
            if (d < bestD) {
                bestD = d;
                bestI = i;
                bestT = t;
            }
        }
        List<Curve2> out = new ArrayList<>();
        Curve2 c = loop.get(bestI);
        Vec2 q = c.pointAt(bestT);
        // an arc cut at one of its own ends would become a whole circle: leave such pieces out
        boolean hasTail = q.distance(c.end()) > 1e-9;
        boolean hasHead = q.distance(c.start()) > 1e-9;
        if (hasTail) {
            out.add(piece(c, q, c.end()));
        }
        for (int k = 1; k < loop.size(); k++) {
            out.add(loop.get((bestI + k) % loop.size()));
        }
        if (hasHead) {
            out.add(piece(c, c.start(), q));
        }
        return new Contour(out);
    }

    static Curve2 piece(Curve2 c, Vec2 a, Vec2 b) {
        if (c instanceof Arc2 arc) {
            return new Arc2(arc.center(), a, b, arc.ccw());
        }
        return new Segment2(a, b);
    }

    /** Full circles as two half circles, so every arc move has distinct ends. */
    static Contour halved(Contour c) {
        List<Curve2> out = new ArrayList<>();
        for (Curve2 k : c.curves()) {
            if (k instanceof Arc2 a && a.isFullCircle()) {
                Vec2 opposite = a.center().times(2).minus(a.start());
                out.add(new Arc2(a.center(), a.start(), opposite, a.ccw()));
                out.add(new Arc2(a.center(), opposite, a.start(), a.ccw()));
            } else {
                out.add(k);
            }
        }
        return new Contour(out);
    }

    private static Toolpath toolpath(List<Cut> order, Level finishing, PocketTechnology t, EntryRule entry)
            throws ToolTooLargeException {
        double safe = t.zTopMm() + CLEARANCE_MM;
        Vec2 s0 = order.get(0).loop().get(0).start();
        PocketMoves moves = new PocketMoves(new Vec3(s0.x(), s0.y(), safe));
        for (int j = 1; j <= t.depthPasses(); j++) {
            double z = t.zTopMm() - j * t.depthStepMm();
            double above = PocketToolpath.entryTop(t, j);
            Vec2 cursor = null;
            // what this layer has cut so far: a link through it stays down
            Coverage cleared = Coverage.of(finishing.loops(), List.of(), t.radiusMm(), COVERAGE_CELL_MM);
            for (Cut cut : order) {
                Contour loop = cut.loop();
                Vec2 s = loop.get(0).start();
                double feed = cut.level() == 0 ? t.finishFeedMmPerMin() : t.feedMmPerMin();
                double limit = linkLimitMm(t, entry, above - z);
                List<Vec2> corners = List.of();
                if (cursor != null
                        && (feedLink(cursor, s, finishing, limit) || cleared.clearedAlong(cursor, s, loop.curves()))) {
                    moves.add(new Move.Linear(at(s, z), t.feedMmPerMin()));
                } else if (cursor != null && !(corners = detour(cursor, s, finishing, limit, t.radiusMm())).isEmpty()) {
                    for (Vec2 corner : corners) {
                        moves.add(new Move.Linear(at(corner, z), t.feedMmPerMin()));
                    }
                    moves.add(new Move.Linear(at(s, z), t.feedMmPerMin()));
                } else {
                    // straight up from where the tool is (the last loop of the layer above ends deep in the pocket)
                    moves.add(new Move.Rapid(new Vec3(moves.at().x(), moves.at().y(), safe)));
                    boolean helixFirst = entry.kind() == EntryRule.Kind.AUTO || entry.kind() == EntryRule.Kind.HELIX;
                    Helix helix =
                            helixFirst ? helixOnto(loop, finishing, t.radiusMm(), above - z, entry.angleDeg()) : null;
                    List<Curve2> down = entry.kind() == EntryRule.Kind.PLUNGE || helix != null
                            ? List.of()
                            : rampPath(loop, above - z, entry.angleDeg());
                    if (!down.isEmpty()) {
                        down = Entries.keepingTheCoreMoving(
                                entry, down, s, (a, b) -> inside(finishing, a, b), t.radiusMm(), above - z);
                    }
                    Vec2 from = helix != null
                            ? helix.from()
                            : down.isEmpty() ? s : down.get(0).start();
                    moves.add(new Move.Rapid(at(from, safe)));
                    // down at rapid to just above the floor cleared at the layer above, then no straight feed down
                    moves.add(new Move.Rapid(at(from, above)));
                    if (helix != null) {
                        moves.add(new Move.Circular(
                                at(s, z), at(helix.centre(), above), Z, helix.ccw(), helix.turns(), t.feedMmPerMin()));
                    } else if (down.isEmpty()) {
                        moves.add(new Move.Linear(at(s, z), t.feedMmPerMin()));
                    } else {
                        ramp(moves, down, above, z, t.feedMmPerMin());
                    }
                    if (moves.size() > PocketTechnology.MAX_MOVES) {
                        throw new ToolTooLargeException("the program would have more than " + PocketTechnology.MAX_MOVES
                                + " moves: use a larger depth per pass, a larger entry angle or a larger tool");
                    }
                }
                for (Curve2 c : loop.curves()) {
                    emit(moves, c, z, z, feed);
                }
                cleared.cutAlong(loop.curves());
                cursor = s;
            }
        }
        moves.add(new Move.Rapid(new Vec3(moves.at().x(), moves.at().y(), safe)));
        ToolpathSection section = new ToolpathSection(
                "pocket", Z, t.toolDiameterMm(), 1, t.spindleRpm(), new Vec3(s0.x(), s0.y(), safe), moves.list());
        return new Toolpath(List.of(section));
    }

    /** Whether the straight course a to b keeps the tool centre inside the finishing offset's region. */
    private static boolean inside(Level finishing, Vec2 a, Vec2 b) {
        double step = 0.05;
        int n = Math.max(1, (int) Math.ceil(a.distance(b) / step));
        for (int k = 1; k <= n; k++) {
            Vec2 p = a.plus(b.minus(a).times((double) k / n));
            // each sample farther from the boundary than half a step: the course between two
            // samples cannot cross it
            if (!holds(finishing, p, 0.6 * a.distance(b) / n)) {
                return false;
            }
        }
        return true;
    }

    /**
     * The way down onto a loop: the last stretch of the loop before its start, as long as a ramp
     * no steeper than angleDeg needs to descend descentMm (1 % longer, so that rounding the
     * program's Z to the micrometre never makes it steeper), round the loop as many times as that
     * takes. It ends at the loop's start, where the loop is then cut at depth: no more feed than
     * the descent needs (whole rounds of a long loop fed up to twice that).
     */
    static List<Curve2> rampPath(Contour loop, double descentMm, double angleDeg) throws ToolTooLargeException {
        double len = loop.length();
        double want = 1.01 * descentMm / Math.tan(Math.toRadians(angleDeg));
        double need = Math.ceil(want / len - 1e-9);
        if (!(len >= 1e-3) || !(need <= Entries.MAX_STEPS)) {
            throw new ToolTooLargeException(String.format(
                    java.util.Locale.ROOT,
                    "a loop of %.4f mm at X%.3f Y%.3f"
                            + " leaves no room for a ramp no steeper than %.1f deg: a centre-cutting tool (--centre-cutting)"
                            + " may plunge there (--entry plunge)",
                    len,
                    loop.get(0).start().x(),
                    loop.get(0).start().y(),
                    angleDeg));
        }
        int rounds = Math.max(1, (int) need);
        // where on the loop (mm from its start) the ramp begins
        double skip = Math.max(0, rounds * len - want);
        List<Curve2> out = new ArrayList<>();
        double at = 0;
        for (Curve2 c : loop.curves()) {
            double l = c.length();
            if (at + l <= skip + 1e-9) {
                at += l;
                continue;
            }
            if (at < skip) {
                Vec2 p = c.pointAt((skip - at) / l);
                if (p.distance(c.end()) >= PocketMoves.RESOLUTION_MM) {
                    out.add(piece(c, p, c.end()));
                }
            } else {
                out.add(c);
            }
            at += l;
        }
        for (int k = 1; k < rounds; k++) {
            out.addAll(loop.curves());
        }
        if (out.isEmpty()) {
            out.addAll(loop.curves());
        }
        return out;
    }

    /**
     * A helix down onto a loop's start: the tool centre on a circle beside the start, tangent to
     * the loop there, descending evenly as far along as a ramp along the loop would
     * ({@link #rampPath}: the same feed at the same angle), in one block (its full turns counted
     * in the block) where a ramp along a loop of many short elements takes one block per element
     * per round.
     *
     * @param from where the helix begins (XY), on its circle
     * @param centre its axis (XY)
     * @param ccw counter-clockwise seen from +Z
     * @param turns full turns before the last part turn that ends at the loop's start
     */
    record Helix(Vec2 from, Vec2 centre, boolean ccw, int turns) {}

    /** The part turn a helix ends with, at least (rad): so that its ends never coincide. */
    private static final double HELIX_LEAST_PART_TURN_RAD = 0.05;

    /**
     * The helix onto the loop's start: radius the tool's radius, else three quarters or half of
     * it (no core wider than half the tool left standing for a tool that does not cut at its
     * centre), its circle of tool centres inside the finishing offset (the tool touches no wall
     * and no island), turning with the loop first; null when none has room.
     */
    static Helix helixOnto(Contour loop, Level finishing, double radiusMm, double descentMm, double angleDeg) {
        double want = 1.01 * descentMm / Math.tan(Math.toRadians(angleDeg));
        Vec2 s = loop.get(0).start();
        Vec2 tangent = null;
        for (Curve2 c : loop.curves()) {
            if (c.length() > 1e-9) {
                tangent = c.startTangent().normalized();
                break;
            }
        }
        if (tangent == null || !(want > 0)) {
            return null;
        }
        boolean loopCcw = loop.isCcw();
        for (double f : new double[] {1, 0.75, 0.5}) {
            double r = f * radiusMm;
            for (boolean ccw : new boolean[] {loopCcw, !loopCcw}) {
                Helix h = helixAbout(s.plus(tangent.leftNormal().times(ccw ? r : -r)), r, ccw, s, want, finishing);
                if (h != null) {
                    return h;
                }
            }
            // no room beside the start: the axis in seven other directions round it, as the
            // single-contour entries try (the helix then meets the loop at an angle, at depth)
            for (int k = 1; k < 8; k++) {
                Vec2 c = s.plus(tangent.leftNormal().rotated(k * Math.PI / 4).times(r));
                Helix h = helixAbout(c, r, loopCcw, s, want, finishing);
                if (h != null) {
                    return h;
                }
            }
        }
        return null;
    }

    /** A helix about c of radius r ending at s after want mm, or null where the finishing offset does not hold it. */
    private static Helix helixAbout(Vec2 c, double r, boolean ccw, Vec2 s, double want, Level finishing) {
        if (!holds(finishing, c, r)) {
            return null;
        }
        double sweep = want / r;
        int turns = (int) Math.floor(sweep / (2 * Math.PI));
        double part = Math.max(HELIX_LEAST_PART_TURN_RAD, sweep - turns * 2 * Math.PI);
        if (turns > Entries.MAX_STEPS) {
            return null;
        }
        return new Helix(c.plus(s.minus(c).rotated(ccw ? -part : part)), c, ccw, turns);
    }

    /** Whether the circle of tool centres about c lies inside the finishing offset's region. */
    private static boolean holds(Level finishing, Vec2 c, double r) {
        int w = 0;
        for (Contour loop : finishing.loops()) {
            if (loop.distanceTo(c) < r + 1e-6) {
                return false;
            }
            w += loop.windingNumber(c);
        }
        return w == 1;
    }

    /** Down from top to z along the ramp's curves, evenly by length. */
    private static void ramp(PocketMoves moves, List<Curve2> down, double top, double z, double feed) {
        double total = down.stream().mapToDouble(Curve2::length).sum();
        double done = 0;
        for (Curve2 c : down) {
            double z0 = top - (top - z) * done / total;
            done += c.length();
            double z1 = top - (top - z) * done / total;
            emit(moves, c, z0, z1, feed);
        }
    }

    static void emit(PocketMoves moves, Curve2 c, double z0, double z1, double feed) {
        if (c instanceof Arc2 a && a.radius() >= PocketMoves.RESOLUTION_MM && !PocketMoves.same(a.start(), a.end())) {
            moves.add(new Move.Circular(at(a.end(), z1), at(a.center(), z0), Z, a.ccw(), 0, feed));
        } else {
            moves.add(new Move.Linear(at(c.end(), z1), feed));
        }
    }

    /**
     * The longest straight link at depth through material not yet cut (mm). The link slots at the
     * layer's depth, as the first loop after an entry does all round; the other way to the next
     * loop is a retract, rapids and a ramp down along it that feeds (top - z) / tan(entry angle)
     * through the same material (76 mm for 4 mm at 3 deg): a link no longer than that ramp takes
     * less feed and no lift. At least 2 D; with plunge entries (no ramp to save) just 2 D.
     */
    static double linkLimitMm(PocketTechnology t, EntryRule entry, double descentMm) {
        double shortLink = 2 * t.toolDiameterMm();
        if (entry.kind() == EntryRule.Kind.PLUNGE) {
            return shortLink;
        }
        return Math.max(shortLink, descentMm / Math.tan(Math.toRadians(entry.angleDeg())));
    }

    /**
     * What a link's corner costs in {@link #detour} beside its length (mm): of two ways nearly
     * as long, the one of fewer blocks.
     */
    private static final double CORNER_MM = 1;

    /**
     * The corners of a link that a straight line cannot make inside the finishing offset (an
     * island's offset in the way): the shortest way from p to q by straight legs through points
     * beside the elements of the finishing loops (a quarter, half and three quarters along each,
     * a little into the region), every leg inside the finishing offset ({@link #feedLink}), the
     * whole no longer than limitMm (the ramp a retract would need); empty when there is none.
     */
    static List<Vec2> detour(Vec2 p, Vec2 q, Level finishing, double limitMm, double radiusMm) {
        if (p.distance(q) > limitMm) {
            return List.of();
        }
        List<Vec2> nodes = new ArrayList<>(List.of(p, q));
        for (Contour c : finishing.loops()) {
            for (Curve2 k : c.curves()) {
                if (k.length() < 1e-6) {
                    continue;
                }
                for (double along : new double[] {0.25, 0.5, 0.75}) {
                    Vec2 at = k.pointAt(along);
                    // the region lies on the left of every finishing loop (faces CCW, holes CW)
                    Vec2 left = k instanceof Arc2 arc
                            ? (arc.ccw() ? arc.center().minus(at) : at.minus(arc.center())).normalized()
                            : k.end().minus(k.start()).normalized().leftNormal();
                    for (double away : new double[] {0.05 * radiusMm, 0.25 * radiusMm, radiusMm}) {
                        Vec2 w = at.plus(left.times(away));
                        if (p.distance(w) + w.distance(q) <= limitMm) {
                            nodes.add(w);
                        }
                    }
                }
            }
        }
        // every pair of nodes may be tried: the walls' boxes once, not once a pair
        List<List<Box2>> boxes = new ArrayList<>();
        for (Contour c : finishing.loops()) {
            boxes.add(c.curves().stream().map(Curve2::bounds).toList());
        }
        // A*: the straight distance to q never overestimates what is left
        int n = nodes.size();
        double[] way = new double[n];
        int[] from = new int[n];
        boolean[] done = new boolean[n];
        java.util.Arrays.fill(way, Double.POSITIVE_INFINITY);
        java.util.Arrays.fill(from, -1);
        way[0] = 0;
        while (true) {
            int u = -1;
            double best = Double.POSITIVE_INFINITY;
            for (int i = 0; i < n; i++) {
                double f = way[i] + nodes.get(i).distance(q);
                if (!done[i] && f < best) {
                    best = f;
                    u = i;
                }
            }
            if (u < 0) {
                return List.of();
            }
            if (u == 1) {
                break;
            }
            done[u] = true;
            for (int v = 0; v < n; v++) {
                if (done[v]) {
                    continue;
                }
                double via = way[u] + nodes.get(u).distance(nodes.get(v)) + (v == 1 ? 0 : CORNER_MM);
                if (via < way[v]
                        && via + nodes.get(v).distance(q) <= limitMm
                        && feedLink(nodes.get(u), nodes.get(v), finishing, limitMm, boxes)) {
                    way[v] = via;
                    from[v] = u;
                }
            }
        }
        List<Vec2> corners = new ArrayList<>();
        for (int v = from[1]; v > 0; v = from[v]) {
            corners.add(0, nodes.get(v));
        }
        return corners;
    }

    /**
     * A straight feed link is safe when no longer than limitMm and inside the finishing offset's
     * region: the tool's disc along it touches no wall and no island.
     */
    static boolean feedLink(Vec2 p, Vec2 q, Level finishing, double limitMm) {
        return feedLink(p, q, finishing, limitMm, null);
    }

    /**
     * {@link #feedLink(Vec2, Vec2, Level, double)} with the boxes of the finishing loops' curves
     * (null: none): a crossing lies in both curves' boxes, so an element whose box the link's
     * misses is not asked. On dxf2gcode's FLH-001 (3 mm tool, its loops of short arcs) the
     * detours' searches took most of 87 s asking every element for every pair of nodes.
     */
    private static boolean feedLink(Vec2 p, Vec2 q, Level finishing, double limitMm, List<List<Box2>> boxes) {
        if (p.distance(q) > limitMm) {
            return false;
        }
        if (p.distance(q) < 1e-9) {
            return true;
        }
        Segment2 link = new Segment2(p, q);
        Tolerance tol = new Tolerance(1e-9, 1e-12);
        Box2 reach = link.bounds();
        Box2 near = new Box2(reach.minX() - 1e-6, reach.minY() - 1e-6, reach.maxX() + 1e-6, reach.maxY() + 1e-6);
        int w = 0;
        Vec2 mid = p.interpolate(q, 0.5);
        for (int ci = 0; ci < finishing.loops().size(); ci++) {
            Contour c = finishing.loops().get(ci);
            for (int ki = 0; ki < c.curves().size(); ki++) {
                Curve2 k = c.curves().get(ki);
                if (boxes != null && !near.intersects(boxes.get(ci).get(ki))) {
                    continue;
                }
                for (Vec2 x : Intersections.of(link, k, tol)) {
                    if (x.distance(p) > 1e-6 && x.distance(q) > 1e-6) {
                        return false;
                    }
                }
            }
            w += c.windingNumber(mid);
        }
        return w == 1;
    }

    private static Vec3 at(Vec2 p, double z) {
        return new Vec3(p.x(), p.y(), z);
    }
}
