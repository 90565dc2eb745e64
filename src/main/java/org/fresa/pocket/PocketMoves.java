package org.fresa.pocket;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;

/**
 * The moves of a pocket program as they are collected, with no degenerate block: a straight move
 * (rapid or feed) that would not take the tool at least one micrometre away, or that the posts
 * would write with the same three-decimal coordinates as the tool's position, is left out (the
 * next move goes to its own end, so nothing drifts); an arc whose ends the posts would write
 * alike, but which is not a full turn, becomes a straight move, since a control reads such a block
 * as a whole circle; a level full turn is written as two half turns. Units mm.
 */
final class PocketMoves {

    /** The resolution of the posts' coordinates (mm): three decimals. */
    static final double RESOLUTION_MM = 1e-3;

    private final List<Move> moves = new ArrayList<>();
    private Vec3 at;

    /** Moves from the section's start, where the tool is before the first move. */
    PocketMoves(Vec3 start) {
        this.at = start;
    }

    /** Where the tool is after the moves so far. */
    Vec3 at() {
        return at;
    }

    /** How many moves are kept. */
    int size() {
        return moves.size();
    }

    /** The moves kept. */
    List<Move> list() {
        return moves;
    }

    void addAll(List<Move> ms) {
        for (Move m : ms) {
            add(m);
        }
    }

    void add(Move m) {
        if (m instanceof Move.Rapid || m instanceof Move.Linear) {
            if (same(at, m.end())) {
                return;
            }
        } else if (m instanceof Move.Circular c && c.turns() == 0) {
            Vec2 a = new Vec2(at.x(), at.y());
            Vec2 b = new Vec2(c.end().x(), c.end().y());
            // an exact return to the start is a full turn asked for; a sliver of arc is not
            if (a.distance(b) > 1e-12 && same(a, b)) {
                add(new Move.Linear(c.end(), c.feedMmPerMin()));
                return;
            }
            if (a.distance(b) <= 1e-12 && Math.abs(at.z() - c.end().z()) < 1e-12) {
                // a level full turn (a helix's last, at depth) in two halves: as one block it would
                // repeat word for word the helix's last block on a post that writes each turn alone
                Vec2 ctr = new Vec2(c.center().x(), c.center().y());
                Vec2 opposite = ctr.times(2).minus(a);
                moves.add(new Move.Circular(
                        new Vec3(opposite.x(), opposite.y(), at.z()),
                        c.center(),
                        c.normal(),
                        c.ccw(),
                        0,
                        c.feedMmPerMin()));
                moves.add(c);
                return;
            }
        }
        moves.add(m);
        at = m.end();
    }

    /** Whether the posts would write the two points alike, or they are less than a micrometre apart. */
    static boolean same(Vec3 a, Vec3 b) {
        return a.distance(b) < RESOLUTION_MM
                || (grid(a.x()) == grid(b.x()) && grid(a.y()) == grid(b.y()) && grid(a.z()) == grid(b.z()));
    }

    /** As {@link #same(Vec3, Vec3)} in the plane. */
    static boolean same(Vec2 a, Vec2 b) {
        return a.distance(b) < RESOLUTION_MM || (grid(a.x()) == grid(b.x()) && grid(a.y()) == grid(b.y()));
    }

    private static long grid(double v) {
        return Math.round(v / RESOLUTION_MM);
    }
}
