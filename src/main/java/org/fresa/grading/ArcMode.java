package org.fresa.grading;

import java.util.Locale;

/** How graded arcs (exactly: elliptic arcs) are written as circular arcs. */
public enum ArcMode {
    /** Tangent-continuous biarcs within the plan's arc tolerance of the exact ellipse (default). */
    BIARC,
    /**
     * The thesis's rebuild: a circle through the graded start, middle and end points (eq. 4.3).
     * Fast and closed, but off the exact ellipse by up to tenths of a mm on long arcs, and with
     * small tangent kinks at the joints.
     */
    THREE_POINT;

    public String id() {
        return name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    /** @throws IllegalArgumentException for a name that is not a mode */
    public static ArcMode ofId(String id) {
        for (ArcMode m : values()) {
            if (m.id().equals(id.trim().toLowerCase(Locale.ROOT))) {
                return m;
            }
        }
        throw new IllegalArgumentException("expected biarc or three-point, found '" + id + "'");
    }
}
