package org.fresa.sole;

import java.util.Locale;

/**
 * How a tread figure follows the outline from size to size (the grading factors ALFA, BETA of
 * the pantograph about the grading origin, with the shrinkage).
 *
 * <ul>
 *   <li>{@link #HELD}: the figure keeps its place and size; only the shrinkage (1 + CTM) is
 *       applied about the part zero, which is exactly what the thesis's DESCOM does (figures are
 *       not graded). For logos, text and size marks.
 *   <li>{@link #POSITION}: the figure keeps its shape (with the shrinkage) but its anchor, the
 *       centre of its bounding box at the base size, moves with the pantograph.
 *   <li>{@link #SCALED}: the figure is graded like the outline, x by the width factor and y by
 *       the length factor. Lines stay exact; arcs, which an unequal scaling turns into ellipses,
 *       are rebuilt as the circle through the images of their start, middle and end (the
 *       thesis's 3-point rebuild; full circles keep their centre's image and the radius times
 *       sqrt(width x length)). Width and length factors differ by about 1 % per size step in the
 *       Brazilian system, so the rebuilt arcs depart from the ellipse by well under 0.1 mm on
 *       tread-sized arcs.
 * </ul>
 */
public enum SizeRule {
    HELD,
    POSITION,
    SCALED;

    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** @throws IllegalArgumentException for an unknown id */
    public static SizeRule ofId(String id) {
        for (SizeRule r : values()) {
            if (r.id().equals(id.trim().toLowerCase(Locale.ROOT))) {
                return r;
            }
        }
        throw new IllegalArgumentException("unknown size rule '" + id + "', expected held, position or scaled");
    }
}
