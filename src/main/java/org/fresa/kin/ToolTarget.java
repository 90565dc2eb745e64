package org.fresa.kin;

import java.util.Objects;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;

/**
 * Where the tool tip must be, in the robot base frame: a position, the tool axis and a preferred
 * direction for the tool's x axis. The turn about the tool axis is free for a spindle; the
 * trajectory solver may change it (and says so) to stay away from limits and singularities.
 *
 * @param label the workingstep (or another name) the point belongs to
 * @param positionMm tool tip (TCP) position (mm)
 * @param toolAxis unit tool z axis, from the flange towards the tip, into the material
 * @param preferredX the wished tool x direction; its part normal to the axis is used
 */
public record ToolTarget(String label, Vec3 positionMm, Vec3 toolAxis, Vec3 preferredX) {

    public ToolTarget {
        Objects.requireNonNull(label, "label");
        Objects.requireNonNull(positionMm, "positionMm");
        toolAxis = toolAxis.normalized();
        Vec3 xn = preferredX.minus(toolAxis.times(preferredX.dot(toolAxis)));
        if (xn.norm() < 1e-9) {
            // any direction normal to the axis will do
            Vec3 other = Math.abs(toolAxis.x()) < 0.9 ? Vec3.UNIT_X : Vec3.UNIT_Y;
            xn = other.minus(toolAxis.times(other.dot(toolAxis)));
        }
        preferredX = xn.normalized();
    }

    /**
     * A target whose preferred x is {@link #naturalX} of its axis, so that neighbouring faces of
     * a part get tool frames that turn into each other without a twist.
     */
    public static ToolTarget of(String label, Vec3 positionMm, Vec3 toolAxis) {
        return new ToolTarget(label, positionMm, toolAxis, naturalX(toolAxis));
    }

    /**
     * The image of +x under the smallest rotation that takes the vertical-down tool axis (0, 0, -1)
     * to this axis: +x for a top face, +x for a face normal to y, +z (from down, turned about y)
     * for the face at x = 0 of a block, and +x for a tool pointing straight up.
     */
    public static Vec3 naturalX(Vec3 axis) {
        Vec3 a = axis.normalized();
        Vec3 u = new Vec3(0, 0, -1);
        Vec3 k = u.cross(a);
        double s = k.norm();
        double c = u.dot(a);
        if (s < 1e-12) {
            return Vec3.UNIT_X; // down, or up (half a turn about x keeps x)
        }
        Vec3 kh = k.times(1 / s);
        Vec3 v = Vec3.UNIT_X;
        return v.times(c).plus(kh.cross(v).times(s)).plus(kh.times(kh.dot(v) * (1 - c)));
    }

    /** The full pose with the tool turned by angleDeg about its axis from the preferred x. */
    public Transform3 pose(double freeRotationDeg) {
        double a = Math.toRadians(freeRotationDeg);
        Vec3 x = preferredX.times(Math.cos(a)).plus(toolAxis.cross(preferredX).times(Math.sin(a)));
        return Transform3.ofFrame(positionMm, toolAxis, x);
    }

    /** The same target moved by distanceMm against the tool axis (lifted off the part). */
    public ToolTarget lifted(double distanceMm) {
        return new ToolTarget(label, positionMm.minus(toolAxis.times(distanceMm)), toolAxis, preferredX);
    }
}
