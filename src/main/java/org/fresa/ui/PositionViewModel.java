package org.fresa.ui;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.fresa.cell.RobotFiles;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.job.Job;
import org.fresa.job.JobSettings;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.RobotTrajectoryService;
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
        JobSettings.RobotSettings old = job.robot().orElse(JobSettings.RobotSettings.DEFAULTS);
        return job.withRobot(new JobSettings.RobotSettings(
                old.robot(),
                robotTablePlacement(),
                tablePiecePlacement(),
                old.formats(),
                old.spindle(),
                old.toolLengthMm(),
                old.placing()));
    }

    /** The job with this robot -> table placement (the placement search's), all else kept. */
    static Job withRobotTable(Job job, Placement robotTable) {
        JobSettings.RobotSettings old = job.robot()
                .orElse(new JobSettings.RobotSettings(
                        "irb140", Placement.ORIGIN, Placement.ORIGIN, JobSettings.RobotSettings.DEFAULT_FORMATS));
        return job.withRobot(new JobSettings.RobotSettings(
                old.robot(),
                robotTable,
                old.tablePiece(),
                old.formats(),
                old.spindle(),
                old.toolLengthMm(),
                old.placing()));
    }

    /**
     * What {@code fresa robot} does before writing: reads the STEP-NC file, plans its toolpaths,
     * places them in the cell and solves every point. Long: run it in the background.
     */
    static RobotTrajectoryService.Solved compute(
            Path stepnc,
            String robotName,
            Placement robotTable,
            Placement tablePiece,
            List<String> formats,
            ProgressMonitor progress)
            throws CamInputException, java.io.IOException {
        return compute(
                stepnc, robotName, robotTable, tablePiece, formats, org.fresa.cell.RobotTools.Choice.NONE, progress);
    }

    /** As above, with the job's spindle and tool length: each workingstep's TCP as {@code fresa robot} makes it. */
    static RobotTrajectoryService.Solved compute(
            Path stepnc,
            String robotName,
            Placement robotTable,
            Placement tablePiece,
            List<String> formats,
            org.fresa.cell.RobotTools.Choice tool,
            ProgressMonitor progress)
            throws CamInputException, java.io.IOException {
        return compute(
                stepnc,
                robotName,
                robotTable,
                tablePiece,
                formats,
                tool,
                org.fresa.toolpath.PlanningChoices.DEFAULT,
                progress);
    }

    /** As above, with the job's planning choices: the trajectory {@code fresa run} solves. */
    static RobotTrajectoryService.Solved compute(
            Path stepnc,
            String robotName,
            Placement robotTable,
            Placement tablePiece,
            List<String> formats,
            org.fresa.cell.RobotTools.Choice tool,
            org.fresa.toolpath.PlanningChoices choices,
            ProgressMonitor progress)
            throws CamInputException, java.io.IOException {
        Planned planned = plan(stepnc, robotName, tool, choices, progress);
        return RobotTrajectoryService.solve(planned.request(robotTable, tablePiece, formats), progress);
    }

    /**
     * A STEP-NC program planned for a robot with its tools, in the workpiece frame: all that the
     * placements do not change, so that the live reachability reads and plans a file once and then
     * only places its toolpath and solves it.
     *
     * @param spindle the spindle nose in the flange frame (drawn with the tool)
     * @param robots the robot carrying each workingstep's TCP, one instance per TCP
     * @param planning what a run says of the planning (the tool frames' warnings, the planner's problems)
     * @param names each section's name in a placement search (a workingstep's id with its entity)
     */
    record Planned(
            Robot robot,
            org.fresa.model.Toolpath toolpath,
            Map<String, Transform3> tcpByLabel,
            org.fresa.check.Limits checkLimits,
            Transform3 spindle,
            java.util.function.Function<String, Robot> robots,
            org.fresa.job.RobotService.Planning planning,
            List<String> names) {

        /** The request {@code fresa robot} makes of this plan at these placements. */
        RobotTrajectoryService.Request request(Placement robotTable, Placement tablePiece, List<String> formats) {
            return new RobotTrajectoryService.Request(
                    toolpath,
                    robot,
                    robotTable,
                    tablePiece,
                    NcPosts.CHORD_TOLERANCE_MM * 10,
                    formats,
                    TrajectorySolver.Options.DEFAULT,
                    tcpByLabel,
                    checkLimits);
        }
    }

    /**
     * Reads the STEP-NC file, plans its toolpaths with the job's choices and gives each workingstep
     * its TCP. Long: in the background.
     */
    static Planned plan(
            Path stepnc,
            String robotName,
            org.fresa.cell.RobotTools.Choice tool,
            org.fresa.toolpath.PlanningChoices choices,
            ProgressMonitor progress)
            throws CamInputException, java.io.IOException {
        Robot robot = RobotFiles.load(robotName);
        org.fresa.job.ToolpathService.Planned planned =
                org.fresa.job.ToolpathService.compute(stepnc, choices, progress);
        var program = planned.program();
        ToolpathPlanner.Plan plan = planned.plan();
        org.fresa.cell.RobotTools.Frames tools =
                org.fresa.cell.RobotTools.of(robot, tool, program, plan, stepnc.toString());
        org.fresa.check.Limits limits = org.fresa.job.ProgramChecks.stepnc(program, plan, choices);
        RobotTrajectoryService.Request any = new RobotTrajectoryService.Request(
                tools.toolpath(),
                robot,
                Placement.ORIGIN,
                Placement.ORIGIN,
                NcPosts.CHORD_TOLERANCE_MM * 10,
                List.of(),
                TrajectorySolver.Options.DEFAULT,
                tools.tcpByLabel(),
                limits);
        return new Planned(
                robot,
                tools.toolpath(),
                tools.tcpByLabel(),
                limits,
                tools.spindle(),
                any.robotOfLabel(),
                org.fresa.job.RobotService.Planning.of(tools, plan),
                org.fresa.job.AutoPlacement.names(plan));
    }

    /**
     * Which targets of the plan the robot reaches at these placements, one solution each (no
     * relinks): the live view of the Position tab. Empty when {@code stale} says the answer is no
     * longer wanted.
     *
     * @param reach the checker of the thread that runs this (it keeps a solver per tool)
     */
    static Optional<RobotTrajectoryService.Solved> reach(
            Planned planned,
            Placement robotTable,
            Placement tablePiece,
            List<String> formats,
            org.fresa.kin.Reachability reach,
            java.util.function.BooleanSupplier stale) {
        RobotTrajectoryService.Request req = planned.request(robotTable, tablePiece, formats);
        List<org.fresa.kin.ToolTarget> targets = RobotTrajectoryService.targets(
                req.toolpath(), robotTable.toTransform().times(tablePiece.toTransform()), req.chordToleranceMm());
        return reach.check(targets, planned.robots(), stale)
                .map(r -> new RobotTrajectoryService.Solved(req, targets, r));
    }

    void setResult(RobotTrajectoryService.Solved s) {
        solved = Optional.of(s);
        selected = 0;
        live = false;
        spindle = null;
        said = List.of();
    }

    /**
     * What a run of the job says of the computed trajectory ({@code RobotService.said}: the
     * planning's warnings, the unreachable points, the solver's notes), set after {@link #setResult}.
     */
    void setSaid(List<String> s) {
        said = List.copyOf(s);
    }

    /** What the run says of the trajectory shown; none for a live answer, which is no run's. */
    WarningList said() {
        return isLive() ? WarningList.none() : WarningList.of(said);
    }

    /**
     * A live reachability result (one solution per target, no relinks) with its scene at the first
     * point, made off the event thread: shown until the next one or Compute's trajectory.
     */
    void setLive(RobotTrajectoryService.Solved s, CellScene atFirstPoint, Transform3 spindleOfResult) {
        setResult(s, atFirstPoint, spindleOfResult);
        live = true;
    }

    /** As above, with the rows of its error per axis table ({@link #errorRowsOf}), made off the event thread. */
    void setLive(
            RobotTrajectoryService.Solved s, CellScene atFirstPoint, Transform3 spindleOfResult, List<String[]> rows) {
        setLive(s, atFirstPoint, spindleOfResult);
        errorRows = List.copyOf(rows);
        errorRowsResult = s;
    }

    /** A Compute result with its spindle (drawn with the tool). */
    void setResult(RobotTrajectoryService.Solved s, CellScene atFirstPoint, Transform3 spindleOfResult) {
        setResult(s, atFirstPoint);
        spindle = spindleOfResult;
    }

    /** Whether the result shown is the live reachability, not a computed trajectory. */
    boolean isLive() {
        return live && solved.isPresent();
    }

    /**
     * One line on what is out of reach: how many targets of which workingsteps (the most first),
     * or that all are within reach; empty before anything is solved.
     */
    String reachLine() {
        if (solved.isEmpty()) {
            return "";
        }
        List<TrajectoryPoint> pts = solved.get().result().points();
        Map<String, Integer> out = new LinkedHashMap<>();
        int targets = 0;
        for (TrajectoryPoint p : pts) {
            if (p.inserted()) {
                continue;
            }
            targets++;
            if (p.status() == TrajectoryPoint.Status.UNREACHABLE) {
                out.merge(p.label(), 1, Integer::sum);
            }
        }
        String robotName = solved.get().request().robot().name();
        if (out.isEmpty()) {
            return "All " + targets + " targets are within reach of " + robotName + ".";
        }
        int total = out.values().stream().mapToInt(Integer::intValue).sum();
        List<Map.Entry<String, Integer>> worst = new ArrayList<>(out.entrySet());
        worst.sort((a, b) -> b.getValue() - a.getValue());
        StringBuilder sb = new StringBuilder();
        sb.append(total)
                .append(" of ")
                .append(targets)
                .append(" targets out of reach of ")
                .append(robotName)
                .append(", in ")
                .append(out.size())
                .append(out.size() == 1 ? " workingstep: " : " workingsteps: ");
        for (int i = 0; i < Math.min(4, worst.size()); i++) {
            sb.append(i == 0 ? "" : ", ")
                    .append(worst.get(i).getKey())
                    .append(" (")
                    .append(worst.get(i).getValue())
                    .append(')');
        }
        if (worst.size() > 4) {
            sb.append(" and ").append(worst.size() - 4).append(" more");
        }
        return sb.toString();
    }

    private boolean live;
    private Transform3 spindle;
    private List<String> said = List.of();

    /** A result with its scene at the first point, made by {@link #sceneOf} in the background. */
    void setResult(RobotTrajectoryService.Solved s, CellScene atFirstPoint) {
        setResult(s);
        sceneCache = atFirstPoint;
        sceneCacheKey = List.of(s, 0);
    }

    /** Forgets the computed trajectory (another document was opened). */
    void clearResult() {
        solved = Optional.empty();
        said = List.of();
        live = false;
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
            return said.isEmpty()
                    ? List.of("Not computed yet: set the placements and press Compute.")
                    : List.of(
                            "No trajectory: no table placement",
                            "reaches every target (the job's",
                            "placement is searched); fresa run",
                            "says why below.");
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
        if (live) {
            out.add("Live reachability: one solution per target, no relinks (Compute solves the trajectory)");
            out.add("Robot: " + solved.get().request().robot().name());
            out.add("Targets: " + r.points().size());
            out.add("Out of reach: " + r.unreachable());
            out.add(String.format(Locale.ROOT, "ik_ms: %.1f", r.ikNanos() / 1e6));
            return out;
        }
        out.add("Robot: " + solved.get().request().robot().name());
        out.add("Points: " + r.points().size() + " (" + solved.get().targets().size() + " targets)");
        out.add("Unreachable: " + r.unreachable());
        out.add("Relinks: " + r.relinks());
        out.add(String.format(Locale.ROOT, "Max position error: %.3g mm", maxPos));
        out.add(String.format(Locale.ROOT, "Max orientation error: %.3g rad", maxRot));
        out.add(String.format(Locale.ROOT, "ik_ms: %.1f", r.ikNanos() / 1e6));
        if (!said.isEmpty()) {
            out.add("Warnings: " + said.size() + " (listed below, as fresa run says them)");
        }
        return out;
    }

    /** The columns of the error-per-axis table. */
    static final String[] ERROR_COLUMNS = {"Axis", "Mean", "Min", "Max"};

    /**
     * The error per axis of the result shown, target - reached, as summary.json's
     * {@code error_per_axis} and the thesis's Table 5.3: x, y, z (mm), then the orientation about
     * x, y, z (rad); empty before a result or when no point is reached.
     */
    List<String[]> errorRows() {
        if (solved.isEmpty()) {
            return List.of();
        }
        if (errorRowsResult != solved.get()) {
            errorRows = errorRowsOf(solved.get().result());
            errorRowsResult = solved.get();
        }
        return errorRows;
    }

    // the rows of one result, kept: a live answer brings them made off the event thread
    private List<String[]> errorRows = List.of();
    private RobotTrajectoryService.Solved errorRowsResult;

    /** The error per axis rows of a result (any thread): {@link #errorRows()} of a model showing it. */
    static List<String[]> errorRowsOf(TrajectorySolver.Result result) {
        List<String[]> rows = new ArrayList<>();
        for (org.fresa.kin.ErrorStatistics.Axis a :
                org.fresa.kin.ErrorStatistics.of(result).axes()) {
            rows.add(new String[] {
                a.axis() + " (" + a.unit() + ")",
                String.format(Locale.ROOT, "%.3g", a.mean()),
                String.format(Locale.ROOT, "%.3g", a.min()),
                String.format(Locale.ROOT, "%.3g", a.max())
            });
        }
        return rows;
    }

    /** The selected point: label, status and joint values. */
    String selectedText() {
        if (solved.isEmpty() || pointCount() == 0) {
            return "";
        }
        TrajectoryPoint p = solved.get().result().points().get(selected);
        StringBuilder sb = new StringBuilder();
        sb.append("Point ")
                .append(selected + 1)
                .append(" of ")
                .append(pointCount())
                .append(": ")
                .append(p.label())
                .append(", ")
                .append(p.status().csv());
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
            Transform3 piece =
                    problems().isEmpty() ? table.times(tablePiecePlacement().toTransform()) : table;
            return CellScene.of(robot, CellScene.homePose(robot), table, piece, Optional.empty(), List.of(), -1);
        }
        RobotTrajectoryService.Solved s = solved.get();
        // every repaint asks: the scene of a long trajectory is worth keeping until the point changes
        List<Object> key = List.of(s, selected);
        if (sceneCache != null
                && sceneCacheKey.get(0) == s
                && sceneCacheKey.get(1).equals(selected)) {
            return sceneCache;
        }
        sceneCache = solvedScene(s);
        sceneCacheKey = key;
        return sceneCache;
    }

    private CellScene sceneCache;
    private List<Object> sceneCacheKey;

    private CellScene solvedScene(RobotTrajectoryService.Solved s) {
        return sceneOf(s, selected, spindleShown());
    }

    /** The spindle drawn with a result: none for a result set without one. */
    private Optional<Transform3> spindleShown() {
        return Optional.ofNullable(spindle);
    }

    /** The 3D scene of a result at a point, the robot with a bare flange (no tool drawn). */
    static CellScene sceneOf(RobotTrajectoryService.Solved s, int selected) {
        return sceneOf(s, selected, Optional.empty());
    }

    /**
     * The 3D scene of a result at a point (any thread: the tab prepares the first one off the event
     * thread): with a spindle, the robot is drawn to its flange and the spindle and the point's
     * cutter (the tool length of its TCP, the diameter of its STEP-NC tool) on it.
     */
    static CellScene sceneOf(RobotTrajectoryService.Solved s, int selected, Optional<Transform3> spindle) {
        List<TrajectoryPoint> pts = s.result().points();
        double[] q = CellScene.homePose(s.request().robot());
        Robot robot = s.request().robot();
        String label = null;
        for (int i = Math.min(selected, pts.size() - 1); i >= 0; i--) {
            if (pts.get(i).status() != TrajectoryPoint.Status.UNREACHABLE) {
                q = pts.get(i).q();
                label = pts.get(i).label();
                // drawn with the point's tool: the last link runs from the flange to the tool tip
                robot = s.request().robot().withTool(s.request().tcp(label));
                break;
            }
        }
        Transform3 table = s.request().robotTable().toTransform();
        Transform3 piece = table.times(s.request().tablePiece().toTransform());
        if (spindle.isEmpty() || label == null) {
            return CellScene.of(robot, q, table, piece, Optional.of(s.request().toolpath()), pts, selected);
        }
        Robot bare = robot.withTool(Transform3.IDENTITY);
        CellScene scene =
                CellScene.of(bare, q, table, piece, Optional.of(s.request().toolpath()), pts, selected);
        Transform3 flange = bare.forward(q);
        Transform3 tip = robot.forward(q);
        Vec3 nose = flange.times(spindle.get()).translationPart();
        return scene.withTool(
                new CellScene.ToolShape(
                        flange.translationPart(),
                        nose,
                        tip.translationPart(),
                        diameterOf(s.request().toolpath(), label)),
                tip);
    }

    /** The diameter of the tool of a workingstep (its label), 0 when unknown. */
    private static double diameterOf(org.fresa.model.Toolpath toolpath, String label) {
        for (org.fresa.model.ToolpathSection sec : toolpath.sections()) {
            if (sec.label().equals(label)) {
                return sec.toolDiameterMm();
            }
        }
        return 0;
    }

    /**
     * What the 3D view fits its camera to: it refits when this changes (a new result, other
     * placements or robot), not while the replay moves the robot.
     */
    Object fitKey() {
        if (live && solved.isPresent()) {
            // the live answers follow the fields as they are typed: the view stays where the planner put it
            return List.of("live", System.identityHashCode(robot()));
        }
        return List.of(
                solved.map(System::identityHashCode).orElse(0),
                String.join(",", robotTable),
                String.join(",", tablePiece),
                System.identityHashCode(robot()));
    }

    /** Points of the toolpath in the robot base frame, with their status. */
    record CellPoint(Vec3 at, TrajectoryPoint.Status status) {}

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
                .orElseGet(() -> problems().isEmpty()
                        ? robotTablePlacement().toTransform().translationPart()
                        : Vec3.ZERO);
    }

    /** The workpiece origin in the robot base frame. */
    Vec3 pieceOrigin() {
        return solved.map(s -> s.request()
                        .robotTable()
                        .toTransform()
                        .times(s.request().tablePiece().toTransform())
                        .translationPart())
                .orElse(tableOrigin());
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
        Robot robot =
                solved.get().request().robot().withTool(solved.get().request().tcp(p.label()));
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
