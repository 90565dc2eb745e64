package org.fresa.dxf;

import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;

/** A plane affine map p' = (a b; c d) p + (tx, ty), for block inserts and OCS mirroring. */
record DxfAffine(double a, double b, double c, double d, double tx, double ty) {

    static final DxfAffine IDENTITY = new DxfAffine(1, 0, 0, 1, 0, 0);

    static DxfAffine translation(double x, double y) {
        return new DxfAffine(1, 0, 0, 1, x, y);
    }

    static DxfAffine rotationDeg(double deg) {
        double r = Math.toRadians(deg);
        double co = Math.cos(r);
        double si = Math.sin(r);
        // exact quarter turns keep inserted geometry on the grid it was drawn on
        if (deg % 90 == 0) {
            co = Math.rint(co);
            si = Math.rint(si);
        }
        return new DxfAffine(co, -si, si, co, 0, 0);
    }

    static DxfAffine scale(double sx, double sy) {
        return new DxfAffine(sx, 0, 0, sy, 0, 0);
    }

    /** this after other: p -> this(other(p)). */
    DxfAffine times(DxfAffine o) {
        return new DxfAffine(
                a * o.a + b * o.c,
                a * o.b + b * o.d,
                c * o.a + d * o.c,
                c * o.b + d * o.d,
                a * o.tx + b * o.ty + tx,
                c * o.tx + d * o.ty + ty);
    }

    Vec2 apply(Vec2 p) {
        return new Vec2(a * p.x() + b * p.y() + tx, c * p.x() + d * p.y() + ty);
    }

    double det() {
        return a * d - b * c;
    }

    boolean isIdentity() {
        return equals(IDENTITY);
    }

    /** True when the map keeps circles circles (a rotation and uniform scale, maybe mirrored). */
    boolean isSimilarity() {
        double s1 = a * a + c * c;
        double s2 = b * b + d * d;
        double dot = a * b + c * d;
        double tol = 1e-12 * Math.max(s1, s2);
        return Math.abs(s1 - s2) <= tol && Math.abs(dot) <= tol && s1 > 0;
    }

    Segment2 apply(Segment2 s) {
        return new Segment2(apply(s.start()), apply(s.end()));
    }

    /** The image of a curve when the map is a similarity (a mirror reverses the arc sense). */
    Curve2 applySimilar(Curve2 cv) {
        if (cv instanceof Segment2 s) {
            return apply(s);
        }
        Arc2 arc = (Arc2) cv;
        boolean ccw = det() > 0 ? arc.ccw() : !arc.ccw();
        return new Arc2(apply(arc.center()), apply(arc.start()), apply(arc.end()), ccw);
    }
}
