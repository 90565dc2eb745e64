package org.fresa.job;

import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.fresa.cell.RobotFiles;
import org.fresa.cell.RobotTools;
import org.fresa.geom.Transform3;
import org.fresa.io.Json;
import org.fresa.io.OutputFolder;
import org.fresa.kin.ErrorStatistics;
import org.fresa.kin.IkOptions;
import org.fresa.kin.IkResult;
import org.fresa.kin.IkSolver;
import org.fresa.kin.Robot;
import org.fresa.kin.SerialRobot;
import org.fresa.model.CamInputException;
import org.fresa.model.ExactDecimal;
import org.fresa.post.KrlWriter;
import org.fresa.post.RapidWriter;
import org.fresa.post.RobotProgram;
import org.fresa.robot.RobotPrograms;
import org.fresa.setting.SettingRanges;

/**
 * {@code fresa ik TARGETS.csv}: the inverse kinematics of any list of tool (TCP) poses in the
 * robot base frame (spec/cli.md), into {@code ik.csv} (the columns of trajectory.csv, plus
 * {@code branch} with {@code --all}) and {@code summary.json}.
 *
 * <p>Each row is solved from every start (the closed form where the robot has one), plus warm
 * from its seed joints and from the previous row's solution; the solutions that keep the asked
 * configuration are kept. Without {@code --all} the row gets the one nearest its seed, else
 * nearest the previous row's, else (the first row) the one with the largest joint-limit margin:
 * the configuration never changes silently between rows unless the previous one cannot reach.
 * Everything is read and checked before the first file is written.
 */
public final class IkService {

    /** The configuration keys a six-joint arm with a spherical wrist knows (ABB confdata, KUKA S and T). */
    public static final List<String> CONFIGURATION_KEYS = List.of("cf1", "cf4", "cf6", "cfx", "S", "T");

    private IkService() {}

    /**
     * What to run.
     *
     * @param targets the CSV of poses
     * @param robot a built-in robot name or a robot file
     * @param tool the spindle and tool length (the TCP is spindle * Tz(tool length))
     * @param method the solver
     * @param toleranceMm the position tolerance; the orientation's is toleranceMm / 100 rad (as
     *     the default 1e-7 mm and 1e-9 rad)
     * @param configuration wanted configuration values by key ({@link #CONFIGURATION_KEYS})
     * @param all every solution branch instead of one per row
     */
    public record Settings(
            Path targets,
            String robot,
            RobotTools.Choice tool,
            IkOptions.Method method,
            double toleranceMm,
            Map<String, Integer> configuration,
            boolean all) {
        public Settings {
            Objects.requireNonNull(targets, "targets");
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(tool, "tool");
            Objects.requireNonNull(method, "method");
            configuration = Map.copyOf(configuration);
            SettingRanges.Robot.IK_TOLERANCE.require(toleranceMm);
        }
    }

    /** One row of the targets: the pose and its seed joints (empty when none). */
    record Target(int line, double[] pose, double[] seed) {}

    /**
     * Reads {@code --configuration K=V[,K=V]}: cf1, cf4, cf6 (quarter turns, -8..7), cfx (0..7),
     * S (KUKA Status, 0..7) and T (Turn, 0..63), as integers or KUKA's {@code 'B010'} binary form.
     */
    public static Map<String, Integer> parseConfiguration(String text) throws CamInputException {
        Map<String, Integer> out = new LinkedHashMap<>();
        for (String part : text.split(",", -1)) {
            String p = part.trim();
            int eq = p.indexOf('=');
            if (eq <= 0) {
                throw new CamInputException(
                        "--configuration",
                        "expected K=V[,K=V] with K one of " + String.join(", ", CONFIGURATION_KEYS) + ", got '" + p
                                + "'");
            }
            String key = p.substring(0, eq).trim();
            String value = p.substring(eq + 1).trim();
            String k = null;
            for (String known : CONFIGURATION_KEYS) {
                if (known.equalsIgnoreCase(key)) {
                    k = known;
                }
            }
            if (k == null) {
                throw new CamInputException(
                        "--configuration",
                        "unknown key '" + key + "': expected one of " + String.join(", ", CONFIGURATION_KEYS));
            }
            int v;
            try {
                String b = value.replace("'", "");
                v = b.length() > 1 && (b.charAt(0) == 'B' || b.charAt(0) == 'b')
                        ? Integer.parseInt(b.substring(1), 2)
                        : Integer.parseInt(b);
            } catch (NumberFormatException e) {
                throw new CamInputException("--configuration", key + ": expected an integer, got '" + value + "'");
            }
            int min = k.startsWith("cf") && !k.equals("cfx") ? -8 : 0;
            int max = k.equals("T") ? 63 : 7;
            if (v < min || v > max) {
                throw new CamInputException("--configuration", key + ": expected " + min + " to " + max + ", got " + v);
            }
            if (out.put(k, v) != null) {
                throw new CamInputException("--configuration", key + " is given twice");
            }
        }
        return out;
    }

    /** Reads, solves and writes ik.csv and summary.json; exit status 1 when a row has no solution. */
    public static TaskOutcome run(Settings s, OutputFolder out, ProgressMonitor progress)
            throws CamInputException, IOException {
        Robot bare = RobotFiles.load(s.robot());
        if (!s.configuration().isEmpty() && !hasConfigurations(bare)) {
            throw new CamInputException(
                    "--configuration",
                    bare.name() + " has no arm configurations to choose (only"
                            + " six-joint arms with a spherical wrist have cf1, cf4, cf6, cfx, S and T)");
        }
        List<String> problems = new ArrayList<>();
        Transform3 spindle = RobotTools.spindle(bare, s.tool(), problems);
        Robot robot =
                bare.withTool(RobotTools.tcp(spindle, s.tool().toolLengthMm().orElse(0)));
        List<Target> targets = read(s.targets(), robot.dof());
        IkOptions options =
                new IkOptions(s.method(), s.toleranceMm(), s.toleranceMm() / 100, IkOptions.DEFAULT.maxIterations());
        IkSolver solver = robot.newSolver(options);
        RapidWriter.ArmGeometry arm = RobotPrograms.armGeometry(robot);
        int n = robot.dof();
        StringBuilder csv = new StringBuilder(targets.size() * 300);
        csv.append("index,workingstep,x,y,z,roll,pitch,yaw");
        for (int i = 1; i <= n; i++) {
            csv.append(",q").append(i);
        }
        csv.append(",reached_x,reached_y,reached_z,pos_err_mm,rot_err_rad,status,flange_x,flange_y,flange_z");
        csv.append(s.all() ? ",branch\n" : "\n");
        ErrorStatistics stats = new ErrorStatistics();
        double[] previous = null;
        int unreachable = 0;
        int rows = 0;
        long nanos = 0;
        progress.progress(0, "inverse kinematics");
        for (int k = 0; k < targets.size(); k++) {
            progress.checkCancelled();
            Target t = targets.get(k);
            double[] v = t.pose();
            Transform3 pose = Transform3.ofXyzRpyDeg(v[0], v[1], v[2], v[5], v[4], v[3]);
            long t0 = System.nanoTime();
            List<double[]> found = solutions(solver, pose, t.seed(), previous, robot);
            nanos += System.nanoTime() - t0;
            List<double[]> kept = new ArrayList<>();
            for (double[] q : found) {
                if (matches(q, pose, s.configuration(), arm)) {
                    kept.add(q);
                }
            }
            if (kept.isEmpty()) {
                unreachable++;
                rows++;
                row(csv, rows, v, null, robot, pose, s.all() ? 0 : -1);
                continue;
            }
            if (s.all()) {
                for (int b = 0; b < kept.size(); b++) {
                    rows++;
                    stats.add(pose, robot.forward(kept.get(b)));
                    row(csv, rows, v, kept.get(b), robot, pose, b + 1);
                }
                previous = kept.get(0);
            } else {
                double[] reference = t.seed().length > 0 ? t.seed() : previous;
                double[] best = reference == null ? kept.get(0) : nearest(kept, reference, robot);
                rows++;
                stats.add(pose, robot.forward(best));
                row(csv, rows, v, best, robot, pose, -1);
                previous = best;
            }
            if ((k & 255) == 0) {
                progress.progress((double) (k + 1) / targets.size(), "inverse kinematics");
            }
        }
        Map<String, Object> summary = new LinkedHashMap<>();
        summary.put("robot", robot.name());
        summary.put("targets", targets.size());
        summary.put("points", rows);
        summary.put("unreachable", unreachable);
        summary.put("method", s.method() == IkOptions.Method.THESIS_DLS ? "thesis-dls" : "default");
        summary.put("tolerance_mm", s.toleranceMm());
        summary.put("configuration", new LinkedHashMap<>(s.configuration()));
        summary.put(
                "tcp_mm",
                List.of(robot.tool().tx(), robot.tool().ty(), robot.tool().tz()));
        summary.put("max_pos_err_mm", stats.maxPosMm());
        summary.put("max_rot_err_rad", stats.maxRotRad());
        summary.putAll(stats.summary());
        summary.put("ik_ms", nanos / 1e6);
        out.create();
        out.writeString("ik.csv", csv.toString());
        out.writeString("summary.json", Json.writePretty(summary));
        int exit = 0;
        if (unreachable > 0) {
            exit = 1;
            problems.add(unreachable + " of " + targets.size() + " poses have no solution within the joint limits"
                    + (s.configuration().isEmpty() ? "" : " in the configuration asked")
                    + " (status unreachable in ik.csv)");
        }
        return new TaskOutcome(exit, problems, summary, out.written());
    }

    static boolean hasConfigurations(Robot r) {
        return r instanceof SerialRobot s && s.dof() == 6 && s.wristJoint() >= 0;
    }

    /** Every distinct solution: from every start, then warm from the seed and the previous row's. */
    private static List<double[]> solutions(
            IkSolver solver, Transform3 pose, double[] seed, double[] previous, Robot robot) {
        List<double[]> out = new ArrayList<>();
        for (IkResult.Converged c : solver.solveAll(pose)) {
            addDistinct(out, c.q());
        }
        for (double[] start : new double[][] {seed, previous}) {
            if (start != null
                    && start.length == robot.dof()
                    && solver.solve(pose, start) instanceof IkResult.Converged c) {
                addDistinct(out, c.q());
            }
        }
        return out;
    }

    private static void addDistinct(List<double[]> out, double[] q) {
        for (double[] o : out) {
            double d = 0;
            for (int i = 0; i < q.length; i++) {
                d = Math.max(d, Math.abs(o[i] - q[i]));
            }
            if (d < 1e-6) {
                return;
            }
        }
        out.add(q);
    }

    /** The solution with the smallest largest joint change from the reference (prismatic mm as deg). */
    private static double[] nearest(List<double[]> kept, double[] reference, Robot robot) {
        double[] best = null;
        double bestD = Double.POSITIVE_INFINITY;
        for (double[] q : kept) {
            double d = 0;
            for (int i = 0; i < q.length; i++) {
                d = Math.max(d, Math.abs(q[i] - reference[i]));
            }
            if (d < bestD) {
                best = q;
                bestD = d;
            }
        }
        return best;
    }

    /** Whether the joints have every configuration value asked. */
    static boolean matches(double[] q, Transform3 pose, Map<String, Integer> wanted, RapidWriter.ArmGeometry arm) {
        if (wanted.isEmpty()) {
            return true;
        }
        List<Double> values = new ArrayList<>();
        for (double v : q) {
            values.add(v);
        }
        RobotProgram.Motion m = new RobotProgram.Motion(
                0, "", RobotProgram.MotionType.LINEAR, RobotProgram.PointRole.PART, values, pose, 1, 0, 0, 0);
        RapidWriter.Confdata cf = RapidWriter.confdata(m, arm);
        Map<String, Integer> has = Map.of(
                "cf1",
                cf.cf1(),
                "cf4",
                cf.cf4(),
                "cf6",
                cf.cf6(),
                "cfx",
                cf.cfx(),
                "S",
                KrlWriter.status(m, arm),
                "T",
                KrlWriter.turn(m));
        for (Map.Entry<String, Integer> e : wanted.entrySet()) {
            if (!has.get(e.getKey()).equals(e.getValue())) {
                return false;
            }
        }
        return true;
    }

    private static void row(
            StringBuilder sb, int index, double[] v, double[] q, Robot robot, Transform3 pose, int branch) {
        int n = robot.dof();
        sb.append(index).append(',');
        for (double d : v) {
            ExactDecimal.append(sb.append(','), d);
        }
        if (q == null) {
            sb.append(",".repeat(n + 5)).append(",unreachable,,,");
        } else {
            for (double d : q) {
                ExactDecimal.append(sb.append(','), d);
            }
            Transform3 reached = robot.forward(q);
            Transform3 flange = robot.flange(q);
            for (double d : new double[] {
                reached.tx(),
                reached.ty(),
                reached.tz(),
                reached.translationPart().distance(pose.translationPart()),
                pose.rotationAngleTo(reached)
            }) {
                ExactDecimal.append(sb.append(','), d);
            }
            sb.append(",ok");
            for (double d : new double[] {flange.tx(), flange.ty(), flange.tz()}) {
                ExactDecimal.append(sb.append(','), d);
            }
        }
        if (branch >= 0) {
            sb.append(',');
            if (branch > 0) {
                sb.append(branch);
            }
        }
        sb.append('\n');
    }

    /**
     * Reads the targets: a header {@code x,y,z,roll,pitch,yaw[,q1,...,qN]}, then one pose per row
     * (mm, deg), with N seed joints when the header names them.
     *
     * @throws CamInputException with the file, line and column of the first bad cell
     */
    static List<Target> read(Path file, int dof) throws CamInputException {
        String name = file.toString();
        List<Target> out = new ArrayList<>();
        try (BufferedReader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            String header = r.readLine();
            if (header == null) {
                throw new CamInputException(
                        name,
                        1,
                        1,
                        "expected the header x,y,z,roll,pitch,yaw[,q1,...,q" + dof + "], the file is empty");
            }
            String[] h = header.replace("\uFEFF", "").split(",", -1);
            String[] want = {"x", "y", "z", "roll", "pitch", "yaw"};
            boolean seeds = h.length == 6 + dof;
            boolean ok = h.length == 6 || seeds;
            for (int i = 0; i < h.length && ok; i++) {
                String expected = i < 6 ? want[i] : "q" + (i - 5);
                ok = h[i].trim().equalsIgnoreCase(expected);
            }
            if (!ok) {
                throw new CamInputException(
                        name,
                        1,
                        1,
                        "expected the header x,y,z,roll,pitch,yaw or" + " x,y,z,roll,pitch,yaw,q1,...,q" + dof + " ("
                                + dof + " joints), got '" + header + "'");
            }
            int columns = h.length;
            String line;
            int lineNo = 1;
            while ((line = r.readLine()) != null) {
                lineNo++;
                if (line.isBlank()) {
                    continue;
                }
                String[] c = line.split(",", -1);
                if (c.length != columns) {
                    throw new CamInputException(
                            name,
                            lineNo,
                            1,
                            "expected " + columns + " comma-separated numbers ("
                                    + String.join(",", h).trim() + "), got " + c.length);
                }
                double[] v = new double[columns];
                int col = 1;
                for (int i = 0; i < columns; i++) {
                    v[i] = number(name, lineNo, col, h[i].trim(), c[i].trim(), i, dof);
                    col += c[i].length() + 1;
                }
                double[] seed = new double[seeds ? dof : 0];
                System.arraycopy(v, 6, seed, 0, seed.length);
                out.add(new Target(lineNo, java.util.Arrays.copyOf(v, 6), seed));
                if (out.size() > MAX_TARGETS) {
                    throw new CamInputException(name, lineNo, 1, "expected at most " + MAX_TARGETS + " poses");
                }
            }
        } catch (NoSuchFileException e) {
            throw new CamInputException(name, "no such file");
        } catch (java.nio.charset.CharacterCodingException e) {
            throw new CamInputException(name, "expected UTF-8 text");
        } catch (IOException e) {
            throw new CamInputException(name, "cannot read (" + e.getMessage() + ")");
        }
        return out;
    }

    /** At most this many poses per file: a million rows of ik.csv. */
    static final int MAX_TARGETS = 1_000_000;

    private static double number(String file, int line, int column, String what, String text, int index, int dof)
            throws CamInputException {
        double v;
        try {
            v = Double.parseDouble(text);
        } catch (NumberFormatException e) {
            v = Double.NaN;
        }
        // positions within a robot cell, angles within two turns (a seed's prismatic joint in mm)
        double limit = index < 3 ? SettingRanges.CELL_SIZE_MM : index < 6 ? 720 : SettingRanges.CELL_SIZE_MM;
        if (!Double.isFinite(v) || Math.abs(v) > limit || text.isEmpty()) {
            throw new CamInputException(
                    file,
                    line,
                    column,
                    what + ": expected a number from " + -limit + " to "
                            + limit
                            + (index < 3 || index >= 6 ? " (mm" + (index >= 6 ? " or deg" : "") + ")" : " (deg)")
                            + ", got '" + text + "'");
        }
        return v;
    }
}
