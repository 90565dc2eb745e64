package org.fresa.ui;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.fresa.cell.RobotFiles;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.job.Job;
import org.fresa.job.JobSettings;
import org.fresa.kin.DenavitHartenbergChain;
import org.fresa.kin.DhExpression;
import org.fresa.kin.DhJoint;
import org.fresa.kin.JointLimit;
import org.fresa.kin.JointType;
import org.fresa.kin.Robot;
import org.fresa.kin.Robots;
import org.fresa.kin.SerialRobot;
import org.fresa.kin.SymbolicKinematics;
import org.fresa.kin.TriceptRobot;
import org.fresa.model.CamInputException;
import org.fresa.model.ExactDecimal;
import org.fresa.model.Placement;

/**
 * The Robot tab's state without Swing: the chosen robot (built-in name or file) and its editable
 * description: the DH table as text cells (theta and alpha in deg, d and a in mm; cells are
 * {@link DhExpression}s such as {@code q2 - 90}), the joint limits (deg or mm), and the other
 * parameters (name, tool frame of a serial robot, Tricept dimensions). Every cell has a message
 * when it is wrong; when none is, {@link #edited()} is the robot the table describes.
 *
 * <p>A robot that differs from the one chosen must live in a file for a job to name it (the job
 * stores a built-in name or a path, and {@code fresa run} reads it): {@link #save} writes it where
 * the user says, {@link #keepIn} into the application's folder under a name made from its content.
 */
final class RobotViewModel {

    static final String[] COLUMNS = {
        "Joint", "Type", "theta (deg)", "d (mm)", "a (mm)", "alpha (deg)", "Min (deg | mm)", "Max (deg | mm)"
    };
    static final int TYPE = 1;
    static final int THETA = 2;
    static final int D = 3;
    static final int A = 4;
    static final int ALPHA = 5;
    static final int MIN = 6;
    static final int MAX = 7;
    private static final String[] CELL_NAMES = {"joint", "type", "theta", "d", "a", "alpha", "min", "max"};

    private static final List<String> SERIAL_PARAMS = List.of(
            "Name", "Tool X (mm)", "Tool Y (mm)", "Tool Z (mm)", "Tool RX (deg)", "Tool RY (deg)", "Tool RZ (deg)");
    private static final List<String> TRICEPT_PARAMS = List.of(
            "Name",
            "Base radius r_b (mm)",
            "Platform radius r_p (mm)",
            "Platform to wrist centre d_eff (mm)",
            "Wrist centre to tool tip e_ffl (mm)");

    private Robot robot = Robots.irb140();
    private String choice = JobSettings.RobotSettings.DEFAULTS.robot();
    private final List<String[]> cells = new ArrayList<>();
    private final List<String> params = new ArrayList<>();
    private Map<String, String> problems = new LinkedHashMap<>();
    private Optional<Robot> edited = Optional.empty();

    RobotViewModel() {
        load();
    }

    /** The built-in robot names, in the order of {@link Robots#all()}. */
    static List<String> builtIns() {
        List<String> out = new ArrayList<>();
        for (Robot r : Robots.all()) {
            out.add(r.name());
        }
        return out;
    }

    /** The robot chosen (built-in or read from a file), before edits. */
    Robot robot() {
        return robot;
    }

    /** What RobotSettings stores: a built-in name or a file path. */
    String choice() {
        return choice;
    }

    /** Chooses a built-in robot or reads a robot file (name or path, as {@code --robot}); edits are dropped. */
    void choose(String nameOrFile) throws CamInputException {
        robot = RobotFiles.load(nameOrFile);
        choice = nameOrFile;
        load();
    }

    void chooseFile(Path file) throws CamInputException {
        choose(file.toAbsolutePath().toString());
    }

    private boolean isTricept() {
        return robot instanceof TriceptRobot;
    }

    private void load() {
        cells.clear();
        params.clear();
        List<JointLimit> limits = robot.joints();
        if (robot instanceof SerialRobot s) {
            List<DhJoint> js = s.chain().joints();
            for (int i = 0; i < js.size(); i++) {
                DhJoint d = js.get(i);
                boolean rev = d.type() == JointType.REVOLUTE;
                String q = "q" + (i + 1);
                cells.add(new String[] {
                    q,
                    rev ? "R" : "P",
                    rev ? q + offset(d.thetaDeg()) : exact(d.thetaDeg()),
                    rev ? exact(d.dMm()) : q + offset(d.dMm()),
                    exact(d.aMm()),
                    exact(d.alphaDeg()),
                    exact(d.qMin()),
                    exact(d.qMax())
                });
            }
            Transform3 tool = s.chain().tool();
            Vec3 zyx = tool.zyxAnglesDeg();
            params.addAll(List.of(
                    robot.name(),
                    exact(tool.tx()),
                    exact(tool.ty()),
                    exact(tool.tz()),
                    exact(zyx.z()),
                    exact(zyx.y()),
                    exact(zyx.x())));
        } else if (robot instanceof TriceptRobot t) {
            List<DhJoint> wrist = t.wristChain(Transform3.IDENTITY).joints();
            for (int i = 0; i < limits.size(); i++) {
                JointLimit l = limits.get(i);
                if (i < 3) {
                    cells.add(new String[] {
                        l.name(),
                        "P (leg)",
                        "",
                        "|B" + (i + 1) + " - A" + (i + 1) + "|",
                        "",
                        "",
                        exact(l.min()),
                        exact(l.max())
                    });
                } else {
                    DhJoint d = wrist.get(i - 3);
                    cells.add(new String[] {
                        l.name(),
                        "R (wrist)",
                        "q" + (i + 1) + offset(d.thetaDeg()),
                        exact(d.dMm()),
                        exact(d.aMm()),
                        exact(d.alphaDeg()),
                        exact(l.min()),
                        exact(l.max())
                    });
                }
            }
            params.addAll(List.of(
                    robot.name(),
                    exact(t.baseRadiusMm()),
                    exact(t.platformRadiusMm()),
                    exact(t.centreOffsetMm()),
                    exact(t.effectorLengthMm())));
        }
        rebuild();
    }

    // ---- the table

    int rowCount() {
        return cells.size();
    }

    String cell(int row, int col) {
        return cells.get(row)[col];
    }

    /** The DH table: one row per joint, cells as shown. */
    List<String[]> dhRows() {
        List<String[]> out = new ArrayList<>();
        for (String[] r : cells) {
            out.add(r.clone());
        }
        return out;
    }

    /**
     * Whether a cell can be edited: for a serial robot the type, the four DH cells and the limits;
     * for the Tricept only the limits (its geometry is in the parameters).
     */
    boolean isEditable(int row, int col) {
        if (col == MIN || col == MAX) {
            return true;
        }
        return !isTricept() && col >= TYPE;
    }

    /**
     * Sets a cell. Changing a joint's type moves the variable: a revolute joint that becomes
     * prismatic gets theta = its old offset and d = qN + old d, and back.
     */
    void setCell(int row, int col, String text) {
        if (!isEditable(row, col)) {
            throw new IllegalArgumentException("cell " + row + "," + col + " cannot be edited");
        }
        String[] r = cells.get(row);
        String t = text.trim();
        if (col == TYPE) {
            String type = t.toUpperCase(Locale.ROOT).startsWith("P") ? "P" : "R";
            if (!type.equals(r[TYPE])) {
                String q = "q" + (row + 1);
                String oldTheta = r[THETA];
                String oldD = r[D];
                if (type.equals("P")) {
                    r[THETA] = stripVariable(oldTheta, q);
                    r[D] = oldD.equals("0") ? q : q + " + " + oldD;
                } else {
                    r[D] = stripVariable(oldD, q);
                    r[THETA] = oldTheta.equals("0") ? q : q + " + " + oldTheta;
                }
                r[TYPE] = type;
            }
        } else {
            r[col] = t;
        }
        rebuild();
    }

    /** The cell's offset when it reads as qN + c, else the text unchanged (it then shows its problem). */
    private String stripVariable(String text, String q) {
        try {
            DhExpression e = DhExpression.parse(text, rowCount());
            int j = Integer.parseInt(q.substring(1));
            if (e.coefficients().size() == 1 && e.coefficient(j) == 1) {
                return exact(e.constant());
            }
        } catch (IllegalArgumentException ex) {
            // left as typed, with its message
        }
        return text;
    }

    /** What is wrong with a cell, if anything. */
    Optional<String> problem(int row, int col) {
        return Optional.ofNullable(problems.get("cell." + row + "." + col));
    }

    // ---- the other parameters

    List<String> parameterNames() {
        return isTricept() ? TRICEPT_PARAMS : SERIAL_PARAMS;
    }

    String parameter(int i) {
        return params.get(i);
    }

    void setParameter(int i, String text) {
        params.set(i, text.trim());
        rebuild();
    }

    Optional<String> parameterProblem(int i) {
        return Optional.ofNullable(problems.get("param." + i));
    }

    /** Every problem, "Joint 2, theta: ..." or "Tool X (mm): ...", in table order; empty when the robot is valid. */
    List<String> messages() {
        return List.copyOf(problems.values());
    }

    /** The robot the table describes; empty while a cell is wrong. */
    Optional<Robot> edited() {
        return edited;
    }

    /** Whether the table describes another robot than the one chosen (and is valid). */
    boolean isModified() {
        return edited.isPresent() && !sameRobot(edited.get(), robot);
    }

    /** The robot's other parameters, one line each, for reading. */
    List<String> parameters() {
        Robot r = edited.orElse(robot);
        List<String> out = new ArrayList<>();
        out.add(r.name() + ": " + r.description() + ", " + r.dof() + " joints");
        if (r instanceof TriceptRobot t) {
            out.add("Base radius r_b = " + num(t.baseRadiusMm()) + " mm (leg joints at 90, 210, 330 deg)");
            out.add("Platform radius r_p = " + num(t.platformRadiusMm()) + " mm");
            out.add("Platform to wrist centre d_eff = " + num(t.centreOffsetMm()) + " mm");
            out.add("Wrist centre to tool tip e_ffl = " + num(t.effectorLengthMm()) + " mm");
        } else if (r instanceof SerialRobot s && !s.chain().tool().equals(Transform3.IDENTITY)) {
            Transform3 tool = s.chain().tool();
            out.add("Tool offset " + num(tool.tx()) + ", " + num(tool.ty()) + ", " + num(tool.tz()) + " mm");
        }
        return out;
    }

    private void rebuild() {
        Map<String, String> p = new LinkedHashMap<>();
        Optional<Robot> built;
        if (robot instanceof SerialRobot s) {
            built = buildSerial(s, p);
        } else if (robot instanceof TriceptRobot t) {
            built = buildTricept(t, p);
        } else {
            built = Optional.empty();
        }
        problems = p;
        edited = p.isEmpty() ? built : Optional.empty();
    }

    private Optional<Robot> buildSerial(SerialRobot original, Map<String, String> p) {
        int n = cells.size();
        List<DhJoint> joints = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            String[] r = cells.get(i);
            int j = i + 1;
            boolean rev = r[TYPE].equals("R");
            int varCol = rev ? THETA : D;
            Double theta = dhCell(i, THETA, varCol, j, n, p);
            Double d = dhCell(i, D, varCol, j, n, p);
            Double a = dhCell(i, A, varCol, j, n, p);
            Double alpha = dhCell(i, ALPHA, varCol, j, n, p);
            double[] lim = limits(i, rev ? JointType.REVOLUTE : JointType.PRISMATIC, p);
            if (theta != null && d != null && a != null && alpha != null && lim != null) {
                joints.add(
                        rev
                                ? DhJoint.revolute(a, alpha, d, theta, lim[0], lim[1])
                                : DhJoint.prismatic(a, alpha, d, theta, lim[0], lim[1]));
            }
        }
        String name = name(p);
        double[] tool = new double[6];
        for (int k = 1; k <= 6; k++) {
            Double v = constantParam(k, p);
            tool[k - 1] = v == null ? 0 : v;
        }
        if (!p.isEmpty()) {
            return Optional.empty();
        }
        Transform3 toolFrame = Transform3.ofXyzRpyDeg(tool[0], tool[1], tool[2], tool[3], tool[4], tool[5]);
        SerialRobot r = new SerialRobot(
                name,
                description(original),
                new DenavitHartenbergChain(joints, original.chain().base(), toolFrame),
                original.wristJoint());
        return Optional.of(r);
    }

    private Optional<Robot> buildTricept(TriceptRobot t, Map<String, String> p) {
        List<JointLimit> legs = new ArrayList<>();
        List<JointLimit> wrist = new ArrayList<>();
        for (int i = 0; i < cells.size(); i++) {
            JointType type = i < 3 ? JointType.PRISMATIC : JointType.REVOLUTE;
            double[] lim = limits(i, type, p);
            if (lim != null) {
                (i < 3 ? legs : wrist).add(new JointLimit("q" + (i + 1), type, lim[0], lim[1]));
            }
        }
        String name = name(p);
        double[] dims = new double[4];
        for (int k = 1; k <= 4; k++) {
            Double v = constantParam(k, p);
            if (v != null && (k <= 2 ? !(v > 0) : v < 0)) {
                p.put("param." + k, parameterNames().get(k) + ": must be " + (k <= 2 ? "more than 0" : "0 or more"));
            }
            dims[k - 1] = v == null ? 0 : v;
        }
        if (!p.isEmpty()) {
            return Optional.empty();
        }
        return Optional.of(new TriceptRobot(name, description(t), dims[0], dims[1], dims[2], dims[3], legs, wrist));
    }

    private String description(Robot original) {
        String name = params.get(0);
        return name.equals(original.name()) ? original.description() : original.description() + ", edited";
    }

    private String name(Map<String, String> p) {
        String n = params.get(0);
        if (n.isEmpty() || !n.matches("[A-Za-z0-9_.-]+")) {
            p.put("param.0", "Name: use letters, digits, '-', '_' and '.' only (it names the robot file)");
        }
        return n;
    }

    private Double constantParam(int k, Map<String, String> p) {
        String label = parameterNames().get(k);
        try {
            DhExpression e = DhExpression.parse(params.get(k), 1);
            if (!e.isConstant()) {
                p.put("param." + k, label + ": a number, not a joint variable");
                return null;
            }
            return e.constant();
        } catch (IllegalArgumentException ex) {
            p.put("param." + k, label + ": " + ex.getMessage());
            return null;
        }
    }

    /** One DH cell's constant (the offset for the variable cell), or null with its problem recorded. */
    private Double dhCell(int row, int col, int varCol, int joint, int n, Map<String, String> p) {
        String where = "Joint " + joint + ", " + CELL_NAMES[col];
        String key = "cell." + row + "." + col;
        DhExpression e;
        try {
            e = DhExpression.parse(cells.get(row)[col], n);
        } catch (IllegalArgumentException ex) {
            p.put(key, where + ": " + ex.getMessage());
            return null;
        }
        for (int other : e.coefficients().keySet()) {
            if (other != joint) {
                p.put(
                        key,
                        where + ": q" + other + " is joint " + other + "'s variable; joint " + joint + " may use only q"
                                + joint);
                return null;
            }
        }
        boolean rev = varCol == THETA;
        if (col == varCol) {
            if (e.isConstant()) {
                p.put(
                        key,
                        where + ": the " + (rev ? "revolute" : "prismatic") + " joint's variable belongs here: write q"
                                + joint + (rev ? " - 90" : " + 100") + " or q" + joint);
                return null;
            }
            if (e.coefficient(joint) != 1) {
                p.put(
                        key,
                        where + ": q" + joint + " must appear with factor 1 (" + CELL_NAMES[col] + " = q" + joint
                                + " + offset)");
                return null;
            }
        } else if (!e.isConstant()) {
            p.put(
                    key,
                    where + ": a constant for a " + (rev ? "revolute" : "prismatic") + " joint; q" + joint
                            + " belongs in " + CELL_NAMES[varCol]);
            return null;
        }
        return e.constant();
    }

    /** A row's limits {min, max}, or null with the problems recorded. */
    private double[] limits(int row, JointType type, Map<String, String> p) {
        Double min = limit(row, MIN, type, p);
        Double max = limit(row, MAX, type, p);
        if (min == null || max == null) {
            return null;
        }
        if (!(max > min)) {
            p.put(
                    "cell." + row + "." + MAX,
                    "Joint " + (row + 1) + ", max: must be more than min (" + num(min) + " " + type.unit() + ")");
            return null;
        }
        return new double[] {min, max};
    }

    private Double limit(int row, int col, JointType type, Map<String, String> p) {
        String where = "Joint " + (row + 1) + ", " + CELL_NAMES[col];
        String key = "cell." + row + "." + col;
        try {
            DhExpression e = DhExpression.parse(cells.get(row)[col], cells.size());
            if (!e.isConstant()) {
                p.put(key, where + ": a number (" + type.unit() + "), not a joint variable");
                return null;
            }
            double v = e.constant();
            if (type == JointType.REVOLUTE && Math.abs(v) > 720) {
                p.put(key, where + ": " + num(v) + " deg is more than two turns (limit within -720..720 deg)");
                return null;
            }
            return v;
        } catch (IllegalArgumentException ex) {
            p.put(key, where + ": " + ex.getMessage());
            return null;
        }
    }

    private static boolean sameRobot(Robot a, Robot b) {
        if (!a.name().equals(b.name())) {
            return false;
        }
        if (a instanceof SerialRobot s && b instanceof SerialRobot t) {
            return s.chain().joints().equals(t.chain().joints())
                    && s.chain().tool().eq(t.chain().tool(), Tolerance.DEFAULT);
        }
        if (a instanceof TriceptRobot s && b instanceof TriceptRobot t) {
            return s.baseRadiusMm() == t.baseRadiusMm()
                    && s.platformRadiusMm() == t.platformRadiusMm()
                    && s.centreOffsetMm() == t.centreOffsetMm()
                    && s.effectorLengthMm() == t.effectorLengthMm()
                    && s.legs().equals(t.legs())
                    && s.wrist().equals(t.wrist());
        }
        return false;
    }

    // ---- files and the job

    /**
     * Writes the edited robot as a robot file and makes it the choice (the job then names the file).
     *
     * @throws IllegalStateException when a cell is wrong (callers check {@link #edited()})
     */
    void save(Path file) throws IOException {
        Robot r = edited.orElseThrow(() -> new IllegalStateException("the robot table has problems"));
        RobotFiles.write(r, file);
        robot = r;
        choice = file.toAbsolutePath().toString();
    }

    /**
     * Keeps the edited robot in a folder as {@code NAME-HASH.xml} (HASH from the file's content,
     * so the same table reuses its file) and makes it the choice. Does nothing when the robot is
     * not modified. Returns the choice.
     */
    String keepIn(Path folder) throws IOException {
        if (!isModified()) {
            return choice;
        }
        if (Robots.byName(params.get(0)).isPresent()) {
            // a file must not pass for the built-in robot it was edited from
            setParameter(0, params.get(0) + "-edited");
        }
        Robot r = edited.orElseThrow();
        Path tmp = Files.createTempFile(Files.createDirectories(folder), ".robot-", ".xml");
        try {
            RobotFiles.write(r, tmp);
            String hash = sha1(Files.readString(tmp, StandardCharsets.UTF_8)).substring(0, 10);
            Path target = folder.resolve(r.name() + "-" + hash + ".xml");
            if (!Files.exists(target)) {
                Files.move(tmp, target);
            }
            robot = r;
            choice = target.toAbsolutePath().toString();
        } finally {
            Files.deleteIfExists(tmp);
        }
        return choice;
    }

    private static String sha1(String s) {
        try {
            return HexFormat.of()
                    .formatHex(MessageDigest.getInstance("SHA-1").digest(s.getBytes(StandardCharsets.UTF_8)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-1 is part of every JDK", e);
        }
    }

    /**
     * The symbolic forward kinematics as text; for the Tricept, of its wrist in the wrist base
     * frame (its parallel part is solved geometrically). Takes about a second.
     */
    static String symbolic(Robot r) {
        SymbolicKinematics.Result res;
        String head;
        if (r instanceof SerialRobot s) {
            res = SymbolicKinematics.of(SymbolicKinematics.rowsOf(s.chain()), false);
            head = "Forward kinematics of " + r.name() + " (mm; q in deg" + (hasPrismatic(s) ? " or mm" : "") + ")"
                    + (s.chain().tool().equals(Transform3.IDENTITY) ? "" : ", flange frame (tool not included)") + ":";
        } else if (r instanceof TriceptRobot t) {
            res = SymbolicKinematics.of(SymbolicKinematics.rowsOf(t.wristChain(Transform3.IDENTITY)), false);
            head = "Wrist of " + r.name() + " in its base frame at the wrist centre W (joints 4-6 as q1-q3;"
                    + " the legs are solved geometrically):";
        } else {
            return "";
        }
        StringBuilder sb = new StringBuilder(head).append('\n');
        String[] names = {"x", "y", "z"};
        List<List<String>> m = res.transform();
        for (int col = 0; col < 4; col++) {
            for (int row = 0; row < 3; row++) {
                String left = col == 3 ? "p" + names[row] : "R" + (row + 1) + (col + 1);
                sb.append(left).append(" = ").append(m.get(row).get(col)).append('\n');
            }
            sb.append('\n');
        }
        return sb.toString();
    }

    /**
     * The symbolic forward kinematics and the geometric Jacobian as text, for a file (takes a few
     * seconds). The Jacobian's columns are per radian of a revolute joint's angle and per mm of a
     * prismatic joint's length, although the expressions take q in degrees.
     */
    static String symbolicExport(Robot r) {
        DenavitHartenbergChain chain;
        if (r instanceof SerialRobot s) {
            chain = s.chain();
        } else if (r instanceof TriceptRobot t) {
            chain = t.wristChain(Transform3.IDENTITY);
        } else {
            return "";
        }
        SymbolicKinematics.Result res = SymbolicKinematics.of(SymbolicKinematics.rowsOf(chain), true);
        StringBuilder sb = new StringBuilder(symbolic(r));
        sb.append("Geometric Jacobian at the ")
                .append(r instanceof TriceptRobot ? "wrist's tool tip" : "flange")
                .append(" (rows vx, vy, vz in mm, then wx, wy, wz; column i per rad or mm of q_i):\n");
        String[] rows = {"vx", "vy", "vz", "wx", "wy", "wz"};
        List<List<String>> j = res.jacobian();
        for (int row = 0; row < j.size(); row++) {
            for (int col = 0; col < j.get(row).size(); col++) {
                sb.append("J_")
                        .append(rows[row])
                        .append("_q")
                        .append(col + 1)
                        .append(" = ")
                        .append(j.get(row).get(col))
                        .append('\n');
            }
            sb.append('\n');
        }
        return sb.toString();
    }

    private static boolean hasPrismatic(SerialRobot s) {
        return s.chain().joints().stream().anyMatch(j -> j.type() == JointType.PRISMATIC);
    }

    // ---- the tool on the flange: the job's spindle and tool length, as typed

    private String spindleText = "";
    private String toolLengthText = "";
    private Optional<Placement> spindle = Optional.empty();
    private java.util.OptionalDouble toolLengthMm = java.util.OptionalDouble.empty();

    String spindleText() {
        return spindleText;
    }

    String toolLengthText() {
        return toolLengthText;
    }

    /**
     * Sets the spindle as {@code --spindle} takes it: {@code X,Y,Z[,RX,RY,RZ]} (mm, deg) of the
     * spindle nose in the flange frame, or nothing for the robot file's tool frame (or the flange).
     * A bad text keeps the last good spindle.
     */
    void setSpindle(String text) {
        spindleText = text.trim();
        if (spindleProblem().isEmpty()) {
            spindle = parseSpindle(spindleText);
        }
    }

    /** Sets the tool length (mm, spindle nose to tip) for every tool; nothing for each STEP-NC tool's own. */
    void setToolLength(String text) {
        toolLengthText = text.trim();
        if (toolLengthProblem().isEmpty()) {
            toolLengthMm = toolLengthText.isEmpty()
                    ? java.util.OptionalDouble.empty()
                    : java.util.OptionalDouble.of(Double.parseDouble(toolLengthText));
        }
    }

    /** What is wrong with the spindle text, if anything. */
    Optional<String> spindleProblem() {
        if (spindleText.isEmpty()) {
            return Optional.empty();
        }
        try {
            org.fresa.setting.SettingRanges.Robot.parseSpindle(spindleText);
            return Optional.empty();
        } catch (CamInputException e) {
            return Optional.of("Spindle: " + e.problem());
        }
    }

    /** What is wrong with the tool length text, if anything. */
    Optional<String> toolLengthProblem() {
        if (toolLengthText.isEmpty()) {
            return Optional.empty();
        }
        double v;
        try {
            v = Double.parseDouble(toolLengthText);
        } catch (NumberFormatException e) {
            return Optional.of("Tool length: '" + toolLengthText + "' is not a number (mm)");
        }
        org.fresa.setting.SettingRange r = org.fresa.setting.SettingRanges.Robot.TOOL_LENGTH;
        return r.contains(v) ? Optional.empty() : Optional.of("Tool length: " + r.problem(v));
    }

    private static Optional<Placement> parseSpindle(String text) {
        if (text.isEmpty()) {
            return Optional.empty();
        }
        try {
            return Optional.of(org.fresa.setting.SettingRanges.Robot.parseSpindle(text));
        } catch (CamInputException e) {
            return Optional.empty();
        }
    }

    /** The spindle and tool length last valid (what the job gets). */
    Optional<Placement> spindle() {
        return spindle;
    }

    java.util.OptionalDouble toolLengthMm() {
        return toolLengthMm;
    }

    /** Shows the spindle and tool length a job holds; true when they differ from those shown. */
    boolean loadTool(Job job) {
        Optional<Placement> s = job.robot().flatMap(JobSettings.RobotSettings::spindle);
        java.util.OptionalDouble l =
                job.robot().map(JobSettings.RobotSettings::toolLengthMm).orElse(java.util.OptionalDouble.empty());
        if (s.equals(spindle) && l.equals(toolLengthMm)) {
            return false;
        }
        spindle = s;
        toolLengthMm = l;
        spindleText = s.map(RobotViewModel::spindleText).orElse("");
        toolLengthText = l.isPresent() ? num(l.getAsDouble()) : "";
        return true;
    }

    /** A spindle as {@code --spindle} writes it: the rotations only when there are any. */
    static String spindleText(Placement p) {
        String xyz = num(p.xMm()) + "," + num(p.yMm()) + "," + num(p.zMm());
        return p.rxDeg() == 0 && p.ryDeg() == 0 && p.rzDeg() == 0
                ? xyz
                : xyz + "," + num(p.rxDeg()) + "," + num(p.ryDeg()) + "," + num(p.rzDeg());
    }

    /** The job with the last valid spindle and tool length (robot, placements and formats kept). */
    Job applyToolTo(Job job) {
        JobSettings.RobotSettings old = job.robot()
                .orElse(new JobSettings.RobotSettings(
                        choice, Placement.ORIGIN, Placement.ORIGIN, JobSettings.RobotSettings.DEFAULT_FORMATS));
        return job.withRobot(new JobSettings.RobotSettings(
                old.robot(), old.robotTable(), old.tablePiece(), old.formats(), spindle, toolLengthMm));
    }

    /** The job with this robot in its RobotSettings (placements and formats kept). */
    Job applyTo(Job job) {
        JobSettings.RobotSettings old = job.robot()
                .orElse(new JobSettings.RobotSettings(
                        choice, Placement.ORIGIN, Placement.ORIGIN, JobSettings.RobotSettings.DEFAULT_FORMATS));
        return job.withRobot(new JobSettings.RobotSettings(
                choice,
                old.robotTable(),
                old.tablePiece(),
                old.formats(),
                old.spindle(),
                old.toolLengthMm(),
                old.placing()));
    }

    /** The robot a job names, if it differs from the one shown. */
    Optional<String> fromJob(Job job) {
        return job.robot().map(JobSettings.RobotSettings::robot).filter(n -> !n.equals(choice));
    }

    static String num(double v) {
        if (v == 0) {
            return "0";
        }
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return String.format(Locale.ROOT, "%.6g", v).replaceFirst("\\.?0+$", "");
    }

    private static String offset(double c) {
        return c == 0 ? "" : (c > 0 ? " + " : " - ") + exact(Math.abs(c));
    }

    /** A cell's text: the number exactly (so that an untouched table gives back the same robot). */
    private static String exact(double v) {
        return v == 0 ? "0" : ExactDecimal.of(v);
    }
}
