package org.fresa.robot;

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
import org.fresa.io.OutputFolder;
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

    /**
     * The path tolerance of linear motions on the part (mm): the blend radius of every point
     * inside a workingstep (RAPID {@code z1}, KRL {@code $APO.CDIS}); a corner is rounded within
     * it. The ends of workingsteps, relinks, points before a gap and dwells are fine points.
     */
    public static final double ZONE_MM = 1;

    private RobotPrograms() {}

    /** The program of a trajectory whose every workingstep uses the robot's own tool frame. */
    public static RobotProgram of(String programName, Robot robot, Toolpath path, List<TrajectoryPoint> points) {
        return of(programName, robot, path, points, label -> robot.tool(), List.of());
    }

    /**
     * The program of a trajectory, one tool frame per tool of the toolpath (its T number) with the
     * TCP of its workingsteps.
     *
     * @param tcpOfLabel the TCP in the flange frame of each workingstep
     * @param dwellAfterTarget the wait at each target (s), in the order of the trajectory's targets
     *     (its rows not inserted by the solver); missing entries are no wait
     */
    public static RobotProgram of(
            String programName,
            Robot robot,
            Toolpath path,
            List<TrajectoryPoint> points,
            java.util.function.Function<String, Transform3> tcpOfLabel,
            List<Double> dwellAfterTarget) {
        List<RobotProgram.Joint> joints = new ArrayList<>();
        for (JointLimit j : robot.joints()) {
            joints.add(new RobotProgram.Joint(j.name(), typeInProgram(j.type()), j.min(), j.max()));
        }
        Map<String, Double> feed = feedsByWorkingstep(path);
        Map<String, Double> spindle = new HashMap<>();
        for (ToolpathSection s : path.sections()) {
            spindle.merge(s.label(), s.spindleRpm(), Math::max);
        }
        List<RobotProgram.Motion> motions = new ArrayList<>();
        String ws = null;
        int target = -1;
        for (int i = 0; i < points.size(); i++) {
            TrajectoryPoint p = points.get(i);
            if (!p.inserted()) {
                target++;
            }
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
            double dwell = !p.inserted() && target < dwellAfterTarget.size() ? dwellAfterTarget.get(target) : 0;
            double speed = joint ? JOINT_SPEED_MM_PER_S : feed.getOrDefault(p.label(), 60.0) / 60.0;
            Transform3 pose = p.reached().orElse(p.target());
            boolean stop = joint || dwell > 0 || stopsAfter(points, i);
            motions.add(new RobotProgram.Motion(
                    i,
                    p.label(),
                    joint ? RobotProgram.MotionType.JOINT : RobotProgram.MotionType.LINEAR,
                    relink ? RobotProgram.PointRole.RELINK : RobotProgram.PointRole.PART,
                    q,
                    pose,
                    speed,
                    stop ? 0 : ZONE_MM,
                    dwell,
                    spindle.getOrDefault(p.label(), 0.0)));
        }
        return new RobotProgram(programName, robot.name(), joints, motions, tools(path, points, tcpOfLabel));
    }

    /**
     * Whether the robot must stop exactly at point i: the last point of its workingstep or of the
     * program, before a relink, or before a point the robot cannot reach (the program skips it).
     */
    private static boolean stopsAfter(List<TrajectoryPoint> points, int i) {
        if (i + 1 >= points.size()) {
            return true;
        }
        TrajectoryPoint next = points.get(i + 1);
        return next.status() != TrajectoryPoint.Status.OK
                || !next.label().equals(points.get(i).label());
    }

    /** One tool frame per tool number and TCP, numbered as the toolpath numbers its tools. */
    private static List<RobotProgram.ToolFrame> tools(
            Toolpath path, List<TrajectoryPoint> points, java.util.function.Function<String, Transform3> tcpOfLabel) {
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
                double f = mv instanceof Move.Linear l
                        ? l.feedMmPerMin()
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
                // a wrist centre on the axis (within a nanometre) is in front, whichever way rounding goes
                return w.minus(base).dot(forward) < -1e-6;
            }

            @Override
            public boolean lowerArm(RobotProgram.Motion m) {
                // a stretched arm (elbow on the line, within rounding) is the upper arm, as at home
                return elbowSide(s, values(m)) * homeSide < -1e-6;
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

    /** A joint's type as the program names it: a prismatic joint moves in mm, any other turns in degrees. */
    private static RobotProgram.JointType typeInProgram(JointType type) {
        return type == JointType.PRISMATIC ? RobotProgram.JointType.PRISMATIC : RobotProgram.JointType.REVOLUTE;
    }
}
