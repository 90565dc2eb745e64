package org.fresa.pocket;

import org.fresa.geom.Contour;
import org.fresa.model.Toolpath;
import org.locationtech.jts.geom.Geometry;

/** The pocket tests' JTS helpers for tests in other packages (sole cavity). */
public final class RegionPocketTestAccess {
    private RegionPocketTestAccess() {}

    /** The contour as a JTS polygon, arcs as chords within 0.5 um. */
    public static Geometry polygon(Contour c) {
        return RegionPocketTest.polygon(c);
    }

    /** The tool disc of radius r swept along every feed move at height z. */
    public static Geometry swept(Toolpath path, double z, double r) {
        return PocketCoverageTest.swept(path, z, r);
    }
}
