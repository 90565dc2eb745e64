package org.fresa.pocket;

/**
 * One record of a thesis {@code .dad} contour as the file holds it, without its numbers: a line
 * {@code A·x + B·y = D} (coefficients raw, not unit-normalised) or a circle with centre (x, y)
 * and radius R, the S/L selector and, for a circle, the arc sense. Element numbers and next
 * numbers follow from the position in the contour ({@link DadContour}).
 *
 * @param arc true for a circle (type C), false for a line (type R)
 * @param a line coefficient A, or the centre x of the circle (mm)
 * @param b line coefficient B, or the centre y of the circle (mm)
 * @param d line coefficient D, or the radius of the circle (mm, >= 0)
 * @param selector ' ' (blank, read as S), 'S' or 'L': which of two intersections with the
 *     previous element starts this one (S the smaller x)
 * @param sense for a circle 'F' (convex, centre inside the pocket) or 'M' (concave); ' ' for a line
 */
public record DadElement(boolean arc, double a, double b, double d, char selector, char sense) {

    /** The largest magnitude of a number in a record: a pocket is smaller than a kilometre. */
    public static final double MAX_ABS_MM = 1e6;

    public DadElement {
        if (!finite(a) || !finite(b) || !finite(d)) {
            throw new IllegalArgumentException(
                    (arc ? "centre and radius" : "A, B and D") + " must be finite with |value| <= 1e6 mm");
        }
        if (selector != ' ' && selector != 'S' && selector != 'L') {
            throw new IllegalArgumentException("selector must be S, L or blank, found '" + selector + "'");
        }
        if (arc) {
            if (sense != 'F' && sense != 'M') {
                throw new IllegalArgumentException(
                        "arc sense must be F (convex) or M (concave), found '" + sense + "'");
            }
            if (!(d >= 0)) {
                throw new IllegalArgumentException("radius must be >= 0");
            }
        } else {
            if (sense != ' ') {
                throw new IllegalArgumentException("a line has no arc sense, found '" + sense + "'");
            }
            if (a == 0 && b == 0) {
                throw new IllegalArgumentException("line coefficients A and B are both zero");
            }
        }
    }

    private static boolean finite(double v) {
        return Double.isFinite(v) && Math.abs(v) <= MAX_ABS_MM;
    }

    /** A line A·x + B·y = D with a blank selector. */
    public static DadElement line(double a, double b, double d) {
        return new DadElement(false, a, b, d, ' ', ' ');
    }

    /** A circle; convex: its centre inside the pocket (F), else concave (M). */
    public static DadElement arc(double xMm, double yMm, double radiusMm, char selector, boolean convex) {
        return new DadElement(true, xMm, yMm, radiusMm, selector, convex ? 'F' : 'M');
    }

    /** The thesis element with its number; a line's k is set from the contour by {@link DadContour#profile}. */
    PocketElement element(int number) {
        return new PocketElement(
                number, arc, a, b, d, arc && sense == 'M' ? 1 : arc ? -1 : 1, selector == 'L' ? 'L' : 'S');
    }

    /** The same element changed in one field (the others kept). */
    public DadElement withArc(boolean isArc) {
        if (isArc == arc) {
            return this;
        }
        return isArc
                ? new DadElement(true, a, b, Math.abs(d), selector, 'F')
                : new DadElement(false, a == 0 && b == 0 ? 1 : a, b, d, selector, ' ');
    }

    public DadElement withA(double v) {
        return new DadElement(arc, v, b, d, selector, sense);
    }

    public DadElement withB(double v) {
        return new DadElement(arc, a, v, d, selector, sense);
    }

    public DadElement withD(double v) {
        return new DadElement(arc, a, b, v, selector, sense);
    }

    public DadElement withSelector(char s) {
        return new DadElement(arc, a, b, d, s, sense);
    }

    public DadElement withSense(char s) {
        return new DadElement(arc, a, b, d, selector, s);
    }
}
