package org.fresa.cutting;

import java.util.Locale;
import java.util.Optional;
import org.fresa.model.EnumWords;

/**
 * A thermal or abrasive jet process with its defaults: cutting feed (mm/min), pierce dwell (s)
 * and the sense contours are cut in. Plasma swirl leaves the square side of the kerf on the
 * right of travel, so outer contours run clockwise and holes counter-clockwise (the part is
 * always on the right, the scrap on the left, the G41 side); laser and waterjet follow the same
 * convention by default.
 */
public enum CutProcess {
    PLASMA(2000, 0.5, true),
    LASER(3000, 0.2, true),
    WATERJET(400, 1.5, true);

    private final double feedMmPerMin;
    private final double pierceDwellS;
    private final boolean outerClockwise;

    CutProcess(double feedMmPerMin, double pierceDwellS, boolean outerClockwise) {
        this.feedMmPerMin = feedMmPerMin;
        this.pierceDwellS = pierceDwellS;
        this.outerClockwise = outerClockwise;
    }

    public double feedMmPerMin() {
        return feedMmPerMin;
    }

    public double pierceDwellS() {
        return pierceDwellS;
    }

    /** True when outer contours are cut clockwise by default. */
    public boolean outerClockwise() {
        return outerClockwise;
    }

    /** True when holes are cut clockwise by default: the opposite sense of the outer contours. */
    public boolean holesClockwise() {
        return !outerClockwise;
    }

    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    @Override
    public String toString() {
        return id();
    }

    public static Optional<CutProcess> ofId(String id) {
        return EnumWords.parseIgnoringCase(CutProcess.class, CutProcess::id, id);
    }
}
