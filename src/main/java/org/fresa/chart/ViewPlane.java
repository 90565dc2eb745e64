package org.fresa.chart;

import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;

/**
 * The three views of a part along a machine axis, as a plot shows them: a point in space
 * becomes a plot point by dropping the coordinate along the view axis (millimetres in, millimetres
 * out). Seen from above (XY) x runs right and y up; from the front (XZ) x right and z up; from the
 * side (YZ) y right and z up.
 */
public enum ViewPlane {
    /** Along x: y to the right, z up. */
    SIDE_YZ("Side view (YZ)", new PlotScene.Axes("y (mm)", "z (mm)"), Vec3.UNIT_X),
    /** Along y: x to the right, z up. */
    FRONT_XZ("Front view (XZ)", new PlotScene.Axes("x (mm)", "z (mm)"), Vec3.UNIT_Y),
    /** Along z: x to the right, y up. */
    TOP_XY("Top view (XY)", PlotScene.Axes.XY_MM, Vec3.UNIT_Z);

    private final String title;
    private final PlotScene.Axes axes;
    private final Vec3 viewAxis;

    ViewPlane(String title, PlotScene.Axes axes, Vec3 viewAxis) {
        this.title = title;
        this.axes = axes;
        this.viewAxis = viewAxis;
    }

    /** The view that looks along the coordinate axis the direction mostly points along (z first, then y). */
    public static ViewPlane along(Vec3 direction) {
        double ax = Math.abs(direction.x());
        double ay = Math.abs(direction.y());
        double az = Math.abs(direction.z());
        if (az >= ax && az >= ay) {
            return TOP_XY;
        }
        return ay >= ax ? FRONT_XZ : SIDE_YZ;
    }

    /** The view's name, e.g. "Front view (XZ)". */
    public String title() {
        return title;
    }

    /** The names of the plot's axes in this view. */
    public PlotScene.Axes axes() {
        return axes;
    }

    /** The unit vector of the coordinate axis the view drops. */
    public Vec3 viewAxis() {
        return viewAxis;
    }

    /** A point in space as a point of this view's plot. */
    public Vec2 project(Vec3 p) {
        switch (this) {
            case SIDE_YZ:
                return new Vec2(p.y(), p.z());
            case FRONT_XZ:
                return new Vec2(p.x(), p.z());
            case TOP_XY:
            default:
                return new Vec2(p.x(), p.y());
        }
    }

    /**
     * Whether a turn counter-clockwise about the positive view axis is drawn counter-clockwise:
     * true for (y, z) about +x and (x, y) about +z; (x, z) looks along +y from its negative side
     * and reverses it.
     */
    public boolean keepsSense() {
        return this != FRONT_XZ;
    }
}
