package org.fresa.geom;

/**
 * The one place where "equal enough" is decided: a linear tolerance in millimetres and an angular
 * tolerance in radians, passed explicitly to every algorithm that compares doubles.
 *
 * <p>Keep this apart from approximation settings (chord error, segment length): a tolerance says
 * when two computed numbers stand for the same quantity, not how coarsely to approximate.
 *
 * @param linear largest distance, in mm, at which two lengths or points count as equal; >= 0
 * @param angularRad largest angle, in radians, at which two directions count as equal; >= 0
 */
public record Tolerance(double linear, double angularRad) {

    /** Geometry of CAD input and toolpaths: 1e-6 mm (a nanometre scale) and 1e-9 rad. */
    public static final Tolerance DEFAULT = new Tolerance(1e-6, 1e-9);

    /** Chaining and matching of drawing entities: 1e-3 mm, as CAD files round their coordinates. */
    public static final Tolerance DRAWING = new Tolerance(1e-3, 1e-6);

    public Tolerance {
        if (!(linear >= 0) || !Double.isFinite(linear)) {
            throw new IllegalArgumentException("linear tolerance must be finite and >= 0: " + linear);
        }
        if (!(angularRad >= 0) || !Double.isFinite(angularRad)) {
            throw new IllegalArgumentException("angular tolerance must be finite and >= 0: " + angularRad);
        }
    }

    /** A tolerance with the given linear part and the default angular part. */
    public static Tolerance ofLinear(double linear) {
        return new Tolerance(linear, DEFAULT.angularRad);
    }

    /** True when |a - b| <= linear. */
    public boolean eq(double a, double b) {
        return Math.abs(a - b) <= linear;
    }

    /** True when |a| <= linear. */
    public boolean isZero(double a) {
        return Math.abs(a) <= linear;
    }

    /** True when the two angles (radians) differ by at most angularRad, modulo nothing. */
    public boolean eqAngle(double aRad, double bRad) {
        return Math.abs(aRad - bRad) <= angularRad;
    }

    /** -1, 0 or 1 as a is less than, equal within the tolerance to, or greater than b. */
    public int compare(double a, double b) {
        return eq(a, b) ? 0 : (a < b ? -1 : 1);
    }
}
