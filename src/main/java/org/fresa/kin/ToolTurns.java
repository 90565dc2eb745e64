package org.fresa.kin;

import java.util.List;

/**
 * The turns of the tool about its own axis that a solve may use, and the ones a cold solve tries
 * first. A spindle cuts the same at any turn, so a target out of reach at the preferred turn may
 * be reached half or a quarter turn away; the trajectory, the live reach check and the placement
 * search must try the same turns, or the live view and the placement would call a target
 * reachable that the trajectory then does not reach.
 *
 * @param free whether the tool may be turned at all (a spindle: yes; a tool with a fixed edge: no)
 * @param maxDeg the largest |turn| from the preferred x direction, degrees (0 to 180)
 */
public record ToolTurns(boolean free, double maxDeg) {

    public ToolTurns {
        if (!(maxDeg >= 0 && maxDeg <= 180)) {
            throw new IllegalArgumentException("largest tool turn " + maxDeg + " deg: expected 0 to 180");
        }
    }

    /** The turns a trajectory with these options uses. */
    public static ToolTurns of(TrajectorySolver.Options options) {
        return new ToolTurns(options.freeRotation(), options.maxFreeRotationDeg());
    }

    /**
     * The turns tried cold at a target, in order: the current turn, then half and quarter turns
     * from it. A robot that does not control the tool's full orientation (a SCARA, 4 axes) turns
     * the tool with one joint, so the turn does not decide its reach and only the current is tried.
     */
    public List<Double> firstDeg(Robot robot, double phiDeg) {
        if (!free || !robot.controlsFullOrientation()) {
            return List.of(wrapDeg(phiDeg));
        }
        List<Double> all = List.of(wrapDeg(phiDeg), wrapDeg(phiDeg + 180), wrapDeg(phiDeg + 90), wrapDeg(phiDeg - 90));
        // held within a largest turn under 180 degrees two of them can be the same turn: solved once
        return maxDeg >= 180 ? all : all.stream().distinct().toList();
    }

    /** The turn in [-180, 180] degrees, held within the largest turn allowed. */
    public double wrapDeg(double phiDeg) {
        double p = phiDeg;
        while (p > 180) {
            p -= 360;
        }
        while (p < -180) {
            p += 360;
        }
        return Math.max(-maxDeg, Math.min(maxDeg, p));
    }
}
