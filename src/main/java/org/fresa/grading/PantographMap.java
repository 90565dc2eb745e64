package org.fresa.grading;

import org.fresa.geom.Vec2;

/**
 * The affine map of the grading pantograph: in the frame, x' = width * x and y' = length * y
 * about the fixed origin (thesis eq. 4.1 with (4.10)). Both factors are > 0, so orientation is kept.
 *
 * @param frame origin and axes
 * @param width factor across the length axis
 * @param length factor along the length axis
 */
public record PantographMap(GradingFrame frame, double width, double length) {

    public PantographMap {
        java.util.Objects.requireNonNull(frame, "frame");
        if (!(width > 0) || !(length > 0)) {
            throw new IllegalArgumentException("factors must be > 0: " + width + ", " + length);
        }
    }

    public static PantographMap of(GradingFrame frame, ScaleFactors f) {
        return new PantographMap(frame, f.width(), f.length());
    }

    /** The image of a point. */
    public Vec2 apply(Vec2 p) {
        Vec2 d = p.minus(frame.origin());
        return frame.origin().plus(linear(d));
    }

    /** The image of a vector (the linear part). */
    public Vec2 linear(Vec2 d) {
        Vec2 w = frame.widthAxis();
        Vec2 u = frame.lengthAxis();
        return w.times(width * d.dot(w)).plus(u.times(length * d.dot(u)));
    }

    /** The map that undoes this one. */
    public PantographMap inverse() {
        return new PantographMap(frame, 1 / width, 1 / length);
    }

    /** This map followed by another with the same frame. */
    public PantographMap then(PantographMap next) {
        if (!next.frame.equals(frame)) {
            throw new IllegalArgumentException("maps in different frames");
        }
        return new PantographMap(frame, width * next.width, length * next.length);
    }
}
