package org.fresa.pocket;

/**
 * The thesis's technology data (§7.5).
 *
 * @param toolDiameterMm flat end mill diameter D (mm)
 * @param cutFraction stepover as a fraction of D; values below 0.5 are raised to 0.5, above 1 rejected
 * @param finishFraction finishing allowance a as a fraction of D (0 to 0.5)
 * @param zTopMm Z of the top surface (mm)
 * @param zBottomMm Z of the pocket floor (mm)
 * @param maxDepthMm largest depth per pass (mm, > 0)
 * @param spindleRpm spindle speed (rpm)
 * @param feedMmPerMin roughing feed (mm/min)
 * @param finishFeedMmPerMin finishing feed (mm/min)
 */
public record PocketTechnology(double toolDiameterMm, double cutFraction, double finishFraction, double zTopMm,
        double zBottomMm, double maxDepthMm, double spindleRpm, double feedMmPerMin, double finishFeedMmPerMin) {

    public PocketTechnology {
        if (!(toolDiameterMm > 0)) {
            throw new IllegalArgumentException("tool diameter must be > 0: " + toolDiameterMm);
        }
        if (!(cutFraction > 0 && cutFraction <= 1)) {
            throw new IllegalArgumentException("cut fraction must be in (0, 1]: " + cutFraction);
        }
        if (!(finishFraction >= 0 && finishFraction <= 0.5)) {
            throw new IllegalArgumentException("finish fraction must be in [0, 0.5]: " + finishFraction);
        }
        if (!(zTopMm > zBottomMm)) {
            throw new IllegalArgumentException("z-top must be above z-bottom");
        }
        if (!(maxDepthMm > 0)) {
            throw new IllegalArgumentException("max depth per pass must be > 0: " + maxDepthMm);
        }
        if (!(feedMmPerMin > 0) || !(finishFeedMmPerMin > 0)) {
            throw new IllegalArgumentException("feeds must be > 0");
        }
    }

    public double radiusMm() {
        return toolDiameterMm / 2;
    }

    /** The stepover fraction actually used: at least 0.5 (the thesis forces it). */
    public double effectiveCut() {
        return Math.max(0.5, cutFraction);
    }

    /** Number of depth passes: the ceiling of depth / max depth, at least 1 (thesis). */
    public int depthPasses() {
        return Math.max(1, (int) Math.ceil((zTopMm - zBottomMm) / maxDepthMm - 1e-9));
    }

    /** Equal depth increment (mm). */
    public double depthStepMm() {
        return (zTopMm - zBottomMm) / depthPasses();
    }
}
