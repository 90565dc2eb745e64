package org.fresa.ui;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.fresa.geom.Transform3;
import org.fresa.job.Job;
import org.fresa.job.JobSettings;
import org.fresa.job.RobotFiles;
import org.fresa.kin.DhJoint;
import org.fresa.kin.JointLimit;
import org.fresa.kin.JointType;
import org.fresa.kin.Robot;
import org.fresa.kin.Robots;
import org.fresa.kin.SerialRobot;
import org.fresa.kin.SymbolicKinematics;
import org.fresa.kin.TriceptRobot;
import org.fresa.model.CamInputException;
import org.fresa.model.Placement;

/**
 * The Robot tab's state without Swing: the chosen robot (built-in name or file), its DH table as
 * rows of text cells (lengths mm, angles deg), the Tricept's parameters, and the symbolic forward
 * kinematics text (slow: {@link #symbolic} is meant for a background thread).
 */
final class RobotViewModel {

    static final String[] COLUMNS = {"Joint", "Type", "a (mm)", "d (mm)", "alpha (deg)", "theta offset", "Min", "Max"};

    private Robot robot = Robots.irb140();
    private String choice = "irb140";

    /** The built-in robot names, in the order of {@link Robots#all()}. */
    static List<String> builtIns() {
        List<String> out = new ArrayList<>();
        for (Robot r : Robots.all()) {
            out.add(r.name());
        }
        return out;
    }

    Robot robot() {
        return robot;
    }

    /** What RobotSettings stores: a built-in name or a file path. */
    String choice() {
        return choice;
    }

    /** Chooses a built-in robot or reads a robot file (name or path, as {@code --robot}). */
    void choose(String nameOrFile) throws CamInputException {
        robot = RobotFiles.load(nameOrFile);
        choice = nameOrFile;
    }

    void chooseFile(Path file) throws CamInputException {
        choose(file.toAbsolutePath().toString());
    }

    /** The DH table: one row per joint, cells as shown. A Tricept shows its wrist rows and legs. */
    List<String[]> dhRows() {
        List<String[]> rows = new ArrayList<>();
        List<JointLimit> limits = robot.joints();
        if (robot instanceof SerialRobot s) {
            List<DhJoint> js = s.chain().joints();
            for (int i = 0; i < js.size(); i++) {
                DhJoint d = js.get(i);
                JointLimit l = limits.get(i);
                boolean rev = d.type() == JointType.REVOLUTE;
                rows.add(new String[] {l.name(), rev ? "R" : "P", num(d.aMm()),
                        rev ? num(d.dMm()) : "q" + (i + 1) + offset(d.dMm()), num(d.alphaDeg()),
                        rev ? "q" + (i + 1) + offset(d.thetaDeg()) : num(d.thetaDeg()),
                        num(l.min()) + " " + l.type().unit(), num(l.max()) + " " + l.type().unit()});
            }
        } else if (robot instanceof TriceptRobot t) {
            List<DhJoint> wrist = t.wristChain(Transform3.IDENTITY).joints();
            for (int i = 0; i < limits.size(); i++) {
                JointLimit l = limits.get(i);
                if (i < 3) {
                    rows.add(new String[] {l.name(), "P (leg)", "", "|B" + (i + 1) + " - A" + (i + 1) + "|", "", "",
                            num(l.min()) + " mm", num(l.max()) + " mm"});
                } else {
                    DhJoint d = wrist.get(i - 3);
                    rows.add(new String[] {l.name(), "R", num(d.aMm()), num(d.dMm()), num(d.alphaDeg()),
                            "q" + (i + 1) + offset(d.thetaDeg()), num(l.min()) + " deg", num(l.max()) + " deg"});
                }
            }
        }
        return rows;
    }

    /** The robot's other parameters (Tricept geometry, tool), one line each. */
    List<String> parameters() {
        List<String> out = new ArrayList<>();
        out.add(robot.name() + ": " + robot.description() + ", " + robot.dof() + " joints");
        if (robot instanceof TriceptRobot t) {
            out.add("Base radius r_b = " + num(t.baseRadiusMm()) + " mm (leg joints at 90, 210, 330 deg)");
            out.add("Platform radius r_p = " + num(t.platformRadiusMm()) + " mm");
            out.add("Platform to wrist centre d_eff = " + num(t.centreOffsetMm()) + " mm");
            out.add("Wrist centre to tool tip e_ffl = " + num(t.effectorLengthMm()) + " mm");
        } else if (robot instanceof SerialRobot s && !s.chain().tool().equals(Transform3.IDENTITY)) {
            Transform3 tool = s.chain().tool();
            out.add("Tool offset " + num(tool.tx()) + ", " + num(tool.ty()) + ", " + num(tool.tz()) + " mm");
        }
        return out;
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
            head = "Forward kinematics of " + r.name() + " (mm; q in deg" + (hasPrismatic(s) ? " or mm" : "") + "):";
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

    private static boolean hasPrismatic(SerialRobot s) {
        return s.chain().joints().stream().anyMatch(j -> j.type() == JointType.PRISMATIC);
    }

    /** The job with this robot in its RobotSettings (placements and formats kept). */
    Job applyTo(Job job) {
        JobSettings.RobotSettings old = job.robot().orElse(new JobSettings.RobotSettings(choice, Placement.ORIGIN,
                Placement.ORIGIN, JobSettings.RobotSettings.DEFAULT_FORMATS));
        return job.withRobot(new JobSettings.RobotSettings(choice, old.robotTable(), old.tablePiece(), old.formats()));
    }

    /** The robot a job names, if it differs from the one shown. */
    Optional<String> fromJob(Job job) {
        return job.robot().map(JobSettings.RobotSettings::robot).filter(n -> !n.equals(choice));
    }

    static String num(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return String.format(Locale.ROOT, "%.6g", v).replaceFirst("\\.?0+$", "");
    }

    private static String offset(double c) {
        return c == 0 ? "" : (c > 0 ? " + " : " - ") + num(Math.abs(c));
    }
}
