package org.fresa.grading;

/**
 * The pantograph's factors for one size.
 *
 * @param size the desired size number ND
 * @param alfa ALFA(ND) = 1 + (ND - NP) VL / LP, the width factor before shrinkage
 * @param beta BETA(ND) = 1 + (ND - NP) VC / CP, the length factor before shrinkage
 * @param width the width factor applied, with shrinkage (ALFA + S or ALFA (1 + S))
 * @param length the length factor applied, with shrinkage
 */
public record ScaleFactors(double size, double alfa, double beta, double width, double length) {

    public ScaleFactors {
        if (!(width > 0) || !(length > 0) || !Double.isFinite(width) || !Double.isFinite(length)) {
            throw new IllegalArgumentException("scale factors must be finite and > 0: " + width + ", " + length
                    + " (is the size too far below the base size?)");
        }
    }
}
