package org.fresa.check;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fresa.geom.Vec3;

/**
 * The check every NC program passes before Fresa writes it: the text is read back block by block
 * as the control would execute it (modal G codes, absolute or incremental, the plane, the spindle
 * and the tool in effect), and the first block that breaks a {@link Rule} is returned with the
 * rule and the reason. A program that fails is not written.
 *
 * <p>The rules, in the order they are asked of each block: {@link WordRule} (every word finite
 * and in range), {@link SpindleRule} (cutting only with the spindle or the process on),
 * {@link EntryAngleRule} (no entry steeper than the tool allows), {@link FloorRule} (nothing
 * below the floor beyond the breakthrough), {@link RapidRule} (no rapid into material the program
 * has not removed).
 *
 * <p>What the reading assumes, as Fresa's posts write: M03/M04/M05 take effect before the block's
 * motion (RS274's order of execution); M06 and the program's end (M02, M30) stop the spindle; a
 * G53 block moves in the machine's frame, so the position is unknown after it until an absolute
 * move gives it again; a G54 block with coordinates (the 7M's zero setting) moves nothing.
 * Nothing is checked of the motion of a block whose start is unknown.
 */
public final class ProgramCheck {

    /** The rules, in the order each block is asked them. */
    public static final List<Rule> RULES =
            List.of(new WordRule(), new SpindleRule(), new EntryAngleRule(), new FloorRule(), new RapidRule());

    private static final java.util.regex.Pattern AXIS_COMMENT = java.util.regex.Pattern.compile(
            "(?i)tool axis (-?\\d+(?:\\.\\d+)?) (-?\\d+(?:\\.\\d+)?) (-?\\d+(?:\\.\\d+)?) is not \\+Z");

    /** Most points an arc is sampled into (a degree each), against absurd turn counts. */
    private static final int MAX_ARC_POINTS = 100_000;

    private ProgramCheck() {}

    /**
     * The outcome: the first failure, or none.
     *
     * @param failure the first block that breaks a rule, or empty when the program passes
     * @param blocks how many blocks (lines, motions) were checked
     */
    public record Verdict(Optional<Failure> failure, int blocks) {
        public boolean ok() {
            return failure.isEmpty();
        }
    }

    /** Checks an NC program's text in its dialect against the limits. */
    public static Verdict of(String program, NcDialect dialect, Limits limits) {
        if (dialect == NcDialect.APT) {
            return AptStatements.check(program, limits);
        }
        try {
            return of(new java.io.StringReader(program), dialect, limits);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e); // a string reader does not fail
        }
    }

    /**
     * Checks an NC program read from a stream, block by block as {@link #of(String, NcDialect, Limits)}
     * does, with the same verdict: a written program file is checked without being held whole.
     * Lines end at LF, CR or CR LF; the text after the last line end is a block of its own.
     */
    public static Verdict of(java.io.Reader program, NcDialect dialect, Limits limits) throws java.io.IOException {
        if (dialect == NcDialect.APT) {
            StringBuilder all = new StringBuilder();
            char[] buf = new char[1 << 14];
            for (int r; (r = program.read(buf)) > 0; ) {
                all.append(buf, 0, r);
            }
            return AptStatements.check(all.toString(), limits);
        }
        Machine m = new Machine(dialect, limits);
        Lines lines = new Lines(program);
        int count = 0;
        for (String text; (text = lines.next()) != null; ) {
            Words.Block b = Words.block(++count, text);
            m.readAxis(b.text());
            Step step = m.execute(b);
            for (Rule r : RULES) {
                String why = r.broken(step, limits);
                if (why != null) {
                    // the rest is not read: a refused program's file is deleted unread
                    return new Verdict(Optional.of(new Failure(b.line(), b.label(), b.text(), r, why)), count);
                }
            }
            step.material().cut(step, limits);
            if (b.problem().isPresent()) {
                break;
            }
        }
        return new Verdict(Optional.empty(), count + lines.skipAll());
    }

    /** The lines of a stream, split as the text version splits them, read a buffer at a time. */
    private static final class Lines {
        private final java.io.Reader in;
        private final char[] buf = new char[1 << 16];
        private final StringBuilder line = new StringBuilder(128);
        private int pos;
        private int len;
        private boolean done;

        Lines(java.io.Reader in) {
            this.in = in;
        }

        private boolean fill() throws java.io.IOException {
            int r;
            do {
                r = in.read(buf, 0, buf.length);
            } while (r == 0);
            pos = 0;
            len = Math.max(r, 0);
            return r > 0;
        }

        /** The next line without its end, or null after the last one. */
        String next() throws java.io.IOException {
            if (done) {
                return null;
            }
            line.setLength(0);
            while (true) {
                if (pos == len && !fill()) {
                    done = true;
                    return line.toString();
                }
                int start = pos;
                while (pos < len && buf[pos] != '\n' && buf[pos] != '\r') {
                    pos++;
                }
                line.append(buf, start, pos - start);
                if (pos < len) {
                    char c = buf[pos++];
                    if (c == '\r' && (pos < len || fill()) && buf[pos] == '\n') {
                        pos++;
                    }
                    return line.toString();
                }
            }
        }

        /** Reads the rest, returning how many lines it held. */
        int skipAll() throws java.io.IOException {
            int n = 0;
            while (next() != null) {
                n++;
            }
            return n;
        }
    }

    /**
     * Checks a robot program before any of its formats (XML, RAPID, KRL) is written: each motion
     * as a block whose feed is its speed (mm/s x 60) and whose spindle is its spindle speed; linear
     * motions on the part are the cutting moves; the tool axis is each target's z axis (into the
     * material). Joint values must be finite and within their joints' limits. The floor is not
     * checked here: the robot program is in the robot's base frame, the floor in the workpiece's
     * (the toolpath the program follows is checked where it is planned).
     */
    public static Verdict of(org.fresa.post.RobotProgram program, Limits limits) {
        return of(program, limits, java.util.Map.of());
    }

    /**
     * Checks a robot program as {@link #of(org.fresa.post.RobotProgram, Limits)} does, each
     * workingstep's motions made with the tool of that number ({@link Limits#tool}).
     */
    public static Verdict of(
            org.fresa.post.RobotProgram program, Limits limits, java.util.Map<String, Integer> toolByWorkingstep) {
        Vec3 prev = null;
        List<org.fresa.post.RobotProgram.Motion> motions = program.motions();
        for (org.fresa.post.RobotProgram.Motion m : motions) {
            Vec3 at = m.target().translationPart();
            String where = "motion " + m.index();
            String text = (m.type() == org.fresa.post.RobotProgram.MotionType.LINEAR ? "linear" : "joint")
                    + " motion in workingstep " + m.workingstep();
            for (int j = 0; j < m.jointValues().size() && j < program.joints().size(); j++) {
                org.fresa.post.RobotProgram.Joint joint = program.joints().get(j);
                double q = m.joint(j);
                if (!Double.isFinite(q) || q < joint.minValue() - 1e-6 || q > joint.maxValue() + 1e-6) {
                    return new Verdict(
                            Optional.of(new Failure(
                                    m.index(),
                                    where,
                                    text,
                                    RULES.get(0),
                                    "joint "
                                            + joint.name() + " at " + Num.of(q) + " "
                                            + joint.type().unit() + ", outside its limits "
                                            + Num.of(joint.minValue()) + ".." + Num.of(joint.maxValue()))),
                            motions.size());
                }
            }
            List<Words.Word> words = new ArrayList<>();
            double feed = m.speedMmPerS() * 60;
            words.add(new Words.Word("F", feed, Num.of(feed)));
            if (m.spindleRpm() > 0) {
                words.add(new Words.Word("S", m.spindleRpm(), Num.of(m.spindleRpm())));
            }
            Words.Block b = new Words.Block(m.index(), text, words, Optional.empty());
            boolean cutting = m.type() == org.fresa.post.RobotProgram.MotionType.LINEAR
                    && m.role() == org.fresa.post.RobotProgram.PointRole.PART;
            Vec3 axis = m.target().zAxis().times(-1);
            List<Vec3> path = prev == null ? List.of(at) : List.of(prev, at);
            Step step = new Step(
                    b,
                    NcDialect.LINUXCNC,
                    cutting,
                    path,
                    false,
                    0,
                    m.spindleRpm() > 0,
                    m.spindleRpm() > 0 ? m.spindleRpm() : Double.NaN,
                    feed,
                    toolByWorkingstep.getOrDefault(m.workingstep(), 0),
                    false,
                    axis,
                    List.of(),
                    null);
            for (Rule r : RULES) {
                String why = r.broken(step, limits);
                if (why != null) {
                    return new Verdict(Optional.of(new Failure(m.index(), where, text, r, why)), motions.size());
                }
            }
            prev = at;
        }
        return new Verdict(Optional.empty(), motions.size());
    }

    /**
     * The tool axis a comment that starts a section states: the one its "tool axis x y z is not
     * +Z" names, otherwise +Z.
     */
    static Vec3 axisOfComment(String comment) {
        java.util.regex.Matcher mt = AXIS_COMMENT.matcher(comment);
        if (mt.find()) {
            Vec3 v = new Vec3(
                    Double.parseDouble(mt.group(1)), Double.parseDouble(mt.group(2)), Double.parseDouble(mt.group(3)));
            return v.norm() > 0.5 ? v.times(1 / v.norm()) : Vec3.UNIT_Z;
        }
        return Vec3.UNIT_Z;
    }

    /**
     * Remembers the hole a tool that may plunge leaves when it goes straight down with its
     * spindle on, along the section's tool axis: a later cutter may enter it ({@link Pilot}).
     */
    static void madeHole(Step s, Limits limits, List<Pilot> drilled) {
        ToolLimits t = limits.tool(s.tool());
        List<Vec3> p = s.path();
        if (!s.feedMove() || !s.cuttingOn() || !t.plunge() || !(t.radiusMm() > 0) || p.size() != 2) {
            return;
        }
        Vec3 d = p.get(1).minus(p.get(0));
        double along = d.dot(s.axis());
        if (along < 0
                && d.minus(s.axis().times(along)).norm() <= s.dialect().quantumMm()
                && Double.isFinite(p.get(1).x() + p.get(1).y() + p.get(1).z())) {
            drilled.add(new Pilot(p.get(1), s.axis(), t.radiusMm()));
        }
    }

    /** The control's state while the program runs. */
    private static final class Machine extends MachineState {
        private final NcDialect dialect;
        private int motion = -1;
        private boolean absolute = true;
        private int plane = 17;
        private int selected;

        Machine(NcDialect dialect, Limits limits) {
            super(limits);
            this.dialect = dialect;
        }

        /**
         * Fresa's posts write a section whose tool axis is not +Z as it is, with a comment naming
         * the axis (the part is to be turned so that it becomes the spindle's): the section's
         * entries are measured along it. Every other comment line starts a section along +Z.
         */
        void readAxis(String text) {
            String t = text.strip();
            if (!(t.startsWith("(") || t.startsWith(";"))) {
                return;
            }
            axis = axisOfComment(t);
        }

        Step execute(Words.Block b) {
            boolean dwell = false;
            boolean machineFrame = false;
            boolean zeroSetting = false;
            for (Words.Word w : b.words()) {
                if (w.address().equals("G")) {
                    double g = w.value();
                    if (g == 0 || g == 1 || g == 2 || g == 3) {
                        motion = (int) g;
                    } else if (g == 80) {
                        motion = -1;
                    } else if (g == 90) {
                        absolute = true;
                    } else if (g == 91) {
                        absolute = false;
                    } else if (g == 17 || g == 18 || g == 19) {
                        plane = (int) g;
                    } else if (g == 4) {
                        dwell = true;
                    } else if (g == 53) {
                        machineFrame = true;
                    } else if (g >= 54 && g <= 59) {
                        zeroSetting = true;
                    }
                }
            }
            b.word("S").ifPresent(w -> rpm = w.value());
            b.word("T").ifPresent(w -> selected = (int) Math.max(0, Math.min(Integer.MAX_VALUE, w.value())));
            switchCutting(b);
            boolean hasAxis = b.word("X").isPresent()
                    || b.word("Y").isPresent()
                    || b.word("Z").isPresent();
            boolean moves = !dwell && motion >= 0 && hasAxis && !(zeroSetting && dialect == NcDialect.SINUMERIK_7M);
            boolean feedMove = moves && motion > 0;
            if (!dwell) {
                b.word("F").ifPresent(w -> feed = w.value());
            }
            List<Vec3> path = List.of();
            boolean arcInPlane = false;
            double horizontal = 0;
            if (moves) {
                double nx = axis(b, "X", x);
                double ny = axis(b, "Y", y);
                double nz = axis(b, "Z", z);
                if (machineFrame) {
                    // G53: machine coordinates, not the program's frame
                    nx = b.word("X").isPresent() ? Double.NaN : x;
                    ny = b.word("Y").isPresent() ? Double.NaN : y;
                    nz = b.word("Z").isPresent() ? Double.NaN : z;
                }
                if (known(x, y, z) && known(nx, ny, nz)) {
                    Vec3 start = new Vec3(x, y, z);
                    Vec3 end = new Vec3(nx, ny, nz);
                    if (motion == 2 || motion == 3) {
                        Arc arc = arc(b, start, end);
                        path = arc.points;
                        arcInPlane = plane == 17;
                        horizontal = arc.horizontalMm;
                    } else {
                        path = List.of(start, end);
                    }
                } else if (known(nx, ny, nz)) {
                    path = List.of(new Vec3(nx, ny, nz));
                }
                x = nx;
                y = ny;
                z = nz;
            }
            Step step = new Step(
                    b,
                    dialect,
                    feedMove,
                    path,
                    arcInPlane,
                    horizontal,
                    on,
                    rpm,
                    feed,
                    tool,
                    dwell,
                    axis,
                    drilled,
                    material);
            madeHole(step, limits, drilled);
            // a tool change and the program's end stop the spindle after the block
            if (b.has("M", 6)) {
                tool = selected;
                on = on && !limits.head().isSpindle();
            }
            if (b.has("M", 2) || b.has("M", 30)) {
                on = false;
            }
            return step;
        }

        private void switchCutting(Words.Block b) {
            Limits.Head head = limits.head();
            if (head.isSpindle()) {
                if (b.has("M", 3) || b.has("M", 4)) {
                    on = true;
                }
                if (b.has("M", 5)) {
                    on = false;
                }
                return;
            }
            if (contains(b, head.off())) {
                on = false;
            }
            if (contains(b, head.on())) {
                on = true;
            }
        }

        private static boolean contains(Words.Block b, List<Words.Word> group) {
            return group.stream().allMatch(w -> b.has(w.address(), w.value()));
        }

        private double axis(Words.Block b, String letter, double current) {
            Optional<Words.Word> w = b.word(letter);
            if (w.isEmpty()) {
                return current;
            }
            double v = w.get().value() * dialect.mmPerUnit();
            return absolute ? v : current + v;
        }

        private static boolean known(double x, double y, double z) {
            return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
        }

        private record Arc(List<Vec3> points, double horizontalMm) {}

        /** The arc (or helix) of a G02/G03 block, sampled every degree; I/J/K from the start point. */
        private Arc arc(Words.Block b, Vec3 start, Vec3 end) {
            // the plane's axes (u, v) and the linear axis w, right-handed: G17 XY, G18 ZX, G19 YZ
            int[] idx = plane == 17 ? new int[] {0, 1, 2} : plane == 18 ? new int[] {2, 0, 1} : new int[] {1, 2, 0};
            String[] centreWords = {"I", "J", "K"};
            double[] s = {start.x(), start.y(), start.z()};
            double[] e = {end.x(), end.y(), end.z()};
            double[] c = new double[3];
            for (int k = 0; k < 3; k++) {
                c[k] = s[k] + b.word(centreWords[k]).map(Words.Word::value).orElse(0.0) * dialect.mmPerUnit();
            }
            double su = s[idx[0]] - c[idx[0]];
            double sv = s[idx[1]] - c[idx[1]];
            double eu = e[idx[0]] - c[idx[0]];
            double ev = e[idx[1]] - c[idx[1]];
            double r0 = Math.hypot(su, sv);
            double r1 = Math.hypot(eu, ev);
            double a0 = Math.atan2(sv, su);
            double a1 = Math.atan2(ev, eu);
            boolean ccw = motion == 3;
            double sweep = ccw ? a1 - a0 : a0 - a1;
            sweep = ((sweep % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI);
            if (sweep < 1e-9) {
                sweep = 2 * Math.PI;
            }
            sweep += 2 * Math.PI * extraTurns(b);
            int n = (int) Math.min(MAX_ARC_POINTS, Math.max(2, Math.ceil(Math.toDegrees(sweep))));
            List<Vec3> pts = new ArrayList<>(n + 1);
            for (int i = 0; i <= n; i++) {
                double t = (double) i / n;
                double a = a0 + (ccw ? 1 : -1) * sweep * t;
                double r = r0 + (r1 - r0) * t;
                double[] p = new double[3];
                p[idx[0]] = c[idx[0]] + r * Math.cos(a);
                p[idx[1]] = c[idx[1]] + r * Math.sin(a);
                p[idx[2]] = s[idx[2]] + (e[idx[2]] - s[idx[2]]) * t;
                pts.add(i == n ? end : i == 0 ? start : new Vec3(p[0], p[1], p[2]));
            }
            return new Arc(pts, 0.5 * (r0 + r1) * sweep);
        }

        private int extraTurns(Words.Block b) {
            String word = dialect.turnWord();
            if (word == null) {
                return 0;
            }
            Optional<Words.Word> w = b.word(word);
            if (w.isEmpty()) {
                return 0;
            }
            double v = w.get().value();
            // LinuxCNC's P counts the turns (P1: none extra), the 840D's TURN the extra ones
            double extra = word.equals("P") ? v - 1 : v;
            return (int) Math.max(0, Math.min(1000, extra));
        }
    }
}
