package org.fresa.ui;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.kin.JointLimit;
import org.fresa.kin.JointType;
import org.fresa.kin.Robot;
import org.fresa.kin.SerialRobot;
import org.fresa.kin.TrajectoryPoint;
import org.fresa.kin.TriceptRobot;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

/**
 * What the 3D cell view draws, in the robot base frame (mm), without Swing: the floor grid, the
 * table top, the workpiece (the box around the cutting moves, in the workpiece frame), the
 * toolpath as the robot follows it (segments coloured by the status of their end point), the
 * robot as links from its forward kinematics, and the base, table, workpiece and tool frames.
 *
 * @param floor grid lines at the lowest height of the scene
 * @param table the table top's outline (closed), empty when unknown
 * @param workpiece the workpiece box's twelve edges, empty before a trajectory is computed
 * @param path consecutive trajectory points
 * @param links the robot's links as polylines (joint centres)
 * @param joints the joint centres drawn as dots
 * @param frames named frames drawn as axes triads
 * @param selected the replayed point, if any
 * @param tool the spindle and cutter at the flange, when known
 */
record CellScene(
        List<List<Vec3>> floor,
        List<Vec3> table,
        List<List<Vec3>> workpiece,
        List<PathSegment> path,
        List<List<Vec3>> links,
        List<Vec3> joints,
        List<Frame> frames,
        Optional<PathPoint> selected,
        Optional<ToolShape> tool) {

    CellScene(
            List<List<Vec3>> floor,
            List<Vec3> table,
            List<List<Vec3>> workpiece,
            List<PathSegment> path,
            List<List<Vec3>> links,
            List<Vec3> joints,
            List<Frame> frames,
            Optional<PathPoint> selected) {
        this(floor, table, workpiece, path, links, joints, frames, selected, Optional.empty());
    }

    /**
     * The spindle (from the flange to its nose) and the cutter (from the nose to the tip, of the
     * STEP-NC tool's diameter), in the robot base frame.
     */
    record ToolShape(Vec3 flange, Vec3 nose, Vec3 tip, double diameterMm) {
        /** From the flange to the tool tip (mm): spindle and tool length together. */
        double lengthMm() {
            return flange.distance(tip);
        }

        /** The cutter's length from the spindle nose to the tip (mm). */
        double cutterLengthMm() {
            return nose.distance(tip);
        }
    }

    /**
     * The same scene with the robot drawn to its flange and the spindle and cutter on it: the
     * tool frame at the tool tip.
     */
    CellScene withTool(ToolShape shape, Transform3 tipPose) {
        List<Frame> fs = new ArrayList<>();
        for (Frame f : frames) {
            fs.add(f.name().equals("tool") ? new Frame("tool", tipPose, f.axisMm()) : f);
        }
        return new CellScene(floor, table, workpiece, path, links, joints, fs, selected, Optional.of(shape));
    }

    CellScene {
        floor = List.copyOf(floor);
        table = List.copyOf(table);
        workpiece = List.copyOf(workpiece);
        path = List.copyOf(path);
        links = List.copyOf(links);
        joints = List.copyOf(joints);
        frames = List.copyOf(frames);
        java.util.Objects.requireNonNull(tool, "tool");
    }

    /** A piece of the toolpath, coloured by the status of the point it ends at. */
    record PathSegment(Vec3 from, Vec3 to, TrajectoryPoint.Status status) {}

    /** A trajectory point. */
    record PathPoint(Vec3 at, TrajectoryPoint.Status status) {}

    /** A frame drawn as x (red), y (green), z (blue) axes of the given length. */
    record Frame(String name, Transform3 pose, double axisMm) {}

    /** Every point drawn, to fit the camera. */
    List<Vec3> points() {
        List<Vec3> out = new ArrayList<>(table);
        workpiece.forEach(out::addAll);
        for (PathSegment s : path) {
            out.add(s.from());
            out.add(s.to());
        }
        links.forEach(out::addAll);
        for (Frame f : frames) {
            out.add(f.pose().translationPart());
        }
        tool.ifPresent(t -> out.add(t.tip()));
        return out;
    }

    /**
     * The scene.
     *
     * @param robot the robot
     * @param q its joint values (deg / mm), drawn when its forward kinematics exists
     * @param robotTable the table frame in the robot base frame
     * @param robotPiece the workpiece frame in the robot base frame
     * @param toolpath the toolpath in the workpiece frame, if computed
     * @param points the trajectory (targets in the robot base frame)
     * @param selected the replayed point's index, or -1
     */
    static CellScene of(
            Robot robot,
            double[] q,
            Transform3 robotTable,
            Transform3 robotPiece,
            Optional<Toolpath> toolpath,
            List<TrajectoryPoint> points,
            int selected) {
        List<List<Vec3>> links = new ArrayList<>();
        List<Vec3> joints = new ArrayList<>();
        Optional<Transform3> tool = robotLinks(robot, q, links, joints);

        List<List<Vec3>> box = toolpath.map(t -> workpieceEdges(t, robotPiece)).orElse(List.of());
        List<PathSegment> path = new ArrayList<>();
        for (int i = 1; i < points.size(); i++) {
            path.add(new PathSegment(
                    points.get(i - 1).target().translationPart(),
                    points.get(i).target().translationPart(),
                    points.get(i).status()));
        }
        Optional<PathPoint> sel = selected >= 0 && selected < points.size()
                ? Optional.of(new PathPoint(
                        points.get(selected).target().translationPart(),
                        points.get(selected).status()))
                : Optional.empty();

        List<Vec3> everything = new ArrayList<>();
        everything.add(Vec3.ZERO);
        everything.add(robotTable.translationPart());
        everything.add(robotPiece.translationPart());
        box.forEach(everything::addAll);
        links.forEach(everything::addAll);
        for (TrajectoryPoint p : points) {
            everything.add(p.target().translationPart());
        }
        List<Vec3> table = tableOutline(robotTable, box, robotPiece);
        everything.addAll(table);
        double size = extent(everything);
        double axis = Math.max(40, 0.08 * size);
        List<Frame> frames = new ArrayList<>();
        frames.add(new Frame("base", Transform3.IDENTITY, axis * 1.5));
        frames.add(new Frame("table", robotTable, axis));
        frames.add(new Frame("workpiece", robotPiece, axis));
        tool.ifPresent(t -> frames.add(new Frame("tool", t, axis * 0.8)));
        return new CellScene(floor(everything), table, box, path, links, joints, frames, sel);
    }

    /**
     * Joint values to draw the robot with before anything is computed: 0 for revolute joints
     * (kept within the limits), mid-range for prismatic ones.
     */
    static double[] homePose(Robot robot) {
        List<JointLimit> ls = robot.joints();
        double[] q = new double[ls.size()];
        for (int i = 0; i < q.length; i++) {
            JointLimit l = ls.get(i);
            q[i] = l.type() == JointType.PRISMATIC ? (l.min() + l.max()) / 2 : Math.max(l.min(), Math.min(l.max(), 0));
        }
        return q;
    }

    /** Fills the links and joints; returns the tool pose, empty when q has no assembly. */
    private static Optional<Transform3> robotLinks(Robot robot, double[] q, List<List<Vec3>> links, List<Vec3> joints) {
        if (q.length != robot.dof()) {
            return Optional.empty();
        }
        try {
            if (robot instanceof SerialRobot s) {
                List<Vec3> arm = new ArrayList<>();
                arm.add(Vec3.ZERO);
                Transform3 previous = s.chain().frame(0, q);
                addPoint(arm, previous.translationPart());
                joints.add(previous.translationPart());
                for (int i = 1; i <= s.chain().dof(); i++) {
                    // A_i = Rz(theta) Tz(d) Tx(a) Rx(alpha): first along z_(i-1) by d, then along x_i by a
                    org.fresa.kin.DhJoint j = s.chain().joints().get(i - 1);
                    double d = j.type() == JointType.PRISMATIC ? q[i - 1] + j.dMm() : j.dMm();
                    addPoint(
                            arm,
                            previous.translationPart().plus(previous.zAxis().times(d)));
                    Transform3 f = s.chain().frame(i, q);
                    addPoint(arm, f.translationPart());
                    if (i < s.chain().dof()) {
                        joints.add(f.translationPart());
                    }
                    previous = f;
                }
                Transform3 tip = s.forward(q);
                addPoint(arm, tip.translationPart());
                links.add(arm);
                return Optional.of(tip);
            } else if (robot instanceof TriceptRobot t) {
                Vec3 w = t.wristCentre(q[0], q[1], q[2]);
                Transform3 tip = t.forward(q);
                Vec3 n = w.normalized();
                Vec3 c = n.times(w.norm() - t.centreOffsetMm());
                List<Vec3> platform = new ArrayList<>();
                for (int k = 0; k < 3; k++) {
                    Vec3 a = t.legBase(k);
                    Vec3 u = a.minus(n.times(a.dot(n))).normalized();
                    Vec3 b = c.plus(u.times(t.platformRadiusMm()));
                    links.add(List.of(a, b));
                    platform.add(b);
                    joints.add(a);
                }
                platform.add(platform.get(0));
                links.add(platform);
                links.add(List.of(Vec3.ZERO, c, w, tip.translationPart()));
                joints.add(w);
                return Optional.of(tip);
            }
        } catch (IllegalArgumentException e) {
            // no assembly for these leg lengths: nothing to draw
            links.clear();
            joints.clear();
        }
        return Optional.empty();
    }

    private static void addPoint(List<Vec3> line, Vec3 p) {
        if (line.isEmpty() || line.get(line.size() - 1).distance(p) > 1e-9) {
            line.add(p);
        }
    }

    /** The box around the cutting moves in the workpiece frame, as 12 edges in the base frame. */
    static List<List<Vec3>> workpieceEdges(Toolpath toolpath, Transform3 robotPiece) {
        double[] lo = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
        double[] hi = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        boolean any = false;
        for (ToolpathSection s : toolpath.sections()) {
            for (Move m : s.moves()) {
                if (m instanceof Move.Linear l) {
                    any = true;
                    include(lo, hi, l.end(), 0);
                } else if (m instanceof Move.Circular c) {
                    any = true;
                    include(lo, hi, c.end(), 0);
                    include(lo, hi, c.center(), c.end().minus(c.center()).norm());
                }
            }
        }
        if (!any) {
            return List.of();
        }
        if (hi[2] - lo[2] < 1) {
            lo[2] = hi[2] - 10;
        }
        Vec3[] corner = new Vec3[8];
        for (int i = 0; i < 8; i++) {
            Vec3 p = new Vec3((i & 1) == 0 ? lo[0] : hi[0], (i & 2) == 0 ? lo[1] : hi[1], (i & 4) == 0 ? lo[2] : hi[2]);
            corner[i] = robotPiece.applyToPoint(p);
        }
        List<List<Vec3>> edges = new ArrayList<>();
        for (int i = 0; i < 8; i++) {
            for (int bit = 1; bit < 8; bit <<= 1) {
                if ((i & bit) == 0) {
                    edges.add(List.of(corner[i], corner[i | bit]));
                }
            }
        }
        return edges;
    }

    private static void include(double[] lo, double[] hi, Vec3 p, double radiusXy) {
        lo[0] = Math.min(lo[0], p.x() - radiusXy);
        lo[1] = Math.min(lo[1], p.y() - radiusXy);
        lo[2] = Math.min(lo[2], p.z());
        hi[0] = Math.max(hi[0], p.x() + radiusXy);
        hi[1] = Math.max(hi[1], p.y() + radiusXy);
        hi[2] = Math.max(hi[2], p.z());
    }

    /**
     * The table top in its own frame's z = 0: 100 mm around the workpiece's footprint, or
     * 600 x 400 mm about the workpiece origin before anything is computed.
     */
    private static List<Vec3> tableOutline(Transform3 robotTable, List<List<Vec3>> box, Transform3 robotPiece) {
        Transform3 inv = robotTable.inverse();
        double x0;
        double x1;
        double y0;
        double y1;
        if (box.isEmpty()) {
            Vec3 o = inv.applyToPoint(robotPiece.translationPart());
            x0 = o.x() - 300;
            x1 = o.x() + 300;
            y0 = o.y() - 200;
            y1 = o.y() + 200;
        } else {
            x0 = Double.MAX_VALUE;
            y0 = Double.MAX_VALUE;
            x1 = -Double.MAX_VALUE;
            y1 = -Double.MAX_VALUE;
            for (List<Vec3> e : box) {
                for (Vec3 p : e) {
                    Vec3 t = inv.applyToPoint(p);
                    x0 = Math.min(x0, t.x());
                    x1 = Math.max(x1, t.x());
                    y0 = Math.min(y0, t.y());
                    y1 = Math.max(y1, t.y());
                }
            }
            x0 -= 100;
            y0 -= 100;
            x1 += 100;
            y1 += 100;
        }
        List<Vec3> out = new ArrayList<>();
        for (double[] xy : new double[][] {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}}) {
            out.add(robotTable.applyToPoint(new Vec3(xy[0], xy[1], 0)));
        }
        return out;
    }

    /**
     * The largest distance from any point to one of the first 64, or the height span if larger.
     * Squared distances are compared and one root taken (the same value: the root is monotonic):
     * a root per pair was most of the live scene's time for thousands of targets.
     */
    private static double extent(List<Vec3> ps) {
        double lo = Double.MAX_VALUE;
        double hi = -Double.MAX_VALUE;
        int k = Math.min(ps.size(), 64);
        double[] bx = new double[k];
        double[] by = new double[k];
        double[] bz = new double[k];
        for (int i = 0; i < k; i++) {
            bx[i] = ps.get(i).x();
            by[i] = ps.get(i).y();
            bz[i] = ps.get(i).z();
        }
        double m2 = 0;
        for (Vec3 a : ps) {
            double ax = a.x();
            double ay = a.y();
            double az = a.z();
            for (int i = 0; i < k; i++) {
                double dx = ax - bx[i];
                double dy = ay - by[i];
                double dz = az - bz[i];
                m2 = Math.max(m2, dx * dx + dy * dy + dz * dz);
            }
            lo = Math.min(lo, az);
            hi = Math.max(hi, az);
        }
        return Math.max(Math.sqrt(m2), hi - lo);
    }

    /** A square grid under everything, at the lowest height drawn, lines every 100 mm (or more). */
    private static List<List<Vec3>> floor(List<Vec3> ps) {
        double x0 = Double.MAX_VALUE;
        double y0 = Double.MAX_VALUE;
        double z0 = 0;
        double x1 = -Double.MAX_VALUE;
        double y1 = -Double.MAX_VALUE;
        for (Vec3 p : ps) {
            x0 = Math.min(x0, p.x());
            x1 = Math.max(x1, p.x());
            y0 = Math.min(y0, p.y());
            y1 = Math.max(y1, p.y());
            z0 = Math.min(z0, p.z());
        }
        double span = Math.max(x1 - x0, y1 - y0) + 400;
        double step = span > 4000 ? 500 : span > 2000 ? 200 : 100;
        x0 = Math.floor((x0 - 200) / step) * step;
        y0 = Math.floor((y0 - 200) / step) * step;
        x1 = Math.ceil((x1 + 200) / step) * step;
        y1 = Math.ceil((y1 + 200) / step) * step;
        List<List<Vec3>> out = new ArrayList<>();
        for (double x = x0; x <= x1 + 1e-9; x += step) {
            out.add(List.of(new Vec3(x, y0, z0), new Vec3(x, y1, z0)));
        }
        for (double y = y0; y <= y1 + 1e-9; y += step) {
            out.add(List.of(new Vec3(x0, y, z0), new Vec3(x1, y, z0)));
        }
        return out;
    }
}
