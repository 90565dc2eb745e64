package org.fresa.toolpath;

/**
 * The distance between neighbouring passes.
 *
 * <p>Nominal: the radial depth when given, else eq. 21 of the thesis, d = D (1 - overlap) with the
 * overlap as a fraction of the tool diameter. Limited to D, and, where nested offsets have sharp
 * corners of interior angle theta, by the corner rule: the tool at a corner of one loop must reach
 * the corner of the next loop's cleared area, which holds when d <= R (1 + sin(theta / 2)) (for a
 * square corner 0.854 D). Beyond that a triangle of material stays between the loops at each
 * corner.
 */
public final class Stepover {
    private Stepover() {}

    /**
     * @param overlapFraction overlap as a fraction of D in [0, 1)
     */
    public static double nominal(double toolDiameterMm, double overlapFraction) {
        if (!(overlapFraction >= 0 && overlapFraction < 1)) {
            throw new IllegalArgumentException("overlap must be a fraction in [0, 1): " + overlapFraction);
        }
        return toolDiameterMm * (1 - overlapFraction);
    }

    /** The largest stepover that leaves nothing between loops with corners of that interior angle. */
    public static double cornerLimit(double toolDiameterMm, double cornerAngleRad) {
        double r = toolDiameterMm / 2;
        if (cornerAngleRad >= Math.PI) {
            return toolDiameterMm;
        }
        return r * (1 + Math.sin(cornerAngleRad / 2));
    }

    /** The stepover to use between offset loops: the nominal value limited by D and the corner rule. */
    public static double forLoops(double nominalMm, double toolDiameterMm, double cornerAngleRad) {
        return Math.min(Math.min(nominalMm, toolDiameterMm), cornerLimit(toolDiameterMm, cornerAngleRad));
    }
}
