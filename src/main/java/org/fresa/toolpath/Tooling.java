package org.fresa.toolpath;

import java.util.List;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.fresa.pocket.PocketTechnology;

/**
 * The cutter and its technology for one operation.
 *
 * @param toolNumber magazine number (T word), >= 1
 * @param diameterMm cutter diameter, > 0
 * @param spindleRpm spindle speed, >= 0
 * @param feedMmPerMin cutting feed, > 0
 * @param plungeFeedMmPerMin feed along the tool axis (plunges, ramps, drilling), > 0
 */
public record Tooling(
        int toolNumber, double diameterMm, double spindleRpm, double feedMmPerMin, double plungeFeedMmPerMin) {

    public Tooling {
        if (toolNumber < 1 || !(diameterMm > 0) || spindleRpm < 0 || !(feedMmPerMin > 0) || !(plungeFeedMmPerMin > 0)) {
            throw new IllegalArgumentException("bad tooling: T" + toolNumber + " D" + diameterMm + " S" + spindleRpm
                    + " F" + feedMmPerMin + "/" + plungeFeedMmPerMin);
        }
    }

    public double radiusMm() {
        return diameterMm / 2;
    }

    /** A section cut with this tool along the feature frame's +Z, the tool first standing at {@code start}. */
    ToolpathSection section(String label, Vec3 start, List<Move> moves) {
        return new ToolpathSection(label, Vec3.UNIT_Z, diameterMm, toolNumber, spindleRpm, start, moves);
    }

    /**
     * The pocket module's technology for clearing a region with this tool from {@code topZ} down
     * to {@code bottomZ} in layers of at most {@code layerMm}, with no finishing allowance and the
     * cutting feed throughout: the stepover as a fraction of the diameter (kept within 0.001 to
     * 1), and a spindle speed of at least 1 rpm, which the region engine needs.
     */
    PocketTechnology regionTechnology(double stepoverMm, double topZ, double bottomZ, double layerMm) {
        double fraction = Math.min(1, Math.max(stepoverMm / diameterMm, 1e-3));
        return new PocketTechnology(
                diameterMm, fraction, 0, topZ, bottomZ, layerMm, Math.max(spindleRpm, 1), feedMmPerMin, feedMmPerMin);
    }
}
