package org.fresa.toolpath;

import java.util.List;
import org.fresa.geom.Contour;
import org.fresa.geom.Tolerance;

/**
 * Exact inward offsets of a closed line/arc contour, as the pocket module's offset engine
 * provides ({@link #EXACT}, {@code org.fresa.pocket.LineArcOffsetter}).
 */
@FunctionalInterface
public interface ContourOffsetter {

    /**
     * The contours at distance d inside c (counter-clockwise input), largest first; empty when
     * the offset vanishes.
     */
    List<Contour> inward(Contour c, double dMm, Tolerance tol);

    /** The pocket module's exact line/arc offsetter, largest loop first. */
    ContourOffsetter EXACT = (c, d, tol) -> {
        java.util.List<Contour> loops = new java.util.ArrayList<>(org.fresa.pocket.LineArcOffsetter.offset(c, -d, tol));
        loops.removeIf(l -> l.isCcw() != c.isCcw());
        loops.sort(java.util.Comparator.comparingDouble(Contour::area).reversed());
        return loops;
    };
}
