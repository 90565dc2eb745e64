package org.fresa.kin;

/** What a joint's variable moves: an angle (degrees at the boundary) or a length (mm). */
public enum JointType {
    /** theta = q + offset; q in degrees at the boundary, radians inside. */
    REVOLUTE,
    /** d = q + offset; q in mm. */
    PRISMATIC;

    /** "deg" or "mm". */
    public String unit() {
        return this == REVOLUTE ? "deg" : "mm";
    }
}
