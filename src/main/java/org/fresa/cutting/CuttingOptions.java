package org.fresa.cutting;

import java.util.Objects;

/**
 * What to cut and how.
 *
 * @param kerfMm full kerf width; the tool centre runs kerfMm / 2 off the part, in the scrap
 * @param process plasma, laser or waterjet (feed, pierce dwell, default directions)
 * @param leadInMm lead-in length (a line of that length, or an arc of that radius); 0 for none
 * @param leadOutMm lead-out length, as the lead-in; 0 for none
 * @param arcLeads arc leads (tangent entry) instead of straight ones
 * @param overcutMm how far the cut runs past its pierce point before the lead-out
 * @param gapToleranceMm open chains whose ends are closer than this are joined when chaining
 *     (each gap closed is listed); ends closer than {@link #JOINT_MM} always meet
 * @param paperMode the 2010 paper's rules: one-way chaining at 1e-4 mm, largest contour outside
 *     and the others holes, holes before the outside, sharp corners by the paper's corner
 *     equations (eq. 3 corrected), no leads, no re-orientation
 * @param controllerCompensation leave the kerf to the controller (G41/G42) and cut the drawn
 *     contour; leads are then straight
 * @param outerClockwise direction of outer contours
 * @param holesClockwise direction of holes (by default the opposite of the outer contours, so
 *     the scrap is on the same side of the jet on both)
 * @param feedMmPerMin cutting feed
 * @param pierceDwellS dwell after switching the jet on
 * @param avoidCutParts route rapid moves around parts already cut free ({@link RapidRouter})
 */
public record CuttingOptions(
        double kerfMm,
        CutProcess process,
        double leadInMm,
        double leadOutMm,
        boolean arcLeads,
        double overcutMm,
        double gapToleranceMm,
        boolean paperMode,
        boolean controllerCompensation,
        boolean outerClockwise,
        boolean holesClockwise,
        double feedMmPerMin,
        double pierceDwellS,
        boolean avoidCutParts) {

    /**
     * Ends closer than this (mm) are one point of the drawing: rounding in the file, never a gap
     * worth naming. Zero-length and repeated elements are judged at this tolerance too.
     */
    public static final double JOINT_MM = 0.001;
    /**
     * The default gap tolerance (mm): drawings exported from other programs leave gaps of a few
     * hundredths of a millimetre between the ends of an outline (0.008 to 0.011 mm in an inch
     * drawing of the dxf2gcode corpus); 0.05 mm is below any kerf, so closing them changes no
     * cut part, and each gap closed is listed.
     */
    public static final double DEFAULT_GAP_MM = 0.05;
    /** Widest kerf (mm): no jet or beam cuts wider. */
    public static final double MAX_KERF_MM = 100;
    /**
     * Longest lead-in, lead-out and overcut (mm): the search for a clear lead looks at the
     * drawing around it, so its length bounds the work.
     */
    public static final double MAX_LEAD_MM = 1000;

    public CuttingOptions {
        Objects.requireNonNull(process, "process");
        if (!(kerfMm >= 0) || !(leadInMm >= 0) || !(leadOutMm >= 0) || !(overcutMm >= 0) || !(gapToleranceMm >= 0)) {
            throw new IllegalArgumentException("kerf, leads, overcut and tolerance must be >= 0");
        }
        if (!(kerfMm <= MAX_KERF_MM)
                || !(Math.max(leadInMm, Math.max(leadOutMm, overcutMm)) <= MAX_LEAD_MM)
                || !Double.isFinite(gapToleranceMm)) {
            throw new IllegalArgumentException(
                    "the kerf may be at most " + MAX_KERF_MM + " mm, leads and overcut at most " + MAX_LEAD_MM + " mm");
        }
        if (!(feedMmPerMin > 0) || !(pierceDwellS >= 0)) {
            throw new IllegalArgumentException("feed must be > 0 and dwell >= 0");
        }
    }

    /** The defaults of a process with the given kerf and leads. */
    public static CuttingOptions of(CutProcess p, double kerfMm, double leadInMm, double leadOutMm, boolean arcLeads) {
        return new CuttingOptions(
                kerfMm,
                p,
                leadInMm,
                leadOutMm,
                arcLeads,
                0,
                DEFAULT_GAP_MM,
                false,
                false,
                p.outerClockwise(),
                p.holesClockwise(),
                p.feedMmPerMin(),
                p.pierceDwellS(),
                true);
    }

    public CuttingOptions withGapTolerance(double mm) {
        return with(overcutMm, mm, paperMode, controllerCompensation, outerClockwise, holesClockwise, avoidCutParts);
    }

    public CuttingOptions withPaperMode(boolean on) {
        return with(
                overcutMm, gapToleranceMm, on, controllerCompensation, outerClockwise, holesClockwise, avoidCutParts);
    }

    /** Leaves the kerf to the controller: G41/G42 on the drawn contour instead of an offset path. */
    public CuttingOptions withControllerCompensation(boolean on) {
        return with(overcutMm, gapToleranceMm, paperMode, on, outerClockwise, holesClockwise, avoidCutParts);
    }

    public CuttingOptions withOvercut(double mm) {
        return with(
                mm, gapToleranceMm, paperMode, controllerCompensation, outerClockwise, holesClockwise, avoidCutParts);
    }

    /** The senses of outer contours and of holes (true: clockwise). */
    public CuttingOptions withDirections(boolean outerCw, boolean holesCw) {
        return with(overcutMm, gapToleranceMm, paperMode, controllerCompensation, outerCw, holesCw, avoidCutParts);
    }

    /** Whether rapids detour around parts already cut free. */
    public CuttingOptions withAvoidCutParts(boolean on) {
        return with(overcutMm, gapToleranceMm, paperMode, controllerCompensation, outerClockwise, holesClockwise, on);
    }

    /**
     * The same process, kerf, leads, feed and dwell, with other choices of how the drawing is
     * read and cut.
     */
    private CuttingOptions with(
            double overcut,
            double gapTolerance,
            boolean paper,
            boolean controller,
            boolean outerCw,
            boolean holesCw,
            boolean avoid) {
        return new CuttingOptions(
                kerfMm,
                process,
                leadInMm,
                leadOutMm,
                arcLeads,
                overcut,
                gapTolerance,
                paper,
                controller,
                outerCw,
                holesCw,
                feedMmPerMin,
                pierceDwellS,
                avoid);
    }
}
