package org.fresa.kin;

import java.util.List;
import org.fresa.geom.Transform3;

/**
 * A robot: its joints, forward kinematics (joint values in deg / mm to the tool pose in the
 * robot base frame, mm) and inverse kinematics. The tool frame's z axis points from the flange
 * towards the tool tip (into the material); the tool tip is the TCP.
 */
public sealed interface Robot permits SerialRobot, TriceptRobot {

    /** The name used on the command line ({@code irb140}). */
    String name();

    /** One line for people. */
    String description();

    List<JointLimit> joints();

    default int dof() {
        return joints().size();
    }

    /**
     * Whether the tool may be turned freely about its own axis (a spindle): true when the robot
     * has at least six joints and so controls the full orientation.
     */
    default boolean controlsFullOrientation() {
        return dof() >= 6;
    }

    /** The tool pose for joint values q (deg / mm). */
    Transform3 forward(double... q);

    /**
     * The tool frame (TCP) in the flange frame: the identity for a bare flange, else the spindle
     * and the tool's length, its z pointing from the flange towards the tip.
     */
    Transform3 tool();

    /** The same robot with another tool frame (TCP) in the flange frame. */
    Robot withTool(Transform3 tool);

    /** The flange pose for joint values q (deg / mm): {@link #forward} without the tool frame. */
    default Transform3 flange(double... q) {
        return forward(q).times(tool().inverse());
    }

    /** A new solver with its own work buffers. */
    IkSolver newSolver(IkOptions options);

    /**
     * The wrist-singularity measure at q: |sin| of the angle between the first and last wrist
     * axes (0 singular, 1 far from it), or 1 when the robot has no spherical wrist.
     */
    double wristConditioning(double[] q);
}
