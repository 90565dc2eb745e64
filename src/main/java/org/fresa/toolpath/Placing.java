package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;

/**
 * Puts a section computed in its feature frame into the workpiece frame (thesis section
 * 3.2.2.3): points through the placement, arc axes and the tool axis as directions. Arcs stay
 * arcs; their normal becomes the feature's axis, which the posts write as G17/G18/G19 when it
 * is a principal axis.
 */
public final class Placing {
    private Placing() {}

    public static ToolpathSection place(ToolpathSection s, Transform3 featureToWorkpiece) {
        List<Move> moves = new ArrayList<>(s.moves().size());
        for (Move m : s.moves()) {
            moves.add(place(m, featureToWorkpiece));
        }
        return new ToolpathSection(
                s.label(),
                unit(featureToWorkpiece.applyToDirection(s.toolAxis())),
                s.toolDiameterMm(),
                s.toolNumber(),
                s.spindleRpm(),
                featureToWorkpiece.applyToPoint(s.start()),
                moves);
    }

    static Move place(Move m, Transform3 t) {
        if (m instanceof Move.Rapid r) {
            return new Move.Rapid(t.applyToPoint(r.end()));
        }
        if (m instanceof Move.Linear l) {
            return new Move.Linear(t.applyToPoint(l.end()), l.feedMmPerMin());
        }
        if (m instanceof Move.Circular c) {
            return new Move.Circular(
                    t.applyToPoint(c.end()),
                    t.applyToPoint(c.center()),
                    unit(t.applyToDirection(c.normal())),
                    c.ccw(),
                    c.turns(),
                    c.feedMmPerMin());
        }
        if (m instanceof Move.Dwell d) {
            return new Move.Dwell(t.applyToPoint(d.end()), d.seconds());
        }
        if (m instanceof Move.SpindleStop s) {
            return new Move.SpindleStop(t.applyToPoint(s.end()));
        }
        Move.SpindleStart on = (Move.SpindleStart) m;
        return new Move.SpindleStart(t.applyToPoint(on.end()), on.rpm(), on.clockwise());
    }

    /** Snaps exact axis directions (rotation round-off of 1e-17) and renormalises. */
    static Vec3 unit(Vec3 v) {
        double x = Math.abs(v.x()) < 1e-12 ? 0 : v.x();
        double y = Math.abs(v.y()) < 1e-12 ? 0 : v.y();
        double z = Math.abs(v.z()) < 1e-12 ? 0 : v.z();
        return new Vec3(x, y, z).normalized();
    }
}
