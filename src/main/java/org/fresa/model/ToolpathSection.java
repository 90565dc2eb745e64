package org.fresa.model;

import java.util.List;
import java.util.Objects;
import org.fresa.geom.Vec3;

/**
 * The moves of one workingstep (or one pass group), with the tool and spindle that make them.
 *
 * @param label the workingstep id or another name shown to the planner and written to CSV
 * @param toolAxis unit tool axis from the tip towards the spindle, in the toolpath frame
 * @param toolDiameterMm cutter diameter
 * @param toolNumber the tool's number in the machine's magazine (T word), >= 1
 * @param spindleRpm spindle speed, >= 0 (0: not set)
 * @param start where the tool is before the first move (mm)
 * @param moves the moves in order
 */
public record ToolpathSection(
        String label,
        Vec3 toolAxis,
        double toolDiameterMm,
        int toolNumber,
        double spindleRpm,
        Vec3 start,
        List<Move> moves) {

    public ToolpathSection {
        Objects.requireNonNull(label, "label");
        Objects.requireNonNull(toolAxis, "toolAxis");
        Objects.requireNonNull(start, "start");
        moves = List.copyOf(moves);
        if (toolNumber < 1) {
            throw new IllegalArgumentException("tool number must be >= 1: " + toolNumber);
        }
    }

    /** The same moves, tool and spindle under another label. */
    public ToolpathSection withLabel(String other) {
        return new ToolpathSection(other, toolAxis, toolDiameterMm, toolNumber, spindleRpm, start, moves);
    }
}
