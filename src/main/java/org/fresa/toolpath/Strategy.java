package org.fresa.toolpath;

/** The ISO 14649-11 two5D milling strategies this package generates. */
public enum Strategy {
    /** Parallel passes along the feed direction, all the same way, lifting between passes. */
    UNIDIRECTIONAL,
    /** Parallel passes along the feed direction, zig-zag, joined at depth. */
    BIDIRECTIONAL,
    /** Nested offsets of the profile, inside out, each closed and joined by a straight link. */
    CONTOUR_PARALLEL,
    /** Nested offsets, each loop continuing into the next without closing. */
    CONTOUR_SPIRAL,
    /** Bidirectional passes, then one contour at the wall. */
    BIDIRECTIONAL_CONTOUR,
    /** One contour at the wall, then bidirectional passes inside it. */
    CONTOUR_BIDIRECTIONAL,
    /** One pass along the profile's centre line (a point for round profiles). */
    CENTER_MILLING
}
