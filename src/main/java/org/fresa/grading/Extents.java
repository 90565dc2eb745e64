package org.fresa.grading;

import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;

/** Exact extents of lines-and-arcs contours along any direction (the axis-free bounding box). */
public final class Extents {
    private Extents() {}

    /** Smallest and largest p . dir over the curve; dir must be a unit vector. */
    public static double[] along(Curve2 c, Vec2 dir) {
        double a = c.start().dot(dir);
        double b = c.end().dot(dir);
        double lo = Math.min(a, b);
        double hi = Math.max(a, b);
        if (c instanceof Arc2 arc) {
            double r = arc.radius();
            double ang = dir.angleRad();
            if (arc.containsAngle(ang)) {
                hi = Math.max(hi, arc.center().dot(dir) + r);
            }
            if (arc.containsAngle(ang + Math.PI)) {
                lo = Math.min(lo, arc.center().dot(dir) - r);
            }
        }
        return new double[] {lo, hi};
    }

    /** Smallest and largest p . dir over the contour. */
    public static double[] along(Contour c, Vec2 dir) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (Curve2 k : c.curves()) {
            double[] e = along(k, dir);
            lo = Math.min(lo, e[0]);
            hi = Math.max(hi, e[1]);
        }
        return new double[] {lo, hi};
    }

    /** The contour's size along the direction (mm). */
    public static double sizeAlong(Contour c, Vec2 dir) {
        double[] e = along(c, dir);
        return e[1] - e[0];
    }
}
