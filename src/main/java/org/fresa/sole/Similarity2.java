package org.fresa.sole;

import java.util.Objects;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;

/**
 * A plane similarity p' = M p + t where M is a rotation times a uniform scale, possibly with a
 * reflection: the transforms of the thesis's {@code COPY} (TRANSL, MIRROR about XPAR/YPAR or a
 * line, rotation) and the shrinkage (1 + CTM). A similarity maps circles to circles, so arcs stay
 * arcs; a reflection turns the arcs' sense.
 *
 * @param a M[0][0]
 * @param b M[0][1]
 * @param c M[1][0]
 * @param d M[1][1]
 * @param t translation (mm)
 */
public record Similarity2(double a, double b, double c, double d, Vec2 t) {

    public static final Similarity2 IDENTITY = new Similarity2(1, 0, 0, 1, Vec2.ZERO);

    public Similarity2 {
        Objects.requireNonNull(t, "t");
        double s1 = a * a + c * c;
        double s2 = b * b + d * d;
        if (!(s1 > 0) || Math.abs(s1 - s2) > 1e-9 * s1 || Math.abs(a * b + c * d) > 1e-9 * s1) {
            throw new IllegalArgumentException("not a similarity: " + a + " " + b + " " + c + " " + d);
        }
    }

    public static Similarity2 translation(double dxMm, double dyMm) {
        return new Similarity2(1, 0, 0, 1, Vec2.of(dxMm, dyMm));
    }

    public static Similarity2 translation(Vec2 by) {
        return new Similarity2(1, 0, 0, 1, by);
    }

    /** Rotation by angleDeg (counter-clockwise) about the centre. */
    public static Similarity2 rotation(Vec2 center, double angleDeg) {
        double r = Math.toRadians(angleDeg);
        double co = Math.cos(r);
        double si = Math.sin(r);
        Vec2 rc = new Vec2(co * center.x() - si * center.y(), si * center.x() + co * center.y());
        return new Similarity2(co, -si, si, co, center.minus(rc));
    }

    /** Uniform scale by factor (> 0) about the centre. */
    public static Similarity2 scale(Vec2 center, double factor) {
        if (!(factor > 0)) {
            throw new IllegalArgumentException("scale factor must be > 0: " + factor);
        }
        return new Similarity2(factor, 0, 0, factor, center.times(1 - factor));
    }

    /** Reflection in the line x = xMm (the thesis's {@code MIRROR,YPAR,x}). */
    public static Similarity2 mirrorX(double xMm) {
        return new Similarity2(-1, 0, 0, 1, Vec2.of(2 * xMm, 0));
    }

    /** Reflection in the line y = yMm (the thesis's {@code MIRROR,XPAR,y}). */
    public static Similarity2 mirrorY(double yMm) {
        return new Similarity2(1, 0, 0, -1, Vec2.of(0, 2 * yMm));
    }

    public boolean reflects() {
        return a * d - b * c < 0;
    }

    /** The uniform scale factor of M. */
    public double scaleFactor() {
        return Math.sqrt(a * a + c * c);
    }

    public Vec2 apply(Vec2 p) {
        return new Vec2(a * p.x() + b * p.y() + t.x(), c * p.x() + d * p.y() + t.y());
    }

    public Curve2 apply(Curve2 k) {
        if (k instanceof Segment2 s) {
            return new Segment2(apply(s.start()), apply(s.end()));
        }
        Arc2 arc = (Arc2) k;
        Vec2 s = apply(arc.start());
        Vec2 e = arc.isFullCircle() ? s : apply(arc.end());
        return new Arc2(apply(arc.center()), s, e, reflects() != arc.ccw());
    }

    /** First this, then next. */
    public Similarity2 then(Similarity2 n) {
        return new Similarity2(n.a * a + n.b * c, n.a * b + n.b * d, n.c * a + n.d * c, n.c * b + n.d * d, n.apply(t));
    }

    public Similarity2 inverse() {
        double det = a * d - b * c;
        double ia = d / det;
        double ib = -b / det;
        double ic = -c / det;
        double id = a / det;
        Vec2 it = new Vec2(-(ia * t.x() + ib * t.y()), -(ic * t.x() + id * t.y()));
        return new Similarity2(ia, ib, ic, id, it);
    }
}
