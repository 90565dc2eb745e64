package org.fresa.job;

import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.kin.JointLimit;
import org.fresa.kin.JointType;
import org.fresa.kin.Robot;
import org.fresa.kin.SerialRobot;
import org.fresa.kin.TrajectoryPoint;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.fresa.post.KrlWriter;
import org.fresa.post.RapidWriter;
import org.fresa.post.RobotProgram;
import org.fresa.post.RobotProgramWriter;

/**
 * Turns a solved joint trajectory into a {@link RobotProgram} and writes the robot-program
 * formats ({@code xml}, {@code rapid}, {@code krl}) of {@code --formats}.
 *
 * <p>Motions: the first point of each workingstep and every relink point are joint motions
 * (MoveAbsJ, PTP) at {@link #JOINT_SPEED_MM_PER_S}; the other reachable points are linear motions
 * at the workingstep's feed. Unreachable points are left out of the programs (trajectory.csv lists
 * them), so a program never asks the robot for a pose it cannot take.
 */
public final class RobotPrograms {

    /** The formats that are robot programs. */
    public static final List<String> FORMATS = List.of("xml", "rapid", "krl");

    /** The speed of joint motions (approach, relinks), mm/s. */
    public static final double JOINT_SPEED_MM_PER_S = 250;

    /** Blend radius of linear motions on the part, mm: small against the toolpath's chord tolerance. */
    public static final double ZONE_MM = 0.1;

    private RobotPrograms() {
    }

    /** The program of a trajectory. */
    public static RobotProgram of(String programName, Robot robot, Toolpath path, List<TrajectoryPoint> points) {
        List<RobotProgram.Joint> joints = new ArrayList<>();
        for (JointLimit j : robot.joints()) {
            joints.add(new RobotProgram.Joint(j.name(), j.type() == JointType.PRISMATIC
                    ? RobotProgram.JointType.PRISMATIC : RobotProgram.JointType.REVOLUTE, j.min(), j.max()));
        }
        Map<String, Double> feed = feedsByWorkingstep(path);
        Map<String, Double> spindle = new HashMap<>();
        for (ToolpathSection s : path.sections()) {
            spindle.merge(s.label(), s.spindleRpm(), Math::max);
        }
        List<RobotProgram.Motion> motions = new ArrayList<>();
        String ws = null;
        for (int i = 0; i < points.size(); i++) {
            TrajectoryPoint p = points.get(i);
            if (p.status() == TrajectoryPoint.Status.UNREACHABLE) {
                continue;
            }
            boolean relink = p.status() == TrajectoryPoint.Status.RELINK;
            boolean first = !p.label().equals(ws);
            ws = p.label();
            List<Double> q = new ArrayList<>();
            for (double v : p.q()) {
                q.add(v);
            }
            boolean joint = relink || first;
            double speed = joint ? JOINT_SPEED_MM_PER_S : feed.getOrDefault(p.label(), 60.0) / 60.0;
            Transform3 pose = p.reached().orElse(p.target());
            motions.add(new RobotProgram.Motion(i, p.label(),
                    joint ? RobotProgram.MotionType.JOINT : RobotProgram.MotionType.LINEAR,
                    relink ? RobotProgram.PointRole.RELINK : RobotProgram.PointRole.PART, q, pose, speed,
                    joint ? 0 : ZONE_MM, spindle.getOrDefault(p.label(), 0.0)));
        }
        return new RobotProgram(programName, robot.name(), joints, motions);
    }

    private static Map<String, Double> feedsByWorkingstep(Toolpath path) {
        Map<String, Double> m = new HashMap<>();
        for (ToolpathSection s : path.sections()) {
            for (Move mv : s.moves()) {
                double f = mv instanceof Move.Linear l ? l.feedMmPerMin()
                        : mv instanceof Move.Circular c ? c.feedMmPerMin() : 0;
                if (f > 0) {
                    m.merge(s.label(), f, Math::max);
                }
            }
        }
        return m;
    }

    /** Writes the program in each requested robot format; returns the formats it handled. */
    public static List<String> write(RobotProgram program, Robot robot, List<String> formats, OutputFolder out)
            throws IOException {
        RapidWriter.ArmGeometry arm = armGeometry(robot);
        List<String> done = new ArrayList<>();
        if (formats.contains("xml")) {
            out.write("program.xml", os -> RobotProgramXml.write(program, arm, os));
            done.add("xml");
        }
        for (RobotProgramWriter w : List.of(new RapidWriter(arm), new KrlWriter(arm))) {
            if (formats.contains(w.format())) {
                out.write(w.fileName(), os -> {
                    Writer wr = new OutputStreamWriter(os, StandardCharsets.UTF_8);
                    w.write(program, wr);
                    wr.flush();
                });
                done.add(w.format());
            }
        }
        return done;
    }

    /**
     * The arm configuration that confdata and Status bits need, from the robot's own kinematics:
     * for a 6R arm with a spherical wrist, the wrist centre is the origin of the DH frame of the
     * wrist joint; "rear" is the wrist centre behind axis 1, "lower arm" the wrist centre on the
     * other side of the shoulder-elbow line than at the home position. Other robots have neither.
     */
    public static RapidWriter.ArmGeometry armGeometry(Robot robot) {
        if (!(robot instanceof SerialRobot s) || s.dof() != 6 || s.wristJoint() < 0) {
            return new RapidWriter.ArmGeometry() {
                @Override
                public boolean rear(RobotProgram.Motion m) {
                    return false;
                }

                @Override
                public boolean lowerArm(RobotProgram.Motion m) {
                    return false;
                }
            };
        }
        double homeSide = Math.signum(elbowSide(s, new double[6]));
        return new RapidWriter.ArmGeometry() {
            @Override
            public boolean rear(RobotProgram.Motion m) {
                double[] q = values(m);
                Transform3 f1 = s.chain().frame(1, q);
                Vec3 w = s.chain().frame(s.wristJoint(), q).translationPart();
                Vec3 base = s.chain().frame(0, q).translationPart();
                Vec3 up = s.chain().frame(0, q).zAxis();
                Vec3 forward = f1.xAxis().minus(up.times(f1.xAxis().dot(up)));
                return w.minus(base).dot(forward) < 0;
            }

            @Override
            public boolean lowerArm(RobotProgram.Motion m) {
                return Math.signum(elbowSide(s, values(m))) != homeSide;
            }
        };
    }

    private static double elbowSide(SerialRobot s, double[] q) {
        Vec3 shoulder = s.chain().frame(1, q).translationPart();
        Transform3 f2 = s.chain().frame(2, q);
        Vec3 elbow = f2.translationPart();
        Vec3 w = s.chain().frame(s.wristJoint(), q).translationPart();
        return elbow.minus(shoulder).cross(w.minus(shoulder)).dot(f2.zAxis());
    }

    private static double[] values(RobotProgram.Motion m) {
        double[] q = new double[m.jointValues().size()];
        for (int i = 0; i < q.length; i++) {
            q[i] = m.joint(i);
        }
        return q;
    }
}
