package org.fresa.pocket;

import org.fresa.geom.Vec2;

/**
 * One element of a pocket contour in the 1988 thesis's canonical form, with its offset direction.
 *
 * <p>A line is {@code a·x + b·y = d}; its coefficients are kept raw (not unit-normalised), as the
 * thesis's published results use them raw. An arc is the circle with centre (a, b) and radius d
 * (mm). Offsetting into the pocket by t moves a line to {@code d + k·t} and gives an arc the
 * radius {@code d + k·t}: k = +1 for concave arcs (centre outside the pocket, traversed
 * counter-clockwise in the clockwise contour) and -1 for convex ones. Zero-radius concave arcs
 * stand at reflex corners so that offsets stay Euclidean.
 *
 * @param number element number as in the input (created zero-radius arcs get numbers above N)
 * @param arc true for a circle element
 * @param a line coefficient A, or the centre x of an arc (mm)
 * @param b line coefficient B, or the centre y of an arc (mm)
 * @param d line coefficient D, or the radius of an arc at t = 0 (mm, >= 0)
 * @param k +1 or -1, the sign of the offset into the pocket
 * @param selector 'S' or 'L': which of two intersections with the previous element is the start
 */
public record PocketElement(int number, boolean arc, double a, double b, double d, int k, char selector) {

    public PocketElement {
        if (k != 1 && k != -1) {
            throw new IllegalArgumentException("k must be +1 or -1: " + k);
        }
        if (selector != 'S' && selector != 'L') {
            throw new IllegalArgumentException("selector must be S or L: " + selector);
        }
    }

    /** D (line) or radius (arc) at offset t. */
    public double at(double t) {
        return d + k * t;
    }

    public boolean concave() {
        return arc && k == 1;
    }

    public boolean convex() {
        return arc && k == -1;
    }

    public boolean zeroRadius() {
        return arc && d == 0;
    }

    public Vec2 center() {
        return new Vec2(a, b);
    }

    /** Length of the line normal (A, B); 1 for unit-normalised lines. */
    public double normalLength() {
        return Math.hypot(a, b);
    }

    /** The offset t at which this element's offset carrier passes through p. */
    public double offsetThrough(Vec2 p) {
        if (arc) {
            return k * (p.distance(center()) - d);
        }
        return k * (a * p.x() + b * p.y() - d);
    }

    /** Unit tangent, in the direction of travel of the clockwise contour, at point p on the element. */
    public Vec2 tangentAt(Vec2 p) {
        if (arc) {
            Vec2 r = p.minus(center());
            Vec2 t = k == -1 ? new Vec2(r.y(), -r.x()) : new Vec2(-r.y(), r.x());
            double n = t.norm();
            return n == 0 ? Vec2.ZERO : t.times(1 / n);
        }
        double n = normalLength();
        // travel keeps the pocket (the inward normal k·(A, B)) on its right
        return new Vec2(-k * b / n, k * a / n);
    }

    public PocketElement withSelector(char s) {
        return new PocketElement(number, arc, a, b, d, k, s);
    }

    public PocketElement withK(int newK) {
        return new PocketElement(number, arc, a, b, d, newK, selector);
    }

    @Override
    public String toString() {
        return (arc ? (zeroRadius() ? "Z" : "C") : "R") + number;
    }
}
