package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;

/** Collects the moves of a section in the feature frame, tracking where the tool is. */
final class MoveBuilder {
    private final List<Move> moves = new ArrayList<>();
    private Vec3 at;

    MoveBuilder(Vec3 start) {
        this.at = start;
    }

    Vec3 at() {
        return at;
    }

    List<Move> moves() {
        return moves;
    }

    void rapid(Vec3 p) {
        if (!p.equals(at)) {
            moves.add(new Move.Rapid(p));
            at = p;
        }
    }

    void feed(Vec3 p, double f) {
        if (!p.equals(at)) {
            moves.add(new Move.Linear(p, f));
            at = p;
        }
    }

    /** Moves that start where the tool is (an entry's). */
    void append(List<Move> ms) {
        for (Move m : ms) {
            moves.add(m);
            at = m.end();
        }
    }

    /** The tool waits where it is. */
    void dwell(double seconds) {
        moves.add(new Move.Dwell(at, seconds));
    }

    void spindleStop() {
        moves.add(new Move.SpindleStop(at));
    }

    void spindleStart(double rpm, boolean clockwise) {
        moves.add(new Move.SpindleStart(at, rpm, clockwise));
    }

    void arc(Vec3 end, Vec3 center, boolean ccw, int turns, double f) {
        moves.add(new Move.Circular(end, center, Vec3.UNIT_Z, ccw, turns, f));
        at = end;
    }

    /** Cuts the curves at height z. */
    void curves(List<Curve2> cs, double z, double f) {
        for (Curve2 c : cs) {
            if (c instanceof Segment2 s) {
                feed(Vec3.of(s.end(), z), f);
            } else if (c instanceof Arc2 a) {
                if (a.radius() == 0) {
                    continue;
                }
                arc(Vec3.of(a.end(), z), Vec3.of(a.center(), z), a.ccw(), 0, f);
            }
        }
    }

    /** Lifts to z where the tool is, then traverses to (xy, z). */
    void liftAndTraverse(Vec2 xy, double z) {
        if (at.z() < z) {
            rapid(new Vec3(at.x(), at.y(), z));
        }
        rapid(Vec3.of(xy, Math.max(z, at.z())));
        rapid(Vec3.of(xy, z));
    }
}
