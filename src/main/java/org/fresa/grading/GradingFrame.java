package org.fresa.grading;

import org.fresa.geom.Vec2;

/**
 * The frame the pantograph works in: the fixed origin and the length axis. The width axis is the
 * length axis turned 90 degrees clockwise, so with the length axis along +y the frame's
 * coordinates are the drawing's (x across, y along), as in the thesis.
 *
 * @param origin the fixed point of the grading (mm), by default the heel circle's centre
 * @param lengthAxis unit vector from heel to toe
 */
public record GradingFrame(Vec2 origin, Vec2 lengthAxis) {

    public GradingFrame {
        java.util.Objects.requireNonNull(origin, "origin");
        if (Math.abs(lengthAxis.norm() - 1) > 1e-9) {
            throw new IllegalArgumentException("length axis must be a unit vector: " + lengthAxis);
        }
    }

    /** The thesis's frame: origin given, length along +y. */
    public static GradingFrame alongY(Vec2 origin) {
        return new GradingFrame(origin, Vec2.UNIT_Y);
    }

    /** Unit vector across the length (the length axis turned clockwise). */
    public Vec2 widthAxis() {
        return new Vec2(lengthAxis.y(), -lengthAxis.x());
    }

    /** The length axis's angle from +x, degrees in (-180, 180]. */
    public double lengthAxisDeg() {
        return Math.toDegrees(lengthAxis.angleRad());
    }

    /** Frame coordinates of a point: x across, y along the length, from the origin. */
    public Vec2 toLocal(Vec2 p) {
        Vec2 d = p.minus(origin);
        return new Vec2(d.dot(widthAxis()), d.dot(lengthAxis));
    }

    /** The drawing point of frame coordinates. */
    public Vec2 toGlobal(Vec2 local) {
        return origin.plus(widthAxis().times(local.x())).plus(lengthAxis.times(local.y()));
    }
}
