package org.fresa.post;

import java.util.List;
import java.util.Objects;
import org.fresa.geom.Transform3;

/**
 * A robot program ready to be written in a robot language or as offline-programming XML: the
 * robot's joints and one motion per reachable trajectory point, in order. Built from a joint
 * trajectory; unreachable points are not in it.
 *
 * @param programName a name for the program (each writer sanitises it for its language)
 * @param robotName the robot's name (e.g. irb140)
 * @param joints the robot's joints in order
 * @param motions the motions in order
 * @param tools the tool frames, at least one; each motion uses the one of its workingstep
 */
public record RobotProgram(
        String programName, String robotName, List<Joint> joints, List<Motion> motions, List<ToolFrame> tools) {

    public RobotProgram {
        Objects.requireNonNull(programName, "programName");
        Objects.requireNonNull(robotName, "robotName");
        joints = List.copyOf(joints);
        tools = List.copyOf(tools);
        if (tools.isEmpty()) {
            throw new IllegalArgumentException("a robot program needs a tool frame");
        }
        motions = oneValuePerJoint(List.copyOf(motions), joints.size());
    }

    /** The motions, once each is seen to give a value for every joint of the robot. */
    private static List<Motion> oneValuePerJoint(List<Motion> motions, int joints) {
        for (Motion m : motions) {
            if (m.jointValues().size() != joints) {
                throw new IllegalArgumentException("motion " + m.index() + " has "
                        + m.jointValues().size() + " joint values for " + joints + " joints");
            }
        }
        return motions;
    }

    /** A program whose every motion uses the flange as its TCP (tool 1, the identity). */
    public RobotProgram(String programName, String robotName, List<Joint> joints, List<Motion> motions) {
        this(programName, robotName, joints, motions, List.of(new ToolFrame(1, Transform3.IDENTITY, List.of())));
    }

    /** The tool frame of a workingstep: the one that lists it, else the first. */
    public ToolFrame toolOf(String workingstep) {
        for (ToolFrame t : tools) {
            if (t.workingsteps().contains(workingstep)) {
                return t;
            }
        }
        return tools.get(0);
    }

    /**
     * A tool as the controller knows it: its number and its TCP in the flange frame (spindle and
     * tool length, z from the flange towards the tip).
     *
     * @param number the tool's number (the T word of the toolpath), >= 1
     * @param tcp the TCP in the flange frame (mm)
     * @param workingsteps the workingsteps cut with it
     */
    public record ToolFrame(int number, Transform3 tcp, List<String> workingsteps) {
        public ToolFrame {
            Objects.requireNonNull(tcp, "tcp");
            workingsteps = List.copyOf(workingsteps);
            if (number < 1) {
                throw new IllegalArgumentException("tool number must be >= 1: " + number);
            }
        }
    }

    /** Revolute joints move in degrees, prismatic ones in millimetres. */
    public enum JointType {
        REVOLUTE,
        PRISMATIC;

        /** The unit of the joint's values and limits. */
        public String unit() {
            return switch (this) {
                case REVOLUTE -> "deg";
                case PRISMATIC -> "mm";
            };
        }
    }

    /** A joint: its name (A1, Joint 1, ...), type and limits in its unit. */
    public record Joint(String name, JointType type, double minValue, double maxValue) {
        public Joint {
            Objects.requireNonNull(name, "name");
            Objects.requireNonNull(type, "type");
        }
    }

    /** How the robot moves to a point: interpolated in joints, or on a straight line of the tool tip. */
    public enum MotionType {
        JOINT,
        LINEAR
    }

    /** What the point is for: on the part, or a relink point lifted off the part. */
    public enum PointRole {
        PART,
        RELINK
    }

    /**
     * One motion.
     *
     * @param index the trajectory row (trajectory.csv index)
     * @param workingstep the workingstep it belongs to
     * @param type joint or linear motion
     * @param role on the part or a relink point
     * @param jointValues joint values in each joint's unit (deg or mm), as trajectory.csv has them
     * @param target the tool-tip pose in the robot base frame (mm), from forward kinematics
     * @param speedMmPerS tool-tip speed along the path (mm/s)
     * @param zoneMm rounding (blend) radius; 0 for a fine point
     * @param dwellS time the tool waits at the point once reached (s), 0 for none; a point with a
     *     dwell is a fine point
     * @param spindleRpm the spindle speed while the robot makes the motion, rpm; 0 with the spindle stopped
     */
    public record Motion(
            int index,
            String workingstep,
            MotionType type,
            PointRole role,
            List<Double> jointValues,
            Transform3 target,
            double speedMmPerS,
            double zoneMm,
            double dwellS,
            double spindleRpm) {

        public Motion {
            if (!(dwellS >= 0) || !Double.isFinite(dwellS)) {
                throw new IllegalArgumentException("dwell must be >= 0 s: " + dwellS);
            }
            if (dwellS > 0 && zoneMm > 0) {
                throw new IllegalArgumentException("a point with a dwell is a fine point, zone " + zoneMm);
            }
            Objects.requireNonNull(workingstep, "workingstep");
            Objects.requireNonNull(type, "type");
            Objects.requireNonNull(role, "role");
            jointValues = List.copyOf(jointValues);
            Objects.requireNonNull(target, "target");
            if (!(speedMmPerS > 0) || !Double.isFinite(speedMmPerS)) {
                throw new IllegalArgumentException("speed must be > 0: " + speedMmPerS);
            }
            if (!(zoneMm >= 0)) {
                throw new IllegalArgumentException("zone must be >= 0: " + zoneMm);
            }
            if (!(spindleRpm >= 0) || Double.isInfinite(spindleRpm)) {
                throw new IllegalArgumentException("spindle speed must be finite and >= 0: " + spindleRpm);
            }
        }

        public double joint(int i) {
            return jointValues.get(i);
        }
    }
}
