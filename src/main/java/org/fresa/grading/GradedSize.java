package org.fresa.grading;

import java.util.List;
import java.util.OptionalDouble;
import org.fresa.geom.Contour;

/**
 * One graded size.
 *
 * @param factors the scale factors of this size (forepart factors under coordination)
 * @param heelSize NBC, the size whose heel this size takes, when coordinated
 * @param exact the exact graded outlines (the affine image; the forepart's map under coordination)
 * @param output the outlines as lines and circular arcs, for DXF and NC
 * @param lengthMm the outline's length along the length axis (mm)
 * @param widthMm the outline's width across it (mm)
 * @param maxDeviationMm how far the output departs from the exact outline (mm); empty under
 *     coordination, where there is no single exact image
 */
public record GradedSize(
        ScaleFactors factors,
        OptionalDouble heelSize,
        List<GradedOutline> exact,
        List<Contour> output,
        double lengthMm,
        double widthMm,
        OptionalDouble maxDeviationMm) {

    public GradedSize {
        exact = List.copyOf(exact);
        output = List.copyOf(output);
    }

    public double size() {
        return factors.size();
    }

    /** The size as a file-name part: 40, 40.5, 265. */
    public String name() {
        return org.fresa.model.ExactDecimal.of(factors.size());
    }
}
