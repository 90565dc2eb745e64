package org.fresa.sole;

import java.util.Objects;

/**
 * A tool that cuts tread grooves (the thesis's hand-made HSS form bits: 3.5, 4, 6 and 12 mm,
 * 4000 rpm, 160 mm/min, the full 2 mm in one pass).
 *
 * @param id the name the job's figures refer to
 * @param number the machine's tool number (T word), >= 1
 * @param diameterMm cutter diameter, > 0 (the groove width)
 * @param spindleRpm spindle speed, >= 0
 * @param feedMmPerMin feed along the groove, > 0
 * @param plungeFeedMmPerMin feed of the plunge, > 0
 */
public record TreadTool(
        String id, int number, double diameterMm, double spindleRpm, double feedMmPerMin, double plungeFeedMmPerMin) {

    public TreadTool {
        Objects.requireNonNull(id, "id");
        if (number < 1 || !(diameterMm > 0) || !(spindleRpm >= 0) || !(feedMmPerMin > 0) || !(plungeFeedMmPerMin > 0)) {
            throw new IllegalArgumentException("tool " + id + ": number >= 1, diameter, feeds > 0, rpm >= 0");
        }
    }
}
