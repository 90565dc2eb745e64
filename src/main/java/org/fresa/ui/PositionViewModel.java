package org.fresa.ui;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.job.Job;
import org.fresa.job.JobSettings;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.RobotFiles;
import org.fresa.job.RobotTrajectoryService;
import org.fresa.job.StepNcService;
import org.fresa.kin.Robot;
import org.fresa.kin.SerialRobot;
import org.fresa.kin.TrajectoryPoint;
import org.fresa.kin.TrajectorySolver;
import org.fresa.kin.TriceptRobot;
import org.fresa.model.CamInputException;
import org.fresa.model.Placement;
import org.fresa.post.NcPosts;
import org.fresa.toolpath.ToolpathPlanner;

/**
 * The Position tab's state without Swing: the robot -> table placement (X, Y, Z mm, RZ deg) and
 * the table -> workpiece placement (X, Y, Z mm, RX, RY, RZ deg) as typed text with a message per
 * bad field, and the last computed trajectory with a replay index. Everything is in the robot
 * base frame (mm).
 */
final class PositionViewModel {

    static final String[] ROBOT_TABLE = {"X", "Y", "Z", "RZ"};
    static final String[] TABLE_PIECE = {"X", "Y", "Z", "RX", "RY", "RZ"};

    private final String[] robotTable = {"0", "0", "0", "0"};
    private final String[] tablePiece = {"0", "0", "0", "0", "0", "0"};
    private Optional<RobotTrajectoryService.Solved> solved = Optional.empty();
    private int selected;
    private Robot robot = org.fresa.kin.Robots.irb140();

    /** The robot drawn before a trajectory is computed (the job's robot). */
    void setRobot(Robot r) {
        robot = java.util.Objects.requireNonNull(r, "robot");
    }

    /** The robot drawn: the computed trajectory's, else the job's. */
    Robot robot() {
        return solved.map(s -> s.request().robot()).orElse(robot);
    }

    String robotTable(int i) {
        return robotTable[i];
    }

    String tablePiece(int i) {
        return tablePiece[i];
    }

    void setRobotTable(int i, String text) {
        robotTable[i] = text.trim();
    }

    void setTablePiece(int i, String text) {
        tablePiece[i] = text.trim();
    }

    /** Shows the placements a job holds. */
    void load(JobSettings.RobotSettings r) {
        Placement a = r.robotTable();
        Placement b = r.tablePiece();
        double[] av = {a.xMm(), a.yMm(), a.zMm(), a.rzDeg()};
        double[] bv = {b.xMm(), b.yMm(), b.zMm(), b.rxDeg(), b.ryDeg(), b.rzDeg()};
        for (int i = 0; i < av.length; i++) {
            robotTable[i] = RobotViewModel.num(av[i]);
        }
        for (int i = 0; i < bv.length; i++) {
            tablePiece[i] = RobotViewModel.num(bv[i]);
        }
    }

    /** Field key ("robot-table.X", "table-piece.RY") -> what is wrong with it; empty when all is well. */
    Map<String, String> problems() {
        Map<String, String> out = new LinkedHashMap<>();
        check("robot-table", ROBOT_TABLE, robotTable, out);
        check("table-piece", TABLE_PIECE, tablePiece, out);
        return out;
    }

    private static void check(String prefix, String[] names, String[] values, Map<String, String> out) {
        for (int i = 0; i < names.length; i++) {
            String v = values[i];
            String key = prefix + "." + names[i];
            if (v.isEmpty()) {
                out.put(key, names[i] + " is empty: type a number (" + (names[i].startsWith("R") ? "deg" : "mm") + ")");
                continue;
            }
            try {
                double d = Double.parseDouble(v);
                if (!Double.isFinite(d)) {
                    out.put(key, names[i] + " must be a finite number");
                } else if (names[i].startsWith("R") && Math.abs(d) > 360) {
                    out.put(key, names[i] + " must lie within -360..360 deg");
                } else if (!names[i].startsWith("R") && Math.abs(d) > 100_000) {
                    out.put(key, names[i] + " is more than 100 m away");
                }
            } catch (NumberFormatException e) {
                out.put(key, names[i] + ": '" + v + "' is not a number");
            }
        }
    }

    /** The robot -> table placement; call only when {@link #problems()} is empty. */
    Placement robotTablePlacement() {
        double[] v = parse(robotTable);
        return new Placement(v[0], v[1], v[2], 0, 0, v[3]);
    }

    Placement tablePiecePlacement() {
        double[] v = parse(tablePiece);
        return new Placement(v[0], v[1], v[2], v[3], v[4], v[5]);
    }

    private static double[] parse(String[] s) {
        double[] v = new double[s.length];
        for (int i = 0; i < s.length; i++) {
            v[i] = Double.parseDouble(s[i]);
        }
        return v;
    }

    /** The job with these placements (robot and formats kept, irb140 when it had none). */
    Job applyTo(Job job) {
        JobSettings.RobotSettings old = job.robot().orElse(new JobSettings.RobotSettings("irb140", Placement.ORIGIN,
                Placement.ORIGIN, JobSettings.RobotSettings.DEFAULT_FORMATS));
        return job.withRobot(new JobSettings.RobotSettings(old.robot(), robotTablePlacement(), tablePiecePlacement(),
                old.formats(), old.spindle(), old.toolLengthMm()));
    }

    /**
     * What {@code fresa robot} does before writing: reads the STEP-NC file, plans its toolpaths,
     * places them in the cell and solves every point. Long: run it in the background.
     */
    static RobotTrajectoryService.Solved compute(Path stepnc, String robotName, Placement robotTable,
            Placement tablePiece, List<String> formats, ProgressMonitor progress) throws CamInputException,
            java.io.IOException {
        return compute(stepnc, robotName, robotTable, tablePiece, formats, org.fresa.job.RobotTools.Choice.NONE,
                progress);
    }

    /** As above, with the job's spindle and tool length: each workingstep's TCP as {@code fresa robot} makes it. */
    static RobotTrajectoryService.Solved compute(Path stepnc, String robotName, Placement robotTable,
            Placement tablePiece, List<String> formats, org.fresa.job.RobotTools.Choice tool, ProgressMonitor progress)
            throws CamInputException, java.io.IOException {
        return compute(stepnc, robotName, robotTable, tablePiece, formats, tool,
                org.fresa.toolpath.PlanningChoices.DEFAULT, progress);
    }

    /** As above, with the job's planning choices: the trajectory {@code fresa run} solves. */
    static RobotTrajectoryService.Solved compute(Path stepnc, String robotName, Placement robotTable,
            Placement tablePiece, List<String> formats, org.fresa.job.RobotTools.Choice tool,
            org.fresa.toolpath.PlanningChoices choices, ProgressMonitor progress)
            throws CamInputException, java.io.IOException {
        return org.fresa.job.RobotService.compute(new org.fresa.job.RobotService.Settings(stepnc, robotName,
                robotTable, tablePiece, formats, choices, tool), progress);
    }

    void setResult(RobotTrajectoryService.Solved s) {
        solved = Optional.of(s);
        selected = 0;
    }

    /** A result with its scene at the first point, made by {@link #sceneOf} in the background. */
    void setResult(RobotTrajectoryService.Solved s, CellScene atFirstPoint) {
        setResult(s);
        sceneCache = atFirstPoint;
        sceneCacheKey = List.of(s, 0);
    }

    /** Forgets the computed trajectory (another document was opened). */
    void clearResult() {
        solved = Optional.empty();
        selected = 0;
        sceneCache = null;
        sceneCacheKey = null;
    }

    Optional<RobotTrajectoryService.Solved> result() {
        return solved;
    }

    int pointCount() {
        return solved.map(s -> s.result().points().size()).orElse(0);
    }

    int selected() {
        return selected;
    }

    void select(int i) {
        selected = Math.max(0, Math.min(i, pointCount() - 1));
    }

    /** The summary figures, one line each (as in summary.json). */
    List<String> summary() {
        if (solved.isEmpty()) {
            return List.of("Not computed yet: set the placements and press Compute.");
        }
        TrajectorySolver.Result r = solved.get().result();
        double maxPos = 0;
        double maxRot = 0;
        for (TrajectoryPoint p : r.points()) {
            if (p.status() != TrajectoryPoint.Status.UNREACHABLE) {
                maxPos = Math.max(maxPos, p.posErrMm());
                maxRot = Math.max(maxRot, p.rotErrRad());
            }
        }
        List<String> out = new ArrayList<>();
        out.add("Robot: " + solved.get().request().robot().name());
        out.add("Points: " + r.points().size() + " (" + solved.get().targets().size() + " targets)");
        out.add("Unreachable: " + r.unreachable());
        out.add("Relinks: " + r.relinks());
        out.add(String.format(Locale.ROOT, "Max position error: %.3g mm", maxPos));
        out.add(String.format(Locale.ROOT, "Max orientation error: %.3g rad", maxRot));
        out.add(String.format(Locale.ROOT, "ik_ms: %.1f", r.ikNanos() / 1e6));
        return out;
    }

    /** The selected point: label, status and joint values. */
    String selectedText() {
        if (solved.isEmpty() || pointCount() == 0) {
            return "";
        }
        TrajectoryPoint p = solved.get().result().points().get(selected);
        StringBuilder sb = new StringBuilder();
        sb.append("Point ").append(selected + 1).append(" of ").append(pointCount()).append(": ").append(p.label())
                .append(", ").append(p.status().csv());
        double[] q = p.q();
        if (p.status() != TrajectoryPoint.Status.UNREACHABLE) {
            sb.append(", q =");
            for (double v : q) {
                sb.append(String.format(Locale.ROOT, " %.3f", v));
            }
        }
        return sb.toString();
    }

    /**
     * What the 3D view draws: the robot at the replayed point (at the last reachable point before
     * it when that one is unreachable; in its home pose before anything is computed), the table,
     * workpiece and toolpath, and the frames.
     */
    CellScene scene() {
        if (solved.isEmpty()) {
            Transform3 table = problems().isEmpty() ? robotTablePlacement().toTransform() : Transform3.IDENTITY;
            Transform3 piece = problems().isEmpty() ? table.times(tablePiecePlacement().toTransform()) : table;
            return CellScene.of(robot, CellScene.homePose(robot), table, piece, Optional.empty(), List.of(), -1);
        }
        RobotTrajectoryService.Solved s = solved.get();
        // every repaint asks: the scene of a long trajectory is worth keeping until the point changes
        List<Object> key = List.of(s, selected);
        if (sceneCache != null && sceneCacheKey.get(0) == s && sceneCacheKey.get(1).equals(selected)) {
            return sceneCache;
        }
        sceneCache = solvedScene(s);
        sceneCacheKey = key;
        return sceneCache;
    }

    private CellScene sceneCache;
    private List<Object> sceneCacheKey;

    private CellScene solvedScene(RobotTrajectoryService.Solved s) {
        return sceneOf(s, selected);
    }

    /** The 3D scene of a result at a point (any thread: the tab prepares the first one off the event thread). */
    static CellScene sceneOf(RobotTrajectoryService.Solved s, int selected) {
        List<TrajectoryPoint> pts = s.result().points();
        double[] q = CellScene.homePose(s.request().robot());
        Robot robot = s.request().robot();
        for (int i = Math.min(selected, pts.size() - 1); i >= 0; i--) {
            if (pts.get(i).status() != TrajectoryPoint.Status.UNREACHABLE) {
                q = pts.get(i).q();
                // drawn with the point's tool: the last link runs from the flange to the tool tip
                robot = s.request().robot().withTool(s.request().tcp(pts.get(i).label()));
                break;
            }
        }
        Transform3 table = s.request().robotTable().toTransform();
        Transform3 piece = table.times(s.request().tablePiece().toTransform());
        return CellScene.of(robot, q, table, piece, Optional.of(s.request().toolpath()), pts, selected);
    }

    /**
     * What the 3D view fits its camera to: it refits when this changes (a new result, other
     * placements or robot), not while the replay moves the robot.
     */
    Object fitKey() {
        return List.of(solved.map(System::identityHashCode).orElse(0), String.join(",", robotTable),
                String.join(",", tablePiece), System.identityHashCode(robot()));
    }

    /** Points of the toolpath in the robot base frame, with their status. */
    record CellPoint(Vec3 at, TrajectoryPoint.Status status) {
    }

    List<CellPoint> cellPoints() {
        List<CellPoint> out = new ArrayList<>();
        solved.ifPresent(s -> {
            for (TrajectoryPoint p : s.result().points()) {
                out.add(new CellPoint(p.target().translationPart(), p.status()));
            }
        });
        return out;
    }

    /** The table origin in the robot base frame. */
    Vec3 tableOrigin() {
        return solved.map(s -> s.request().robotTable().toTransform().translationPart())
                .orElseGet(() -> problems().isEmpty() ? robotTablePlacement().toTransform().translationPart()
                        : Vec3.ZERO);
    }

    /** The workpiece origin in the robot base frame. */
    Vec3 pieceOrigin() {
        return solved.map(s -> s.request().robotTable().toTransform().times(s.request().tablePiece().toTransform())
                .translationPart()).orElse(tableOrigin());
    }

    /**
     * The robot at the selected point as polylines (mm, robot base frame): for a serial robot the
     * DH frame origins from the base to the tool tip; for the Tricept each leg and the wrist to
     * the tip. Empty when the point is unreachable or nothing is computed.
     */
    List<List<Vec3>> robotLinks() {
        if (solved.isEmpty() || pointCount() == 0) {
            return List.of();
        }
        TrajectoryPoint p = solved.get().result().points().get(selected);
        if (p.status() == TrajectoryPoint.Status.UNREACHABLE) {
            return List.of();
        }
        double[] q = p.q();
        Robot robot = solved.get().request().robot().withTool(solved.get().request().tcp(p.label()));
        List<List<Vec3>> out = new ArrayList<>();
        if (robot instanceof SerialRobot s) {
            List<Vec3> arm = new ArrayList<>();
            arm.add(Vec3.ZERO);
            for (int i = 0; i <= s.chain().dof(); i++) {
                arm.add(s.chain().frame(i, q).translationPart());
            }
            arm.add(s.forward(q).translationPart());
            out.add(arm);
        } else if (robot instanceof TriceptRobot t) {
            Vec3 w = t.wristCentre(q[0], q[1], q[2]);
            Transform3 tip = t.forward(q);
            for (int k = 0; k < 3; k++) {
                out.add(List.of(t.legBase(k), w));
            }
            out.add(List.of(Vec3.ZERO, w, tip.translationPart()));
        }
        return out;
    }
}
