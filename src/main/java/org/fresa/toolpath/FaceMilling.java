package org.fresa.toolpath;

import org.fresa.geom.Box2;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.ToolpathSection;

/**
 * A planar face milled in straight passes along its course of travel (ISO 14649-11 plane
 * milling), in the feature frame, layer by layer from {@code topZ} to {@code bottomZ}.
 *
 * <p>The passes are spread evenly across the removal boundary, at most the stepover apart, with
 * the tool's edge flush with the boundary at both sides (one centred pass when the face is no
 * wider than the tool). Each pass runs beyond the boundary so that the tool's edge clears it by
 * {@code overcutMm} at both ends (NIST's example 1 output clears it by 0.25 D). With
 * {@code stepLeft} each pass lies to the left of the previous one seen along the course of
 * travel (ISO stepover_direction LEFT), else to its right; bidirectional passes are joined at depth
 * outside the boundary, unidirectional ones by a lift to the retract height.
 */
public final class FaceMilling {
    private FaceMilling() {}

    /**
     * @param boundary the removal boundary's extent in the feature plane (mm)
     * @param courseOfTravel the pass direction (unit or not)
     */
    public static ToolpathSection section(
            String label,
            Box2 boundary,
            Vec2 courseOfTravel,
            Heights h,
            Tooling tool,
            double stepoverMm,
            double axialDepthMm,
            double overcutMm,
            boolean bidirectional,
            boolean stepLeft) {
        Vec2 u = courseOfTravel.normalized();
        Vec2 n = u.leftNormal();
        double umin = Double.POSITIVE_INFINITY;
        double umax = Double.NEGATIVE_INFINITY;
        double nmin = Double.POSITIVE_INFINITY;
        double nmax = Double.NEGATIVE_INFINITY;
        for (Vec2 p : new Vec2[] {
            new Vec2(boundary.minX(), boundary.minY()),
            new Vec2(boundary.maxX(), boundary.minY()),
            new Vec2(boundary.maxX(), boundary.maxY()),
            new Vec2(boundary.minX(), boundary.maxY())
        }) {
            umin = Math.min(umin, p.dot(u));
            umax = Math.max(umax, p.dot(u));
            nmin = Math.min(nmin, p.dot(n));
            nmax = Math.max(nmax, p.dot(n));
        }
        double r = tool.radiusMm();
        double width = nmax - nmin;
        double d = Math.min(stepoverMm, tool.diameterMm());
        int m = width <= tool.diameterMm() ? 0 : (int) Math.ceil((width - tool.diameterMm()) / d - 1e-9);
        double[] across = new double[m + 1];
        for (int k = 0; k <= m; k++) {
            double t = (width - 2 * r) * k / m;
            across[k] = m == 0 ? (nmin + nmax) / 2 : stepLeft ? (nmin + r) + t : (nmax - r) - t;
        }
        double a = umin - r - overcutMm;
        double b = umax + r + overcutMm;
        Vec2 first = n.times(across[0]).plus(u.times(a));
        MoveBuilder mb = new MoveBuilder(Vec3.of(first, h.clearanceZ()));
        for (double z : h.layers(axialDepthMm)) {
            for (int k = 0; k <= m; k++) {
                boolean forward = !bidirectional || k % 2 == 0;
                Vec2 s = n.times(across[k]).plus(u.times(forward ? a : b));
                Vec2 e = n.times(across[k]).plus(u.times(forward ? b : a));
                if (k == 0 || !bidirectional) {
                    mb.liftAndTraverse(s, h.retractZ());
                    // the pass starts beyond the boundary, in the air
                    mb.feed(Vec3.of(s, z), tool.plungeFeedMmPerMin());
                } else {
                    mb.feed(Vec3.of(s, z), tool.feedMmPerMin());
                }
                mb.feed(Vec3.of(e, z), tool.feedMmPerMin());
            }
            mb.rapid(new Vec3(mb.at().x(), mb.at().y(), h.retractZ()));
        }
        mb.rapid(new Vec3(mb.at().x(), mb.at().y(), h.clearanceZ()));
        return tool.section(label, Vec3.of(first, h.clearanceZ()), mb.moves());
    }
}
