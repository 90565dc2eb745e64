package org.fresa.kin;

/**
 * A joint of a robot as the planner sees it: its name, type and limits in its own unit.
 *
 * @param name q1, q2, ...
 * @param type revolute (deg) or prismatic (mm)
 * @param min lower limit (deg or mm)
 * @param max upper limit (deg or mm)
 */
public record JointLimit(String name, JointType type, double min, double max) {

    /**
     * @throws IllegalArgumentException for limits that are not finite or whose max is not above
     *     the min (a serial joint's limits are held to the same rule in {@link DhJoint})
     */
    public JointLimit {
        java.util.Objects.requireNonNull(name, "name");
        java.util.Objects.requireNonNull(type, "type");
        if (!Double.isFinite(min) || !Double.isFinite(max) || !(max > min)) {
            throw new IllegalArgumentException(
                    "joint " + name + ": limits must have max > min, found " + min + " .. " + max + " " + type.unit());
        }
    }

    public boolean contains(double q, double slack) {
        return q >= min - slack && q <= max + slack;
    }

    /** Distance to the nearer limit as a fraction of the range: 0 at a limit, 0.5 mid-range. */
    public double margin(double q) {
        return Math.min(q - min, max - q) / (max - min);
    }
}
