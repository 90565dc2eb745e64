package org.fresa.check;

import java.util.List;
import org.fresa.geom.Vec3;

/**
 * One block as the control would execute it: its words, the state it runs in, and the motion it
 * makes (the points along it, in mm in the program's frame; empty when it moves nothing).
 *
 * @param block the block as read
 * @param dialect the program's dialect
 * @param feedMove a G01/G02/G03 move (a cutting move)
 * @param path the points of the motion from its start to its end (arcs sampled every degree);
 *     empty when the block does not move or its start or end is not known (after G53)
 * @param arcInPlane a G02/G03 block in G17: the descent is uniform along it
 * @param horizontalMm for an arc in G17, its length in the XY plane
 * @param cuttingOn the spindle (or the jet) runs while the block moves
 * @param spindleRpm the spindle speed in effect (NaN when none was given)
 * @param feedMmPerMin the feed rate in effect (NaN when none was given)
 * @param tool the tool in the spindle (0 when none was called)
 * @param dwell a G04 block: its address words are a time
 * @param axis the tool axis, from the tip towards the spindle (+Z unless the post states another)
 * @param pilots the holes the program went straight down before this block ({@link Pilot})
 * @param material what is left of the stock before this block's motion ({@link Material}), null
 *     where the reading keeps none (a robot program, judged on its toolpath)
 */
public record Step(
        Words.Block block,
        NcDialect dialect,
        boolean feedMove,
        List<Vec3> path,
        boolean arcInPlane,
        double horizontalMm,
        boolean cuttingOn,
        double spindleRpm,
        double feedMmPerMin,
        int tool,
        boolean dwell,
        Vec3 axis,
        List<Pilot> pilots,
        Material material) {

    public Step {
        path = List.copyOf(path);
        pilots = List.copyOf(pilots);
        java.util.Objects.requireNonNull(axis, "axis");
    }

    /**
     * A straight move back along the tool axis, out of the cut (a reamer or a boring bar leaving
     * its hole with the spindle stopped): it removes no material.
     */
    public boolean retract() {
        if (path.size() != 2) {
            return false;
        }
        Vec3 d = path.get(1).minus(path.get(0));
        double along = d.dot(axis);
        return along > 0 && d.minus(axis.times(along)).norm() <= 1e-3;
    }
}
