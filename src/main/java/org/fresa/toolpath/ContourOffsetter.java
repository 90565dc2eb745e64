package org.fresa.toolpath;

import java.util.List;
import org.fresa.geom.Contour;
import org.fresa.geom.Tolerance;

/**
 * Exact inward offsets of a closed line/arc contour, as the pocket module's offset engine
 * provides ({@code org.fresa.pocket.LineArcOffsetter}, issue 7). Until that engine is merged,
 * {@link #UNAVAILABLE} makes general-contour features fail with a clear message.
 */
@FunctionalInterface
public interface ContourOffsetter {

    /**
     * The contours at distance d inside c (counter-clockwise input), largest first; empty when
     * the offset vanishes.
     */
    List<Contour> inward(Contour c, double dMm, Tolerance tol);

    /** The engine that is not there yet. */
    ContourOffsetter UNAVAILABLE = (c, d, tol) -> {
        throw new UnsupportedOperationException(
                "general line/arc profiles need the pocket module's offset engine (issue 7), not merged yet");
    };
}
