package org.fresa.pocket;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

/**
 * A pocket plan as a generic {@link Toolpath} for the G-code posts: every depth pass at its own
 * depth, each sub-area entered by a helix or a zig-zag ramp no steeper than the entry angle
 * ({@link Entries}; no vertical plunge into solid material unless the tool cuts at its centre and
 * a plunge is asked for), passes inside out, links inside cleared material as straight feed moves (the next outer
 * pass encloses the inner one), a retract and rapid between sibling sub-areas, arcs as
 * {@link Move.Circular} about +Z. Climb milling reverses each pass (counter-clockwise with a
 * clockwise spindle) unless conventional milling is asked for. Where the thesis's near-tangent
 * snap leaves an arc end off its circle, the arc ends on its circle and a short feed move joins
 * the junction, so start and end radii always agree.
 */
public final class PocketToolpath {
    private static final Vec3 Z = new Vec3(0, 0, 1);
    private static final double CLEARANCE_MM = 5;

    private PocketToolpath() {}

    /** The moves of the plan with the default entries ({@link EntryRule#DEFAULT}); climb reverses the passes' direction. */
    public static Toolpath of(PocketPlan plan, boolean climb) throws ToolTooLargeException {
        return of(plan, climb, EntryRule.DEFAULT);
    }

    /**
     * The moves of the plan; climb reverses the passes' direction; each sub-area at each depth
     * is entered as the rule allows ({@link Entries}): a helix inside the region the passes clear,
     * else a zig-zag ramp along the sub-area's innermost pass.
     *
     * @throws ToolTooLargeException when an entry has no room for a helix or a ramp and the tool
     *     may not plunge, or the program would have more than {@link PocketTechnology#MAX_MOVES} moves
     */
    public static Toolpath of(PocketPlan plan, boolean climb, EntryRule rule) throws ToolTooLargeException {
        PocketTechnology t = plan.technology();
        double safe = t.zTopMm() + CLEARANCE_MM;
        List<List<PassPiece>> passes = new ArrayList<>();
        for (PocketPass p : plan.milled()) {
            passes.add(climb ? p.reversed().pieces() : p.pieces());
        }
        Vec2 s0 = plan.milled().isEmpty() || passes.get(0).isEmpty()
                ? Vec2.ZERO
                : passes.get(0).get(0).start();
        PocketMoves moves = new PocketMoves(new Vec3(s0.x(), s0.y(), safe));
        List<PocketPass> milled = plan.milled();
        Entries.Room room = room(milled, t.finishFraction() * t.toolDiameterMm());
        int levels = t.depthPasses();
        for (int j = 1; j <= levels; j++) {
            double z = t.zTopMm() - j * t.depthStepMm();
            for (int k = 0; k < milled.size(); k++) {
                PocketPass pass = milled.get(k);
                List<PassPiece> pieces = passes.get(k);
                if (pieces.isEmpty()) {
                    continue;
                }
                Vec2 s = pieces.get(0).start();
                boolean link = k > 0 && milled.get(k - 1).linksOutwardTo(pass);
                double feed = pass.finishing() ? t.finishFeedMmPerMin() : t.feedMmPerMin();
                if (link) {
                    moves.add(new Move.Linear(at(s, z), t.feedMmPerMin()));
                } else {
                    double layerTop = z + t.depthStepMm();
                    moves.add(new Move.Rapid(new Vec3(moves.at().x(), moves.at().y(), safe)));
                    moves.add(new Move.Rapid(at(s, safe)));
                    // down at rapid through the pocket cleared at the layer above, to just above its floor
                    double above = entryTop(t, j);
                    moves.add(new Move.Rapid(at(s, above)));
                    // no straight feed down at all: a helix or a zig-zag ramp within the entry angle
                    Entry entry = Entries.choose(
                                    rule,
                                    s,
                                    chain(pieces),
                                    onwards(milled, passes, k),
                                    climb,
                                    room,
                                    room,
                                    t.radiusMm(),
                                    above - z)
                            .orElseThrow(() -> Entries.tooSmallToGoDown(s));
                    moves.addAll(entry.moves(above, z, t.feedMmPerMin()));
                }
                for (PassPiece pc : pieces) {
                    piece(moves, pc, z, z, feed);
                }
                if (moves.size() > PocketTechnology.MAX_MOVES) {
                    throw new ToolTooLargeException("the program would have more than " + PocketTechnology.MAX_MOVES
                            + " moves: use a larger depth per pass, a larger entry angle or a larger tool");
                }
            }
        }
        if (moves.size() > 0) {
            moves.add(new Move.Rapid(new Vec3(moves.at().x(), moves.at().y(), safe)));
        }
        ToolpathSection section = new ToolpathSection(
                "pocket", Z, t.toolDiameterMm(), 1, t.spindleRpm(), new Vec3(s0.x(), s0.y(), safe), moves.list());
        return new Toolpath(List.of(section));
    }

    /**
     * What the tool follows at depth after pass k: the passes joined to it outward, each by a
     * straight link from where the one before ends (a ramp's legs may run on along it).
     */
    private static List<Curve2> onwards(List<PocketPass> milled, List<List<PassPiece>> passes, int k) {
        List<Curve2> out = new ArrayList<>();
        for (int i = k + 1; i < milled.size() && milled.get(i - 1).linksOutwardTo(milled.get(i)); i++) {
            List<PassPiece> before = passes.get(i - 1);
            List<PassPiece> next = passes.get(i);
            if (before.isEmpty() || next.isEmpty()) {
                break;
            }
            add(out, before.get(before.size() - 1).end(), next.get(0).start());
            out.addAll(chain(next));
        }
        return out;
    }

    /** Above the stock before the first layer (mm): its top face is as delivered. */
    static final double ABOVE_STOCK_MM = 1;

    /** Above the floor the layer before has cut (mm): a face just machined, so the entry wastes no feed in air. */
    static final double ABOVE_FLOOR_MM = 0.2;

    /**
     * The height an entry into depth layer j (1 = the first) starts from: just above the material
     * of that layer, which at the first layer is the stock's top and from the second on the floor
     * the layer above has left inside the region its passes cleared (where every entry lies).
     */
    static double entryTop(PocketTechnology t, int j) {
        double layerTop = t.zTopMm() - (j - 1) * t.depthStepMm();
        return layerTop + (j == 1 ? ABOVE_STOCK_MM : ABOVE_FLOOR_MM);
    }

    /**
     * Where a helix (or a straight zig-zag's leg) may lie: inside the loop of a milled pass,
     * everything inside which is cleared at every depth; inside the finishing pass only as far as
     * the finishing allowance stays.
     *
     * @param milled the passes as milled
     * @param allowanceMm the finishing allowance (mm)
     */
    public static Entries.Room room(List<PocketPass> milled, double allowanceMm) {
        List<Contour> loops = new ArrayList<>();
        List<Double> margins = new ArrayList<>();
        for (PocketPass p : milled) {
            List<Curve2> c = chain(p.pieces());
            if (!c.isEmpty()) {
                loops.add(new Contour(c));
                margins.add(p.finishing() ? allowanceMm : 0.0);
            }
        }
        return (centre, r) -> {
            for (int i = 0; i < loops.size(); i++) {
                Contour loop = loops.get(i);
                if (loop.distanceTo(centre) >= r + margins.get(i) + 1e-6 && loop.windingNumber(centre) != 0) {
                    return true;
                }
            }
            return false;
        };
    }

    /** The pieces as the curves the tool follows ({@link #piece}): arcs on their circles, snapped junctions as lines. */
    static List<Curve2> chain(List<PassPiece> pieces) {
        List<Curve2> out = new ArrayList<>();
        Vec2 at = pieces.isEmpty() ? Vec2.ZERO : pieces.get(0).start();
        for (PassPiece pc : pieces) {
            Vec2 c = pc.center();
            double rn = pc.isArc() ? pc.radiusMm() : 0;
            if (!pc.isArc() || rn < PocketMoves.RESOLUTION_MM || PocketMoves.same(pc.start(), pc.end())) {
                add(out, at, pc.end());
            } else {
                Vec2 start = onCircle(pc.start(), c, rn);
                Vec2 end = onCircle(pc.end(), c, rn);
                add(out, at, start);
                out.add(new Arc2(c, start, end, pc.ccw()));
                add(out, end, pc.end());
            }
            at = pc.end();
        }
        return out;
    }

    private static void add(List<Curve2> out, Vec2 from, Vec2 to) {
        if (from.distance(to) > 1e-9) {
            out.add(new Segment2(from, to));
        }
    }

    /** One piece from height z0 to z1 (a helix for arcs when they differ). */
    private static void piece(PocketMoves moves, PassPiece pc, double z0, double z1, double feed) {
        if (!pc.isArc()) {
            moves.add(new Move.Linear(at(pc.end(), z1), feed));
            return;
        }
        Vec2 c = pc.center();
        double rn = pc.radiusMm();
        if (rn < PocketMoves.RESOLUTION_MM || PocketMoves.same(pc.start(), pc.end())) {
            moves.add(new Move.Linear(at(pc.end(), z1), feed));
            return;
        }
        // the arc runs on its true offset circle; snapped junctions join it by short feed moves
        Vec2 start = onCircle(pc.start(), c, rn);
        Vec2 end = onCircle(pc.end(), c, rn);
        if (start.distance(pc.start()) > 1e-9) {
            moves.add(new Move.Linear(at(start, z0), feed));
        }
        moves.add(new Move.Circular(at(end, z1), at(c, z0), Z, pc.ccw(), 0, feed));
        if (end.distance(pc.end()) > 1e-9) {
            moves.add(new Move.Linear(at(pc.end(), z1), feed));
        }
    }

    private static Vec2 onCircle(Vec2 p, Vec2 c, double r) {
        double d = p.distance(c);
        return d < 1e-12 ? p : c.plus(p.minus(c).times(r / d));
    }

    private static Vec3 at(Vec2 p, double z) {
        return new Vec3(p.x(), p.y(), z);
    }

    /** Total length of the feed and rapid moves (mm): lines and helices in space, full turns counted. */
    public static double lengthMm(Toolpath path) {
        double len = 0;
        for (ToolpathSection s : path.sections()) {
            Vec3 cur = s.start();
            for (Move m : s.moves()) {
                if (m instanceof Move.Circular c) {
                    Vec2 a = new Vec2(
                            cur.x() - c.center().x(), cur.y() - c.center().y());
                    Vec2 b = new Vec2(
                            c.end().x() - c.center().x(),
                            c.end().y() - c.center().y());
                    double sweep = Math.atan2(a.cross(b), a.dot(b));
                    if (c.ccw() && sweep < 0) {
                        sweep += 2 * Math.PI;
                    } else if (!c.ccw() && sweep > 0) {
                        sweep -= 2 * Math.PI;
                    }
                    if (Math.abs(sweep) < 1e-12 && a.distance(b) < 1e-9) {
                        sweep = 2 * Math.PI;
                    }
                    // a helix's extra full turns and its rise
                    double turnsMm = (Math.abs(sweep) + 2 * Math.PI * c.turns()) * a.norm();
                    len += Math.hypot(turnsMm, c.end().z() - cur.z());
                } else {
                    len += cur.minus(m.end()).norm();
                }
                cur = m.end();
            }
        }
        return len;
    }
}
