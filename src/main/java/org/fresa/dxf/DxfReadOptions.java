package org.fresa.dxf;

import java.util.Objects;
import java.util.Optional;

/**
 * How to read a drawing.
 *
 * @param units forced drawing units, or empty to use the file's {@code $INSUNITS}
 * @param unitlessAs the unit of a drawing that declares none (or an unknown one)
 * @param curveToleranceMm largest distance between an ELLIPSE or SPLINE and the arcs replacing it
 * @param maxInsertDepth block nesting deeper than this is reported and not expanded
 * @param maxCurves a drawing expanding to more curves is refused (nothing is cut short)
 */
public record DxfReadOptions(
        Optional<DxfUnits> units, DxfUnits unitlessAs, double curveToleranceMm, int maxInsertDepth, int maxCurves) {

    public static final DxfReadOptions DEFAULT =
            new DxfReadOptions(Optional.empty(), DxfUnits.MM, 0.001, 16, 2_000_000);

    public DxfReadOptions {
        Objects.requireNonNull(units, "units");
        Objects.requireNonNull(unitlessAs, "unitlessAs");
        if (!(curveToleranceMm > 0)) {
            throw new IllegalArgumentException("curve tolerance must be > 0: " + curveToleranceMm);
        }
    }

    public DxfReadOptions withUnits(Optional<DxfUnits> u) {
        return new DxfReadOptions(u, unitlessAs, curveToleranceMm, maxInsertDepth, maxCurves);
    }
}
