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
public record PocketTechnology(
        double toolDiameterMm,
        double cutFraction,
        double finishFraction,
        double zTopMm,
        double zBottomMm,
        double maxDepthMm,
        double spindleRpm,
        double feedMmPerMin,
        double finishFeedMmPerMin) {

    /** Most depth passes (layers) a pocket may have. */
    public static final int MAX_DEPTH_PASSES = 1_000_000;
    /** Most moves a pocket program may have, all layers together: about 30 MB of G-code. */
    public static final long MAX_MOVES = 1_000_000;

    public PocketTechnology {
        double[] all = {
            toolDiameterMm,
            cutFraction,
            finishFraction,
            zTopMm,
            zBottomMm,
            maxDepthMm,
            spindleRpm,
            feedMmPerMin,
            finishFeedMmPerMin
        };
        for (double v : all) {
            if (!Double.isFinite(v)) {
                throw new IllegalArgumentException("technology values must be finite numbers: " + v);
            }
        }
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
        if ((zTopMm - zBottomMm) / maxDepthMm > MAX_DEPTH_PASSES) {
            throw new IllegalArgumentException("a max depth per pass of " + maxDepthMm + " mm over "
                    + (zTopMm - zBottomMm) + " mm makes more than " + MAX_DEPTH_PASSES
                    + " depth passes: give a larger depth per pass");
        }
        if (!(spindleRpm > 0)) {
            throw new IllegalArgumentException("spindle speed must be > 0 rpm: " + spindleRpm);
        }
        if (!(feedMmPerMin > 0) || !(finishFeedMmPerMin > 0)) {
            throw new IllegalArgumentException("feeds must be > 0");
        }
    }

    /**
     * Checks that the program of a plan stays within {@link #MAX_MOVES} over all depth passes.
     *
     * @param movesPerLayer an upper bound of the moves of one layer (pass elements and the moves that link passes)
     * @throws ToolTooLargeException when it would not
     */
    public void checkMoves(long movesPerLayer) throws ToolTooLargeException {
        // both factors are bounded (pass elements by the planners, layers by MAX_DEPTH_PASSES): no overflow
        if (movesPerLayer * depthPasses() > MAX_MOVES) {
            throw new ToolTooLargeException("the program would have up to " + movesPerLayer + " moves in each of "
                    + depthPasses() + " depth passes, more than " + MAX_MOVES + " in all: use a larger depth per pass"
                    + " or a larger tool");
        }
    }

    public double radiusMm() {
        return toolDiameterMm / 2;
    }

    /** The least stepover fraction the offset and zigzag planners take (the thesis forces it). */
    public static final double LEAST_CUT = 0.5;

    /** The stepover fraction actually used: at least {@link #LEAST_CUT} (the thesis forces it). */
    public double effectiveCut() {
        return Math.max(LEAST_CUT, cutFraction);
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
