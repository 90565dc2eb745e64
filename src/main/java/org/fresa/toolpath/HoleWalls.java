package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleUnaryOperator;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec3;
import org.fresa.model.ArcGeometry;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;

/**
 * Whether a hole's tool stays within the hole's wall: the tool's end (a drill's point, a ball, a
 * flat end with its corner) swept along the moves, at every height between the hole's top and its
 * depth, reaches no farther from the axis than the hole's radius. A boring bar or a drill wider
 * than the hole was taken down it as wide as it is. Below the depth the bottom condition's shape
 * is not judged here (how deep a conical or spherical bottom reaches is written differently by
 * different writers). Units mm, the hole's frame: its axis the z axis, its top z 0.
 */
final class HoleWalls {

    /** Heights between checks of the tool's reach along its end (mm). */
    static final double STEP_MM = 0.02;

    /** The chord of an arc's points (mm). */
    static final double CHORD_MM = 1e-3;

    private HoleWalls() {}

    /**
     * The reach of the tool from its axis at a height above its tip: a drill's point, a ball, or a
     * flat end rounded by its corner radius.
     *
     * @param pointLengthMm the drill point's length along the axis (0 for no point)
     */
    static DoubleUnaryOperator toolReach(double radiusMm, boolean ball, double cornerMm, double pointLengthMm) {
        if (pointLengthMm > 0) {
            return h -> h >= pointLengthMm ? radiusMm : radiusMm * h / pointLengthMm;
        }
        double e = ball ? radiusMm : Math.min(Math.max(cornerMm, 0), radiusMm);
        return h -> h >= e ? radiusMm : radiusMm - e + Math.sqrt(Math.max(e * e - (e - h) * (e - h), 0));
    }

    /**
     * Refuses the moves when the tool passes the hole's wall by more than the tolerance, naming by
     * how much and where.
     */
    static void within(
            ToolpathSection local, double holeDiameterMm, double depthMm, DoubleUnaryOperator tool, Tolerance tol) {
        double radius = holeDiameterMm / 2;
        double worst = 0;
        double worstZ = 0;
        double widest = 0;
        for (Vec3 p : points(local)) {
            if (!(p.z() < -tol.linear())) {
                continue;
            }
            double off = Math.hypot(p.x(), p.y());
            for (double h = 0; p.z() + h < 0; h += STEP_MM) {
                double z = p.z() + h;
                if (z < -depthMm) {
                    continue;
                }
                double reach = off + tool.applyAsDouble(h);
                widest = Math.max(widest, reach);
                if (reach - radius > worst) {
                    worst = reach - radius;
                    worstZ = z;
                }
            }
        }
        if (worst > tol.linear()) {
            throw new UnsupportedOperationException("the tool reaches " + ToolpathPlanner.mm(widest)
                    + " mm from the hole's axis: it would cut the " + ToolpathPlanner.mm(holeDiameterMm)
                    + " mm hole's wall " + ToolpathPlanner.mm(worst) + " mm deep at " + ToolpathPlanner.mm(-worstZ)
                    + " mm below its top; a tool no wider than the hole makes it");
        }
    }

    /** The tool tip's positions: every move's end, and arcs by their points. */
    private static List<Vec3> points(ToolpathSection s) {
        List<Vec3> out = new ArrayList<>();
        Vec3 at = s.start();
        out.add(at);
        for (Move m : s.moves()) {
            if (m instanceof Move.Circular c) {
                out.addAll(ArcGeometry.of(at, c).points(CHORD_MM));
            }
            out.add(m.end());
            at = m.end();
        }
        return out;
    }
}
