package org.fresa.check;

import java.util.List;
import org.fresa.geom.Vec3;

/**
 * No cutting move descends into the material steeper than its tool may enter: the tool's entry
 * angle (3 degrees for a cutter that does not cut at its centre), any angle for a drill or a
 * centre-cutting cutter asked to plunge. A descent that ends above the material's top cuts air.
 *
 * <p>The angle is measured from the horizontal over the whole block (a straight move or a helix
 * about Z, whose descent is uniform); arcs in G18/G19 are measured chord by chord, one degree of
 * arc each. The coordinates' last written digit is not counted against the block: the descent
 * less one step over the horizontal length plus one step.
 */
public record EntryAngleRule() implements Rule {

    /** Allowance on the chords of an arc in G18/G19, whose tangent turns within each chord, degrees. */
    static final double CHORD_ALLOWANCE_DEG = 0.5;

    @Override
    public String name() {
        return "entry angle";
    }

    @Override
    public String statement() {
        return "no cutting move descends into the material steeper than its tool's entry angle";
    }

    @Override
    public String broken(Step s, Limits l) {
        List<Vec3> p = s.path();
        if (!s.feedMove() || p.size() < 2) {
            return null;
        }
        ToolLimits tool = l.tool(s.tool());
        if (tool.plunge()) {
            return null;
        }
        double q = s.dialect().quantumMm();
        double top = l.materialTopZMm();
        double angle;
        Vec3 a = p.get(0);
        Vec3 b = p.get(p.size() - 1);
        if (p.size() == 2 || s.arcInPlane()) {
            double drop = a.z() - b.z() - q;
            if (drop <= 0 || !(b.z() < top - q)) {
                return null;
            }
            double h = s.arcInPlane() ? s.horizontalMm() : Math.hypot(b.x() - a.x(), b.y() - a.y());
            angle = Math.toDegrees(Math.atan2(drop, h + q));
            if (angle <= tool.entryAngleDeg() + 1e-9) {
                return null;
            }
        } else {
            angle = 0;
            for (int i = 1; i < p.size(); i++) {
                Vec3 u = p.get(i - 1);
                Vec3 v = p.get(i);
                double drop = u.z() - v.z();
                if (drop > 0 && v.z() < top - q) {
                    angle = Math.max(angle, Math.toDegrees(Math.atan2(drop, Math.hypot(v.x() - u.x(), v.y() - u.y()))));
                }
            }
            if (angle <= tool.entryAngleDeg() + CHORD_ALLOWANCE_DEG) {
                return null;
            }
        }
        return "the tool enters the material at " + Num.deg(angle) + " degrees" + (angle >= 89.95 ? " (a plunge)" : "")
                + ", steeper than the " + Num.deg(tool.entryAngleDeg()) + " degrees allowed for tool " + s.tool()
                + " (" + tool.kind() + ")";
    }
}
