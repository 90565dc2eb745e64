package org.fresa.grading;

/**
 * The thesis's general grading equations (3.5)/(3.6) with the shrinkage of (4.10):
 *
 * <pre>
 * ALFA(ND) = 1 + (ND - NP) * VL / LP        width factor
 * BETA(ND) = 1 + (ND - NP) * VC / CP        length factor
 * </pre>
 *
 * where ND - NP counts whole sizes of the system (for Mondopoint, tens of mm). Lengths and widths
 * therefore grow arithmetically: CP(ND) = CP + (ND - NP) VC exactly, before shrinkage.
 *
 * @param system the size system (counts whole sizes)
 * @param baseSize NP, the size of the drawn pattern
 * @param lengthStepMm VC, length change per whole size (mm)
 * @param widthStepMm VL, width change per whole size (mm)
 * @param baseLengthMm CP, the pattern's length along the length axis (mm, > 0)
 * @param baseWidthMm LP, the pattern's width across the length axis (mm, > 0)
 * @param shrinkage S, the material's shrinkage fraction (0.02 = 2 %), >= 0
 * @param mode how S enters the factors
 */
public record GradingRule(
        SizeSystem system,
        double baseSize,
        double lengthStepMm,
        double widthStepMm,
        double baseLengthMm,
        double baseWidthMm,
        double shrinkage,
        ShrinkageMode mode) {

    public GradingRule {
        java.util.Objects.requireNonNull(system, "system");
        java.util.Objects.requireNonNull(mode, "mode");
        if (!(baseLengthMm > 0) || !(baseWidthMm > 0)) {
            throw new IllegalArgumentException(
                    "pattern length and width must be > 0: " + baseLengthMm + ", " + baseWidthMm);
        }
        if (!(shrinkage >= 0) || !(shrinkage < 1)) {
            throw new IllegalArgumentException("shrinkage must be in [0, 1): " + shrinkage);
        }
        if (!Double.isFinite(lengthStepMm) || !Double.isFinite(widthStepMm) || !Double.isFinite(baseSize)) {
            throw new IllegalArgumentException("steps and base size must be finite");
        }
    }

    /** The factors for size ND. */
    public ScaleFactors factors(double size) {
        double n = system.sizesBetween(baseSize, size);
        double alfa = 1 + n * widthStepMm / baseWidthMm;
        double beta = 1 + n * lengthStepMm / baseLengthMm;
        return new ScaleFactors(size, alfa, beta, mode.apply(alfa, shrinkage), mode.apply(beta, shrinkage));
    }

    /** The nominal length of size ND, CP * length factor (mm). */
    public double lengthMm(double size) {
        return baseLengthMm * factors(size).length();
    }

    /** The nominal width of size ND, LP * width factor (mm). */
    public double widthMm(double size) {
        return baseWidthMm * factors(size).width();
    }
}
