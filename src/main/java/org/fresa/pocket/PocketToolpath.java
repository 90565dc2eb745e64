package org.fresa.pocket;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

/**
 * A pocket plan as a generic {@link Toolpath} for the G-code posts: every depth pass at its own
 * depth, each sub-area entered by a ramp along its innermost pass (no vertical plunge into solid
 * material), passes inside out, links inside cleared material as straight feed moves (the next outer
 * pass encloses the inner one), a retract and rapid between sibling sub-areas, arcs as
 * {@link Move.Circular} about +Z. Climb milling reverses each pass (counter-clockwise with a
 * clockwise spindle) unless conventional milling is asked for. Where the thesis's near-tangent
 * snap leaves an arc end off its circle, the arc ends on its circle and a short feed move joins
 * the junction, so start and end radii always agree.
 */
public final class PocketToolpath {
    private static final Vec3 Z = new Vec3(0, 0, 1);
    private static final double CLEARANCE_MM = 5;

    private PocketToolpath() {
    }

    /** The moves of the plan; climb reverses the passes' direction. */
    public static Toolpath of(PocketPlan plan, boolean climb) {
        PocketTechnology t = plan.technology();
        List<Move> moves = new ArrayList<>();
        double safe = t.zTopMm() + CLEARANCE_MM;
        List<List<PassPiece>> passes = new ArrayList<>();
        for (PocketPass p : plan.milled()) {
            passes.add(climb ? p.reversed().pieces() : p.pieces());
        }
        List<PocketPass> milled = plan.milled();
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
                    moves.add(new Move.Rapid(new Vec3(lastXY(moves, s).x(), lastXY(moves, s).y(), safe)));
                    moves.add(new Move.Rapid(at(s, safe)));
                    moves.add(new Move.Rapid(at(s, t.zTopMm() + 1)));
                    moves.add(new Move.Linear(at(s, layerTop), t.feedMmPerMin()));
                    // ramp down along the innermost pass itself instead of plunging into solid material
                    double total = 0;
                    for (PassPiece pc : pieces) {
                        total += Math.max(pc.lengthMm(), pc.start().distance(pc.end()));
                    }
                    if (total < 1e-6) {
                        moves.add(new Move.Linear(at(s, z), t.feedMmPerMin()));
                    } else {
                        double done = 0;
                        for (PassPiece pc : pieces) {
                            double len = Math.max(pc.lengthMm(), pc.start().distance(pc.end()));
                            double z0 = layerTop - (layerTop - z) * done / total;
                            done += len;
                            double z1 = layerTop - (layerTop - z) * done / total;
                            piece(moves, pc, z0, z1, t.feedMmPerMin());
                        }
                    }
                }
                for (PassPiece pc : pieces) {
                    piece(moves, pc, z, z, feed);
                }
            }
        }
        if (!moves.isEmpty()) {
            Vec3 last = moves.get(moves.size() - 1).end();
            moves.add(new Move.Rapid(new Vec3(last.x(), last.y(), safe)));
        }
        Vec2 s0 = milled.isEmpty() || passes.get(0).isEmpty() ? Vec2.ZERO : passes.get(0).get(0).start();
        ToolpathSection section = new ToolpathSection("pocket", Z, t.toolDiameterMm(), 1, t.spindleRpm(),
                new Vec3(s0.x(), s0.y(), safe), moves);
        return new Toolpath(List.of(section));
    }

    /** One piece from height z0 to z1 (a helix for arcs when they differ). */
    private static void piece(List<Move> moves, PassPiece pc, double z0, double z1, double feed) {
        if (!pc.isArc()) {
            moves.add(new Move.Linear(at(pc.end(), z1), feed));
            return;
        }
        Vec2 c = pc.center();
        double rn = pc.radiusMm();
        if (rn < 1e-6 || pc.start().distance(pc.end()) < 1e-6) {
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

    private static Vec2 lastXY(List<Move> moves, Vec2 fallback) {
        if (moves.isEmpty()) {
            return fallback;
        }
        Vec3 e = moves.get(moves.size() - 1).end();
        return new Vec2(e.x(), e.y());
    }

    private static Vec3 at(Vec2 p, double z) {
        return new Vec3(p.x(), p.y(), z);
    }

    /** Total length of the feed and rapid moves' XY projection plus Z travel (mm). */
    public static double lengthMm(Toolpath path) {
        double len = 0;
        for (ToolpathSection s : path.sections()) {
            Vec3 cur = s.start();
            for (Move m : s.moves()) {
                if (m instanceof Move.Circular c) {
                    Vec2 a = new Vec2(cur.x() - c.center().x(), cur.y() - c.center().y());
                    Vec2 b = new Vec2(c.end().x() - c.center().x(), c.end().y() - c.center().y());
                    double sweep = Math.atan2(a.cross(b), a.dot(b));
                    if (c.ccw() && sweep < 0) {
                        sweep += 2 * Math.PI;
                    } else if (!c.ccw() && sweep > 0) {
                        sweep -= 2 * Math.PI;
                    }
                    len += Math.abs(sweep) * a.norm();
                } else {
                    len += cur.minus(m.end()).norm();
                }
                cur = m.end();
            }
        }
        return len;
    }
}
