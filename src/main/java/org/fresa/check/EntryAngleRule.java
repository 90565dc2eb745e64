package org.fresa.check;

import java.util.List;
import org.fresa.geom.Vec3;

/**
 * No cutting move descends into the material steeper than its tool may enter: the tool's entry
 * angle (3 degrees for a cutter that does not cut at its centre), any angle for a drill or a
 * centre-cutting cutter asked to plunge. Descending means moving against the tool axis (from the
 * tip towards the spindle, +Z unless the post states another axis for the section); a descent
 * that ends where the tool does not touch the stock cuts air, and so does one along +Z where the
 * program has removed the material before ({@link Material}: the tool's disc less one cell of its
 * grid meets nothing above its bottom), and one straight down into a hole
 * the program made before, wide enough for the cutter's core ({@link Pilot}), meets material only
 * with the cutting part of the end face.
 *
 * <p>The angle is measured from the plane normal to the tool axis over the whole block (a straight
 * move, or a helix about the axis, whose descent is uniform); other arcs are measured chord by
 * chord, one degree of arc each. The coordinates' last written digit is not counted against a
 * block: the descent less one step over the sideways length plus one step.
 */
public final class EntryAngleRule extends Rule {

    /** Allowance on the chords of an arc about another axis, whose tangent turns within each chord, degrees. */
    static final double CHORD_ALLOWANCE_DEG = 0.5;

    public EntryAngleRule() {
        super("entry angle", "no cutting move descends into the material steeper than its tool's entry angle");
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
        Vec3 axis = s.axis();
        double angle;
        Vec3 a = p.get(0);
        Vec3 b = p.get(p.size() - 1);
        boolean helix = s.arcInPlane() && Math.abs(axis.z()) > 1 - 1e-9;
        if (p.size() == 2 || helix) {
            Vec3 d = b.minus(a);
            double drop = -d.dot(axis) - q;
            if (drop <= 0 || !l.stock().touches(b, tool.radiusMm(), q) || inCleared(s, tool, q)) {
                return null;
            }
            if (p.size() == 2 && s.pilots().stream().anyMatch(h -> h.admits(a, b, axis, tool.radiusMm(), q))) {
                // straight down into a hole made before: its core that does not cut meets no material
                return null;
            }
            double side =
                    helix ? s.horizontalMm() : d.minus(axis.times(d.dot(axis))).norm();
            angle = Math.toDegrees(Math.atan2(drop, side + q));
            if (angle <= tool.entryAngleDeg() + 1e-9) {
                return null;
            }
        } else {
            angle = 0;
            for (int i = 1; i < p.size(); i++) {
                Vec3 d = p.get(i).minus(p.get(i - 1));
                double drop = -d.dot(axis);
                if (drop > 0
                        && l.stock().touches(p.get(i), tool.radiusMm(), q)
                        && !inCleared(p.get(i - 1), p.get(i), s, tool, q)) {
                    double side = d.minus(axis.times(d.dot(axis))).norm();
                    angle = Math.max(angle, Math.toDegrees(Math.atan2(drop, side)));
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

    /** Whether the whole descent of the block runs where the program has removed the material. */
    private static boolean inCleared(Step s, ToolLimits tool, double q) {
        List<Vec3> p = s.path();
        for (int i = 1; i < p.size(); i++) {
            if (!inCleared(p.get(i - 1), p.get(i), s, tool, q)) {
                return false;
            }
        }
        return true;
    }

    /**
     * Whether the tool meets no material the program has left along the segment: the material
     * model of the program so far ({@link Material}), along +Z only.
     */
    private static boolean inCleared(Vec3 a, Vec3 b, Step s, ToolLimits tool, double q) {
        Material m = s.material();
        if (m == null || !m.known() || !Material.alongZ(s.axis())) {
            return false;
        }
        return m.deepest(a, b, tool.radiusMm(), tool)
                .map(h -> h.depthMm() <= q + 1e-6)
                .orElse(true);
    }
}
