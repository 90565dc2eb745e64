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

    /** The speed of joint motions (approach, relinks), mm/s. */
    public static final double JOINT_SPEED_MM_PER_S = 250;

    /** Blend radius of linear motions on the part, mm: small against the toolpath's chord tolerance. */
    public static final double ZONE_MM = 0.1;

    private RobotPrograms() {
    }

    /** The program of a trajectory whose every workingstep uses the robot's own tool frame. */
    public static RobotProgram of(String programName, Robot robot, Toolpath path, List<TrajectoryPoint> points) {
        return of(programName, robot, path, points, label -> robot.tool());
    }

    /**
     * The program of a trajectory, one tool frame per tool of the toolpath (its T number) with the
     * TCP of its workingsteps.
     *
     * @param tcpOfLabel the TCP in the flange frame of each workingstep
     */
    public static RobotProgram of(String programName, Robot robot, Toolpath path, List<TrajectoryPoint> points,
            java.util.function.Function<String, Transform3> tcpOfLabel) {
        List<RobotProgram.Joint> joints = new ArrayList<>();
        for (JointLimit j : robot.joints()) {
            joints.add(new RobotProgram.Joint(j.name(), j.type() == JointType.PRISMATIC
                    ? RobotProgram.JointType.PRISMATIC : RobotProgram.JointType.REVOLUTE, j.min(), j.max()));
        }
        Map<String, Double> feed = feedsByWorkingstep(path);
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
                    joint ? 0 : ZONE_MM));
        }
        return new RobotProgram(programName, robot.name(), joints, motions, tools(path, points, tcpOfLabel));
    }

    /** One tool frame per tool number and TCP, numbered as the toolpath numbers its tools. */
    private static List<RobotProgram.ToolFrame> tools(Toolpath path, List<TrajectoryPoint> points,
            java.util.function.Function<String, Transform3> tcpOfLabel) {
        Map<Integer, Transform3> tcpOf = new java.util.TreeMap<>();
        Map<Integer, List<String>> steps = new HashMap<>();
        int next = 1;
        for (ToolpathSection s : path.sections()) {
            next = Math.max(next, s.toolNumber() + 1);
        }
        for (ToolpathSection s : path.sections()) {
            Transform3 tcp = tcpOfLabel.apply(s.label());
            int number = s.toolNumber();
            if (tcpOf.containsKey(number) && !tcpOf.get(number).equals(tcp)) {
                // one magazine number with another TCP: a tool of its own for the controller
                number = next++;
            }
            tcpOf.putIfAbsent(number, tcp);
            List<String> ws = steps.computeIfAbsent(number, k -> new ArrayList<>());
            if (!ws.contains(s.label())) {
                ws.add(s.label());
            }
        }
        if (tcpOf.isEmpty()) {
            // targets without a toolpath: one tool, the TCP of the first point's label
            tcpOf.put(1, tcpOfLabel.apply(points.isEmpty() ? "" : points.get(0).label()));
            steps.put(1, List.of());
        }
        List<RobotProgram.ToolFrame> out = new ArrayList<>();
        tcpOf.forEach((n, tcp) -> out.add(new RobotProgram.ToolFrame(n, tcp, steps.get(n))));
        return out;
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
