package org.fresa.job;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import org.fresa.chart.ChartFiles;
import org.fresa.chart.RobotCharts;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.io.Json;
import org.fresa.io.OutputFolder;
import org.fresa.kin.ErrorStatistics;
import org.fresa.kin.JointLimit;
import org.fresa.kin.JointType;
import org.fresa.kin.Orientation;
import org.fresa.kin.Robot;
import org.fresa.kin.ToolTarget;
import org.fresa.kin.TrajectoryPoint;
import org.fresa.kin.TrajectorySolver;
import org.fresa.model.ArcGeometry;
import org.fresa.model.ExactDecimal;
import org.fresa.model.Move;
import org.fresa.model.Placement;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.fresa.post.RobotProgram;
import org.fresa.robot.RobotPrograms;

/**
 * A toolpath in the workpiece frame turned into a robot joint trajectory:
 * {@code trajectory.csv}, {@code summary.json}, {@code joints.png} and {@code error.png}.
 *
 * <p>A point p of the workpiece frame is p_R = T_robot_table * T_table_piece * p in the robot
 * base frame (spec/cli.md). The robot's tool axis z_e points from the flange into the material,
 * so it is minus the toolpath's axis (tip towards spindle). Arcs are sampled at the chord
 * tolerance; each sample is a trajectory point.
 */
public final class RobotTrajectoryService {

    private RobotTrajectoryService() {}

    /**
     * What to run.
     *
     * @param toolpath in the workpiece frame
     * @param robot the robot
     * @param robotTable table origin in the robot base frame
     * @param tablePiece workpiece origin in the table frame
     * @param chordToleranceMm largest distance of an arc from its sampled chords, > 0
     * @param formats output formats; csv and png are handled here
     * @param options trajectory options (IK method, continuity, free rotation)
     * @param tcpByLabel the tool frame (TCP) in the flange frame of each workingstep (its label);
     *     a workingstep not in it (or an empty map) uses the robot's own tool frame
     */
    public record Request(
            Toolpath toolpath,
            Robot robot,
            Placement robotTable,
            Placement tablePiece,
            double chordToleranceMm,
            List<String> formats,
            TrajectorySolver.Options options,
            Map<String, Transform3> tcpByLabel,
            org.fresa.check.Limits checkLimits) {
        public Request {
            Objects.requireNonNull(checkLimits, "checkLimits");
            Objects.requireNonNull(toolpath, "toolpath");
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(robotTable, "robotTable");
            Objects.requireNonNull(tablePiece, "tablePiece");
            Objects.requireNonNull(options, "options");
            formats = List.copyOf(formats);
            tcpByLabel = Map.copyOf(tcpByLabel);
            if (!(chordToleranceMm > 0)) {
                throw new IllegalArgumentException("chord tolerance must be > 0: " + chordToleranceMm);
            }
        }

        /**
         * Without the part's limits: every tool a milling cutter that does not cut at its centre
         * and no stock known, the strictest reading of the program check.
         */
        public Request(
                Toolpath toolpath,
                Robot robot,
                Placement robotTable,
                Placement tablePiece,
                double chordToleranceMm,
                List<String> formats,
                TrajectorySolver.Options options,
                Map<String, Transform3> tcpByLabel) {
            this(
                    toolpath,
                    robot,
                    robotTable,
                    tablePiece,
                    chordToleranceMm,
                    formats,
                    options,
                    tcpByLabel,
                    org.fresa.check.Limits.milling());
        }

        /** Every workingstep with the robot's own tool frame. */
        public Request(
                Toolpath toolpath,
                Robot robot,
                Placement robotTable,
                Placement tablePiece,
                double chordToleranceMm,
                List<String> formats,
                TrajectorySolver.Options options) {
            this(toolpath, robot, robotTable, tablePiece, chordToleranceMm, formats, options, Map.of());
        }

        /** The TCP of a workingstep in the flange frame. */
        public Transform3 tcp(String label) {
            return tcpByLabel.getOrDefault(label, robot.tool());
        }

        /** The robot carrying each workingstep's TCP, one instance per distinct TCP. */
        public java.util.function.Function<String, Robot> robotOfLabel() {
            Map<Transform3, Robot> byTcp = new java.util.HashMap<>();
            byTcp.put(robot.tool(), robot);
            return label -> byTcp.computeIfAbsent(tcp(label), robot::withTool);
        }

        public Request(Toolpath toolpath, Robot robot, Placement robotTable, Placement tablePiece) {
            this(
                    toolpath,
                    robot,
                    robotTable,
                    tablePiece,
                    0.01,
                    List.of("csv", "png"),
                    TrajectorySolver.Options.DEFAULT);
        }
    }

    /** A solved trajectory with what it was solved for. */
    public record Solved(Request request, List<ToolTarget> targets, TrajectorySolver.Result result) {}

    /** Solves and writes the files; exit status 1 (with the reason) when points are unreachable. */
    public static TaskOutcome run(Request req, OutputFolder out, ProgressMonitor progress) throws IOException {
        Solved solved = solve(req, progress);
        // the inverse kinematics is done; the charts and programs take a while yet
        progress.progress(-1, "writing the files");
        return write(solved, "program", out);
    }

    /** Places the toolpath in the cell and solves the inverse kinematics of every point. */
    public static Solved solve(Request req, ProgressMonitor progress) {
        Transform3 robotToPiece =
                req.robotTable().toTransform().times(req.tablePiece().toTransform());
        List<ToolTarget> targets = targets(req.toolpath(), robotToPiece, req.chordToleranceMm());
        progress.progress(0, "inverse kinematics");
        java.util.function.Function<String, Robot> robots = req.tcpByLabel().isEmpty() ? null : req.robotOfLabel();
        TrajectorySolver.Result r = new TrajectorySolver(req.robot(), req.options())
                .solve(targets, robots, (done, total) -> {
                    progress.checkCancelled();
                    if ((done & 255) == 0 || done == total) {
                        progress.progress((double) done / total, "inverse kinematics");
                    }
                });
        return new Solved(req, targets, r);
    }

    /**
     * The program check of a robot program: its toolpath and motions ({@link ProgramChecks#robot}),
     * then its joint motions against the stock ({@link ProgramChecks#jointMotions}).
     */
    public static java.util.Optional<org.fresa.check.Failure> check(
            Solved solved, RobotProgram program, org.fresa.check.Limits limits) {
        Request req = solved.request();
        java.util.Optional<org.fresa.check.Failure> f = ProgramChecks.robot(program, req.toolpath(), limits);
        if (f.isPresent()) {
            return f;
        }
        Map<String, Integer> tools = new java.util.HashMap<>();
        for (ToolpathSection s : req.toolpath().sections()) {
            tools.putIfAbsent(s.label(), s.toolNumber());
        }
        java.util.Map<Transform3, Robot> byTcp = new java.util.HashMap<>();
        return ProgramChecks.jointMotions(
                program,
                label -> byTcp.computeIfAbsent(req.tcp(label), t -> req.robot().withTool(t)),
                req.robotTable().toTransform().times(req.tablePiece().toTransform()),
                limits,
                tools);
    }

    /**
     * The robot program of a solved trajectory, as every writer and the program check take it:
     * each workingstep's tool frame (TCP), the dwells after their targets.
     */
    public static RobotProgram program(Solved solved, String programName) {
        Request req = solved.request();
        return RobotPrograms.of(
                programName, req.robot(), req.toolpath(), solved.result().points(), req::tcp, dwellsAfterTargets(req));
    }

    /**
     * Writes the formats the request names: trajectory.csv (csv), joints.png and error.png (png),
     * program.xml (xml), program.mod (rapid), program.src (krl), and always summary.json.
     *
     * @param programName the name robot programs carry
     */
    public static TaskOutcome write(Solved solved, String programName, OutputFolder out) throws IOException {
        return write(solved, programName, out, solved.request().checkLimits());
    }

    /**
     * Writes the formats as {@link #write(Solved, String, OutputFolder)} does, the robot programs
     * only when they pass the program check against the limits (each tool by its number, as the
     * toolpath's sections have them; with the plain milling limits every tool is a cutter not
     * cutting at its centre).
     */
    public static TaskOutcome write(Solved solved, String programName, OutputFolder out, org.fresa.check.Limits limits)
            throws IOException {
        return write(solved, programName, out, limits, Map.of());
    }

    /** As above, with more entries for summary.json (the placement search's). */
    public static TaskOutcome write(
            Solved solved,
            String programName,
            OutputFolder out,
            org.fresa.check.Limits limits,
            Map<String, Object> moreSummary)
            throws IOException {
        Request req = solved.request();
        TrajectorySolver.Result r = solved.result();
        out.create();
        List<String> fmts = req.formats();
        // the charts first: joints.png is the longest of these files, and the writers may run in
        // parallel (OutputFolder.beginParallel), so the longest starts first
        if (fmts.contains("png")) {
            writeCharts(req.robot(), r, out);
        }
        if (fmts.contains("csv")) {
            out.write("trajectory.csv", os -> os.write(trajectoryCsv(req, r).getBytes(StandardCharsets.UTF_8)));
        }
        RobotProgram program = program(solved, programName);
        java.util.Optional<org.fresa.check.Failure> refused = check(solved, program, limits);
        if (refused.isEmpty()) {
            RobotPrograms.write(program, req.robot(), fmts, out);
        }
        Map<String, Object> summary = summary(req.robot(), solved.targets().size(), r);
        refused.ifPresent(f -> summary.put("program_refused", f.message()));
        summary.putAll(moreSummary);
        out.writeString("summary.json", Json.writePretty(summary));
        boolean programsRefused = refused.isPresent() && fmts.stream().anyMatch(RobotPrograms.FORMATS::contains);
        int exit = programsRefused || r.unreachable() > 0 ? 1 : 0;
        return new TaskOutcome(exit, problems(solved, refused), summary, out.written());
    }

    /**
     * What a run says of a solved trajectory, in its words and order: the points unreachable in
     * this placement, the solver's notes (each relink, each joint limit or singularity it met),
     * then the program check's refusal of the robot programs the request's formats name.
     *
     * @param refused the program check's first failure ({@link #check}), or empty when it passes
     *     or was not made
     */
    public static List<String> problems(Solved solved, java.util.Optional<org.fresa.check.Failure> refused) {
        Request req = solved.request();
        TrajectorySolver.Result r = solved.result();
        List<String> fmts = req.formats();
        List<String> problems = new ArrayList<>();
        if (r.unreachable() > 0) {
            problems.add(r.unreachable() + " of " + r.points().size() + " points are unreachable for "
                    + req.robot().name() + " in this placement (status unreachable in trajectory.csv)");
        }
        problems.addAll(r.notes());
        if (refused.isPresent() && fmts.stream().anyMatch(RobotPrograms.FORMATS::contains)) {
            problems.add("robot programs ("
                    + String.join(
                            ", ",
                            fmts.stream()
                                    .filter(RobotPrograms.FORMATS::contains)
                                    .toList()) + ") not written: the program fails the program check at "
                    + refused.get().message());
        }
        return problems;
    }

    /** The toolpath as robot targets: positions in the robot base frame, z_e into the material. */
    public static List<ToolTarget> targets(Toolpath path, Transform3 robotToPiece, double chordToleranceMm) {
        List<ToolTarget> out = new ArrayList<>();
        walk(path, robotToPiece, chordToleranceMm, out, new ArrayList<>());
        return out;
    }

    /**
     * For each target of {@link #targets} of the request, the time the tool waits there once it
     * has arrived (s): the dwells of the toolpath that follow it (a drilling's dwell at the bottom).
     */
    public static List<Double> dwellsAfterTargets(Request req) {
        Transform3 robotToPiece =
                req.robotTable().toTransform().times(req.tablePiece().toTransform());
        List<Double> dwells = new ArrayList<>();
        walk(req.toolpath(), robotToPiece, req.chordToleranceMm(), new ArrayList<>(), dwells);
        return dwells;
    }

    private static void walk(
            Toolpath path,
            Transform3 robotToPiece,
            double chordToleranceMm,
            List<ToolTarget> out,
            List<Double> dwells) {
        for (ToolpathSection s : path.sections()) {
            Vec3 axis = robotToPiece.applyToDirection(s.toolAxis()).negated().normalized();
            Vec3 x = ToolTarget.naturalX(axis);
            Vec3 at = s.start();
            // the start is a point of its own unless the previous section ended there with this axis
            ToolTarget last = out.isEmpty() ? null : out.get(out.size() - 1);
            if (last == null
                    || !last.positionMm().eq(robotToPiece.applyToPoint(at), org.fresa.geom.Tolerance.DEFAULT)
                    || last.toolAxis().distance(axis) > 1e-12) {
                out.add(new ToolTarget(s.label(), robotToPiece.applyToPoint(at), axis, x));
                dwells.add(0.0);
            }
            for (Move m : s.moves()) {
                if (m instanceof Move.Circular c) {
                    for (Vec3 p : ArcGeometry.of(at, c).points(chordToleranceMm)) {
                        out.add(new ToolTarget(s.label(), robotToPiece.applyToPoint(p), axis, x));
                        dwells.add(0.0);
                    }
                } else if (m.travels()) {
                    out.add(new ToolTarget(s.label(), robotToPiece.applyToPoint(m.end()), axis, x));
                    dwells.add(0.0);
                } else if (m instanceof Move.Dwell d && !dwells.isEmpty()) {
                    // the wait belongs to the point where the tool is: the robot program says it there
                    dwells.set(dwells.size() - 1, dwells.get(dwells.size() - 1) + d.seconds());
                }
                // a dwell or spindle event holds the pose: no point, as a repeated one would be a
                // zero-length linear motion in the robot program
                at = m.end();
            }
        }
    }

    static String trajectoryCsv(Robot robot, TrajectorySolver.Result r) {
        return trajectoryCsv(robot, r, label -> robot.tool());
    }

    static String trajectoryCsv(Request req, TrajectorySolver.Result r) {
        return trajectoryCsv(req.robot(), r, req::tcp);
    }

    /**
     * The rows of trajectory.csv, with the flange position (the reached pose without the TCP of
     * the row's workingstep) after the spec's columns.
     */
    static String trajectoryCsv(
            Robot robot, TrajectorySolver.Result r, java.util.function.Function<String, Transform3> tcpOfLabel) {
        int n = robot.dof();
        StringBuilder sb = new StringBuilder(r.points().size() * 200);
        sb.append("index,workingstep,x,y,z,roll,pitch,yaw");
        for (int i = 1; i <= n; i++) {
            sb.append(",q").append(i);
        }
        sb.append(",reached_x,reached_y,reached_z,pos_err_mm,rot_err_rad,status,flange_x,flange_y,flange_z\n");
        int index = 1;
        for (TrajectoryPoint p : r.points()) {
            Transform3 t = p.target();
            double[] rpy = Orientation.rollPitchYawDeg(t);
            sb.append(index++).append(',').append(csvText(p.label()));
            appendNumbers(sb, t.tx(), t.ty(), t.tz(), rpy[0], rpy[1], rpy[2]);
            if (p.status() == TrajectoryPoint.Status.UNREACHABLE) {
                sb.append(",".repeat(n + 5));
            } else {
                appendNumbers(sb, p.q());
                Transform3 reached = p.reached().orElseThrow();
                appendNumbers(sb, reached.tx(), reached.ty(), reached.tz(), p.posErrMm(), p.rotErrRad());
            }
            sb.append(',').append(p.status().csv());
            if (p.status() == TrajectoryPoint.Status.UNREACHABLE) {
                sb.append(",,,");
            } else {
                Transform3 flange = p.reached()
                        .orElseThrow()
                        .times(tcpOfLabel.apply(p.label()).inverse());
                appendNumbers(sb, flange.tx(), flange.ty(), flange.tz());
            }
            sb.append('\n');
        }
        return sb.toString();
    }

    private static void appendNumbers(StringBuilder sb, double... v) {
        for (double d : v) {
            ExactDecimal.append(sb.append(','), d);
        }
    }

    private static String csvText(String s) {
        if (s.indexOf(',') < 0 && s.indexOf('"') < 0 && s.indexOf('\n') < 0) {
            return s;
        }
        return '"' + s.replace("\"", "\"\"") + '"';
    }

    static Map<String, Object> summary(Robot robot, int targets, TrajectorySolver.Result r) {
        double maxPos = 0;
        double maxRot = 0;
        double maxStep = 0;
        double[] prevOk = null;
        ErrorStatistics stats = new ErrorStatistics();
        for (TrajectoryPoint p : r.points()) {
            if (p.status() == TrajectoryPoint.Status.UNREACHABLE) {
                prevOk = null;
                continue;
            }
            stats.add(p.target(), p.reached().orElseThrow());
            maxPos = Math.max(maxPos, p.posErrMm());
            maxRot = Math.max(maxRot, p.rotErrRad());
            if (p.status() == TrajectoryPoint.Status.OK) {
                double[] q = p.q();
                if (prevOk != null) {
                    for (int i = 0; i < q.length; i++) {
                        if (robot.joints().get(i).type() == JointType.REVOLUTE) {
                            maxStep = Math.max(maxStep, Math.abs(q[i] - prevOk[i]));
                        }
                    }
                }
                prevOk = q;
            } else {
                prevOk = null; // relink points separate the configurations
            }
        }
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("robot", robot.name());
        m.put("targets", targets);
        m.put("points", r.points().size());
        m.put("unreachable", r.unreachable());
        m.put("relinks", r.relinks());
        m.put("subdivided_moves", r.subdividedMoves());
        m.put("max_pos_err_mm", maxPos);
        m.put("max_rot_err_rad", maxRot);
        m.put("max_joint_step_deg", maxStep);
        m.putAll(stats.summary());
        m.put("ik_ms", r.ikNanos() / 1e6);
        Map<String, Object> free = new LinkedHashMap<>();
        free.put("rotated_points", r.rotatedPoints());
        free.put("changes", r.rotationChanges());
        free.put("max_abs_deg", r.maxFreeRotationDeg());
        free.put(
                "what",
                r.rotatedPoints() == 0
                        ? "the tool kept its preferred x direction at every point"
                        : String.format(
                                Locale.ROOT,
                                "the tool was turned about its axis (up to %.0f deg) at %d points, in %d"
                                        + " steps, to stay clear of joint limits and the wrist singularity or to avoid a"
                                        + " reconfiguration",
                                r.maxFreeRotationDeg(),
                                r.rotatedPoints(),
                                r.rotationChanges()));
        m.put("free_rotation", free);
        m.put("notes", r.notes());
        return m;
    }

    private static void writeCharts(Robot robot, TrajectorySolver.Result r, OutputFolder out) throws IOException {
        int n = robot.dof();
        List<RobotCharts.JointSeries> series = jointSeries(robot, r);
        double[][] err = positionErrorsMm(r);
        out.write(
                "joints.png",
                o -> ChartFiles.writePng(
                        RobotCharts.joints("Joint values, " + robot.name(), series), 1000, 160 * n + 80, o));
        // each curve's legend with its mean, least and largest error, the orientation's under the
        // title: the figures of the thesis's Table 5.3
        ErrorStatistics stats = ErrorStatistics.of(r);
        out.write(
                "error.png",
                o -> ChartFiles.writePng(
                        RobotCharts.positionErrors(
                                "Position error per axis, " + robot.name(),
                                err,
                                List.of(stats.positionLegend(0), stats.positionLegend(1), stats.positionLegend(2)),
                                stats.orientationLine()),
                        1000,
                        500,
                        o));
    }

    /** Each joint's values along the trajectory with its limits (NaN at unreachable points), for joints.png. */
    public static List<RobotCharts.JointSeries> jointSeries(Robot robot, TrajectorySolver.Result r) {
        List<JointLimit> limits = robot.joints();
        int n = limits.size();
        int count = r.points().size();
        double[][] values = new double[n][count];
        for (int k = 0; k < count; k++) {
            double[] q = r.points().get(k).q();
            for (int i = 0; i < n; i++) {
                values[i][k] = q.length == n ? q[i] : Double.NaN;
            }
        }
        List<RobotCharts.JointSeries> series = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            JointLimit l = limits.get(i);
            series.add(new RobotCharts.JointSeries(l.name(), l.type().unit(), l.min(), l.max(), values[i]));
        }
        return series;
    }

    /** Per point target - reached {x, y, z} (mm; NaN at unreachable points), for error.png. */
    public static double[][] positionErrorsMm(TrajectorySolver.Result r) {
        int count = r.points().size();
        double[][] err = new double[count][3];
        for (int k = 0; k < count; k++) {
            TrajectoryPoint p = r.points().get(k);
            if (p.reached().isPresent()) {
                Transform3 t = p.target();
                Transform3 re = p.reached().get();
                err[k] = new double[] {t.tx() - re.tx(), t.ty() - re.ty(), t.tz() - re.tz()};
            } else {
                err[k] = new double[] {Double.NaN, Double.NaN, Double.NaN};
            }
        }
        return err;
    }
}
