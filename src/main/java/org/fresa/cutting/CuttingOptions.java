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
 * @param gapToleranceMm endpoints closer than this are joined when chaining
 * @param paperMode the 2010 paper's rules: one-way chaining at 1e-4 mm, largest contour outside
 *     and the others holes, holes before the outside, sharp corners by the paper's corner
 *     equations (eq. 3 corrected), no leads, no re-orientation
 * @param controllerCompensation leave the kerf to the controller (G41/G42) and cut the drawn
 *     contour; leads are then straight
 * @param outerClockwise direction of outer contours (holes run the other way)
 * @param feedMmPerMin cutting feed
 * @param pierceDwellS dwell after switching the jet on
 */
public record CuttingOptions(double kerfMm, CutProcess process, double leadInMm, double leadOutMm, boolean arcLeads,
        double overcutMm, double gapToleranceMm, boolean paperMode, boolean controllerCompensation,
        boolean outerClockwise, double feedMmPerMin, double pierceDwellS) {

    public CuttingOptions {
        Objects.requireNonNull(process, "process");
        if (!(kerfMm >= 0) || !(leadInMm >= 0) || !(leadOutMm >= 0) || !(overcutMm >= 0) || !(gapToleranceMm >= 0)) {
            throw new IllegalArgumentException("kerf, leads, overcut and tolerance must be >= 0");
        }
        if (!(feedMmPerMin > 0) || !(pierceDwellS >= 0)) {
            throw new IllegalArgumentException("feed must be > 0 and dwell >= 0");
        }
    }

    /** The defaults of a process with the given kerf and leads. */
    public static CuttingOptions of(CutProcess p, double kerfMm, double leadInMm, double leadOutMm, boolean arcLeads) {
        return new CuttingOptions(kerfMm, p, leadInMm, leadOutMm, arcLeads, 0, 0.001, false, false, p.outerClockwise(),
                p.feedMmPerMin(), p.pierceDwellS());
    }

    public CuttingOptions withGapTolerance(double mm) {
        return new CuttingOptions(kerfMm, process, leadInMm, leadOutMm, arcLeads, overcutMm, mm, paperMode,
                controllerCompensation, outerClockwise, feedMmPerMin, pierceDwellS);
    }

    public CuttingOptions withPaperMode(boolean on) {
        return new CuttingOptions(kerfMm, process, leadInMm, leadOutMm, arcLeads, overcutMm, gapToleranceMm, on,
                controllerCompensation, outerClockwise, feedMmPerMin, pierceDwellS);
    }

    public CuttingOptions withControllerCompensation(boolean on) {
        return new CuttingOptions(kerfMm, process, leadInMm, leadOutMm, arcLeads, overcutMm, gapToleranceMm, paperMode,
                on, outerClockwise, feedMmPerMin, pierceDwellS);
    }

    public CuttingOptions withOvercut(double mm) {
        return new CuttingOptions(kerfMm, process, leadInMm, leadOutMm, arcLeads, mm, gapToleranceMm, paperMode,
                controllerCompensation, outerClockwise, feedMmPerMin, pierceDwellS);
    }
}
