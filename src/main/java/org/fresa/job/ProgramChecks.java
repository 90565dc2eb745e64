package org.fresa.job;

import java.util.EnumSet;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.fresa.check.Failure;
import org.fresa.check.Limits;
import org.fresa.check.NcDialect;
import org.fresa.check.ProgramCheck;
import org.fresa.check.ToolLimits;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.MachiningWorkingstep;
import org.fresa.stepnc.Operation.OperationType;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.Workpiece;
import org.fresa.toolpath.ToolpathPlanner;

/**
 * What each module's programs are checked against ({@link ProgramCheck}) before they are written,
 * and the refusal a planner reads when one fails: the file that is not written, the block and the
 * rule.
 */
public final class ProgramChecks {

    /** Operations whose tool goes straight down its axis: drills, reamers, taps, boring bars. */
    static final Set<OperationType> AXIAL = EnumSet.of(
            OperationType.DRILLING,
            OperationType.CENTER_DRILLING,
            OperationType.MULTISTEP_DRILLING,
            OperationType.COUNTER_SINKING,
            OperationType.REAMING,
            OperationType.BORING,
            OperationType.BACK_BORING,
            OperationType.TAPPING,
            OperationType.THREAD_DRILLING);

    private ProgramChecks() {}

    /** A program that failed the check and is not written. */
    public static final class RefusedProgram extends Exception {
        private static final long serialVersionUID = 1L;
        private final transient Failure failure;

        public RefusedProgram(String file, Failure failure) {
            super(file + " not written: it fails the program check at " + failure.message());
            this.failure = failure;
        }

        public Failure failure() {
            return failure;
        }
    }

    /** Checks the program; returns it when it passes. */
    public static String require(String file, String program, NcDialect dialect, Limits limits) throws RefusedProgram {
        Optional<Failure> f = ProgramCheck.of(program, dialect, limits).failure();
        if (f.isPresent()) {
            throw new RefusedProgram(file, f.get());
        }
        return program;
    }

    /**
     * Checks a program file as written, block by block: the refusal names {@code file}, the name
     * the program would have had (the written file is a temporary one, renamed only if it passes).
     */
    public static void require(String file, java.nio.file.Path written, NcDialect dialect, Limits limits)
            throws RefusedProgram, java.io.IOException {
        Optional<Failure> f;
        try (java.io.Reader in =
                java.nio.file.Files.newBufferedReader(written, java.nio.charset.StandardCharsets.UTF_8)) {
            f = ProgramCheck.of(in, dialect, limits).failure();
        }
        if (f.isPresent()) {
            throw new RefusedProgram(file, f.get());
        }
    }

    /**
     * The pocket module's limits. The stock below the pocket's top, the floor its bottom with no
     * breakthrough. The cutter as the settings say: the entry angle asked for, straight down only
     * for a centre-cutting cutter asked to plunge (or left to plunge where a helix and a ramp have
     * no room). {@code 7m-compat} writes the thesis's programs, which plunge straight down at every
     * depth pass ({@code G01 G91 Z-}): it is checked with the thesis's cutter declared
     * centre-cutting and asked to plunge (a slot drill, the only tool those programs can have been
     * run with), in the 7M's frame whose zero is the pocket's top ({@code G54 Z} = the top), as
     * {@code 7m} is. A rest tool (T2) is the same kind of cutter with its own radius.
     */
    public static Limits pocket(PocketSettings s) {
        double r = s.toolDiameterMm() / 2;
        boolean sevenM = s.post().sevenM();
        Limits l = sevenM
                ? Limits.milling().withHeights(0, s.zBottomMm() - s.zTopMm(), 0)
                : Limits.milling().withHeights(s.zTopMm(), s.zBottomMm(), 0);
        ToolLimits tool;
        if (s.post().thesis()) {
            tool = ToolLimits.centreCuttingPlunge()
                    .withKind("the thesis's slot drill, declared centre-cutting: 7m-compat plunges as its programs do");
        } else if (s.centreCutting()
                && (s.entry() == org.fresa.pocket.EntryRule.Kind.PLUNGE
                        || s.entry() == org.fresa.pocket.EntryRule.Kind.AUTO)) {
            tool = ToolLimits.centreCuttingPlunge();
        } else {
            double angle = s.entryAngleDeg() > 0 && s.entryAngleDeg() <= 90
                    ? s.entryAngleDeg()
                    : ToolLimits.DEFAULT_ENTRY_ANGLE_DEG;
            tool = new ToolLimits(
                    angle,
                    false,
                    s.centreCutting() ? "a centre-cutting cutter asked to ramp" : "a cutter not cutting at its centre",
                    0);
        }
        l = l.withOtherTools(tool.withRadiusMm(r));
        if (s.strategy().restTool()) {
            // the rest tool (T2) enters as the first does, and the check judges it into stock
            l = l.withTool(
                    org.fresa.pocket.RestMachining.TOOL_NUMBER,
                    tool.withRadiusMm(s.strategy().restToolDiameterMm() / 2));
        }
        return l;
    }

    /**
     * A sole's tread programs: the stock below the mould's top face (z = 0), the floor the tread
     * depth. The job gives every tread tool a plunge feed: they are engravers that go straight
     * down into the groove, taken as centre-cutting tools asked to plunge.
     */
    public static Limits soleTread(JobSettings.SoleSettings s) {
        return Limits.milling()
                .withHeights(0, -s.treadDepthMm(), 0)
                .withOtherTools(
                        ToolLimits.centreCuttingPlunge().withKind("a tread engraver, given a plunge feed by the job"));
    }

    /**
     * A sole's cavity programs: the stock below the top face (z = 0), the floor the cavity depth,
     * the cavity tool a pocket cutter that does not cut at its centre (3 degrees), as the pocket
     * module's.
     */
    public static Limits soleCavity(JobSettings.SoleSettings s) {
        return Limits.milling().withHeights(0, -s.cavityDepthMm(), 0);
    }

    /**
     * Checks a robot program before its formats are written. The robot follows the toolpath, so
     * what depends on the material (entries into the stock, pilot holes drilled before, the floor)
     * is checked on the toolpath in the workpiece frame, where the stock is known, exactly as
     * {@code program.ngc} is; the robot program itself is then checked for what only it has:
     * every linear motion on the part with the spindle running in range, speeds and joint values
     * in range.
     *
     * @return the first failure, or empty
     */
    public static Optional<Failure> robot(
            org.fresa.post.RobotProgram program, org.fresa.model.Toolpath path, Limits limits) {
        java.io.StringWriter nc = new java.io.StringWriter();
        try {
            org.fresa.post.NcPosts.byName("linuxcnc").orElseThrow().write(path, "robot", nc);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
        Optional<Failure> onPath =
                ProgramCheck.of(nc.toString(), NcDialect.LINUXCNC, limits).failure();
        if (onPath.isPresent()) {
            Failure f = onPath.get();
            return Optional.of(new Failure(
                    f.line(), "the toolpath the robot follows, " + f.where(), f.text(), f.rule(), f.reason()));
        }
        // the entries were checked on the path: here each tool may go along its axis
        Map<String, Integer> tools = new HashMap<>();
        Limits onRobot = limits.withStock(Limits.Stock.UNKNOWN).withFloor(Double.NaN, 0);
        for (ToolpathSection s : path.sections()) {
            tools.putIfAbsent(s.label(), s.toolNumber());
            onRobot = onRobot.withTool(
                    s.toolNumber(),
                    ToolLimits.centreCuttingPlunge()
                            .withKind("entries checked on the toolpath")
                            .withRadiusMm(s.toolDiameterMm() / 2));
        }
        return ProgramCheck.of(program, onRobot, tools).failure();
    }

    /** Most samples of one joint motion: a degree (or millimetre) of its largest joint travel each. */
    static final int MAX_JOINT_SAMPLES = 3600;

    /** How far below its lower end a joint motion's tool tip may pass over the stock (mm). */
    static final double JOINT_DIP_MM = 0.01;

    /**
     * The robot's joint motions (MoveAbsJ, PTP) against the stock. The controller interpolates
     * the joints, not the tool tip, so between two points the tip leaves the straight line the
     * toolpath's check judged; on a six-axis arm it can swing down by tens of millimetres. Each
     * joint motion is sampled every degree (or millimetre) of the joint that travels most, the tip
     * taken to the workpiece's frame. A sample where the tool (its radius included) is inside the
     * stock's box, below its top, is refused by the {@code rapid} rule with the place, when both
     * ends are over the stock's top (the straight link was in the air), or when the sample is
     * below both ends by more than {@link #JOINT_DIP_MM} (an end in a cleared pocket: below its
     * ends, the material is not what an earlier cut removed for the ends' straight link; a swing
     * sideways at the ends' height there is not judged). Nothing is stated where the stock has no
     * top.
     *
     * @param robotOf the robot with each workingstep's tool frame, by the workingstep's label
     * @param robotToPiece the workpiece's frame in the robot's base frame
     * @param tools each workingstep's tool number (its section's)
     * @return the first joint motion that dips into the stock, or empty
     */
    public static Optional<Failure> jointMotions(
            org.fresa.post.RobotProgram program,
            java.util.function.Function<String, org.fresa.kin.Robot> robotOf,
            Transform3 robotToPiece,
            Limits limits,
            Map<String, Integer> tools) {
        Limits.Stock stock = limits.stock();
        if (!Double.isFinite(stock.maxZMm())) {
            return Optional.empty();
        }
        Transform3 toPiece = robotToPiece.inverse();
        List<org.fresa.post.RobotProgram.Motion> ms = program.motions();
        for (int i = 1; i < ms.size(); i++) {
            org.fresa.post.RobotProgram.Motion m = ms.get(i);
            org.fresa.post.RobotProgram.Motion before = ms.get(i - 1);
            if (m.type() != org.fresa.post.RobotProgram.MotionType.JOINT
                    || m.jointValues().size() != before.jointValues().size()) {
                continue;
            }
            org.fresa.kin.Robot robot = robotOf.apply(m.workingstep());
            double[] q0 = before.jointValues().stream()
                    .mapToDouble(Double::doubleValue)
                    .toArray();
            double[] q1 =
                    m.jointValues().stream().mapToDouble(Double::doubleValue).toArray();
            double travel = 0;
            for (int j = 0; j < q0.length; j++) {
                travel = Math.max(travel, Math.abs(q1[j] - q0[j]));
            }
            int n = (int) Math.min(MAX_JOINT_SAMPLES, Math.max(1, Math.ceil(travel)));
            Vec3 a = toPiece.applyToPoint(robot.forward(q0).translationPart());
            Vec3 b = toPiece.applyToPoint(robot.forward(q1).translationPart());
            double low = Math.min(a.z(), b.z()) - JOINT_DIP_MM;
            // ends over the stock's top: the straight link was in the air, and so must the tip be
            boolean above = low + JOINT_DIP_MM >= stock.maxZMm();
            double radius = limits.tool(tools.getOrDefault(m.workingstep(), 0)).radiusMm();
            double[] q = new double[q0.length];
            for (int k = 1; k < n; k++) {
                double t = (double) k / n;
                for (int j = 0; j < q.length; j++) {
                    q[j] = q0[j] + t * (q1[j] - q0[j]);
                }
                Vec3 tip = toPiece.applyToPoint(robot.forward(q).translationPart());
                if ((above || tip.z() < low) && stock.touches(tip, radius, 0)) {
                    return Optional.of(new Failure(
                            m.index(),
                            "motion " + m.index(),
                            "joint motion in workingstep " + m.workingstep(),
                            new org.fresa.check.RapidRule(),
                            "the joints' interpolation swings the tool tip down to Z " + mm(tip.z())
                                    + " mm at X " + mm(tip.x()) + " Y " + mm(tip.y()) + " (in the workpiece's frame), "
                                    + mm(Math.min(a.z(), b.z()) - tip.z()) + " mm below the motion's ends and "
                                    + mm(stock.maxZMm() - tip.z()) + " mm below the stock's top Z "
                                    + mm(stock.maxZMm()) + " mm: the straight link between its ends is not what the"
                                    + " robot does"));
                }
            }
        }
        return Optional.empty();
    }

    private static String mm(double v) {
        return org.fresa.model.ExactDecimal.of(Math.round(v * 1e3) / 1e3 + 0.0);
    }

    /**
     * A STEP-NC milling cutter as the user's entry choices say: straight down only for a cutter
     * said to cut at its centre and asked to plunge (or left to, with {@code auto}), as the pocket
     * module's; otherwise the entry angle asked for (3 degrees by default).
     */
    static ToolLimits cutter(org.fresa.pocket.EntryRule e) {
        if (e.centreCutting()
                && (e.kind() == org.fresa.pocket.EntryRule.Kind.PLUNGE
                        || e.kind() == org.fresa.pocket.EntryRule.Kind.AUTO)) {
            return ToolLimits.centreCuttingPlunge();
        }
        if (e.equals(org.fresa.pocket.EntryRule.DEFAULT)) {
            return ToolLimits.notCentreCutting();
        }
        return new ToolLimits(
                e.angleDeg(),
                false,
                e.centreCutting() ? "a centre-cutting cutter asked to ramp" : "a cutter not cutting at its centre",
                0);
    }

    /** The dialect of a post's name ({@code linuxcnc}, ..., {@code 7m-compat}). */
    public static NcDialect dialect(String post) {
        return NcDialect.byPost(post).orElseThrow(() -> new IllegalArgumentException("no dialect for post " + post));
    }

    /**
     * A STEP-NC program's limits: each tool as its operations use it (drills, reamers, taps and
     * boring bars straight down; milling cutters as the entry choices say, {@link #cutter}), the stock
     * the workpiece's block when the file gives one (the floor its bottom, with the deepest through
     * allowance of the planned tools below it: a drill's point or a cutter's edge radius, plus the
     * breakthrough the planner was given), otherwise unbounded with no floor.
     */
    public static Limits stepnc(
            StepNcProgram program, ToolpathPlanner.Plan plan, org.fresa.toolpath.PlanningChoices choices) {
        Map<Long, MachiningWorkingstep> byId = new HashMap<>();
        for (MachiningWorkingstep w : program.workingsteps()) {
            byId.put(w.instanceId(), w);
        }
        StepNcLimits limits = new StepNcLimits(program, choices);
        List<ToolpathSection> sections = plan.toolpath().sections();
        for (int i = 0; i < sections.size() && i < plan.steps().size(); i++) {
            limits.add(byId.get(plan.steps().get(i).workingstepInstanceId()), sections.get(i));
        }
        return limits.limits();
    }

    /**
     * {@link #stepnc}'s limits gathered a section at a time, as a program too long to hold whole is
     * planned and written: what each section adds is its tool, its through allowance and, for a
     * file without a workpiece block, how far its cuts reach.
     */
    public static final class StepNcLimits {
        private final StepNcProgram program;
        private final org.fresa.toolpath.PlanningChoices choices;
        private Limits l = Limits.milling();
        private double allowanceMm;
        // how far the cuts of the sections other than planar faces reach, for statedStock
        private double cutMinX = Double.POSITIVE_INFINITY;
        private double cutMinY = Double.POSITIVE_INFINITY;
        private double cutMaxX = Double.NEGATIVE_INFINITY;
        private double cutMaxY = Double.NEGATIVE_INFINITY;

        public StepNcLimits(StepNcProgram program, org.fresa.toolpath.PlanningChoices choices) {
            this.program = program;
            this.choices = choices;
            this.allowanceMm = choices.breakthroughMm();
        }

        /**
         * A section of the program, in order.
         *
         * @param w its workingstep, or null when it is not one of the program's
         */
        public void add(MachiningWorkingstep w, ToolpathSection s) {
            boolean axial = w != null && AXIAL.contains(w.operation().type());
            // the thesis's paths go straight down into every layer (its robots were simulated, not
            // cutting): they can only be run with a cutter that cuts at its centre, declared so
            ToolLimits t = axial
                    ? ToolLimits.drill()
                    : choices.paths() == org.fresa.toolpath.PathConvention.THESIS
                            ? ToolLimits.centreCuttingPlunge()
                                    .withKind(
                                            "the thesis's paths' cutter, declared centre-cutting: they plunge into every layer")
                            : cutter(choices.entry());
            l = l.withTool(s.toolNumber(), t.withRadiusMm(s.toolDiameterMm() / 2));
            if (w != null) {
                allowanceMm = Math.max(
                        allowanceMm,
                        ToolpathPlanner.throughAllowanceMm(
                                w.operation(), s.toolDiameterMm(), choices.breakthroughMm()));
            }
            if (w != null && w.feature().type() == org.fresa.stepnc.Feature.FeatureType.PLANAR_FACE) {
                return;
            }
            for (org.fresa.model.Move m : s.moves()) {
                // an arc reaches at most its radius from its centre
                double reach = m instanceof org.fresa.model.Move.Circular c
                        ? c.end().minus(c.center()).norm()
                        : 0;
                Vec3 at = m instanceof org.fresa.model.Move.Circular c ? c.center() : m.end();
                if (m instanceof org.fresa.model.Move.Linear || m instanceof org.fresa.model.Move.Circular) {
                    cutMinX = Math.min(cutMinX, at.x() - reach);
                    cutMinY = Math.min(cutMinY, at.y() - reach);
                    cutMaxX = Math.max(cutMaxX, at.x() + reach);
                    cutMaxY = Math.max(cutMaxY, at.y() + reach);
                }
            }
        }

        /** The limits of the sections added. */
        public Limits limits() {
            Optional<Workpiece.Block> block = program.workpieces().size() == 1
                    ? program.workpieces().get(0).block()
                    : Optional.empty();
            if (block.isPresent()) {
                Limits.Stock stock = box(block.get());
                return l.withStock(stock).withFloor(stock.minZMm(), allowanceMm);
            }
            return l.withStock(statedStock(program, cutMinX, cutMinY, cutMaxX, cutMaxY));
        }
    }

    /**
     * The stock of a file that gives no workpiece block, as far as the file states it: its planar
     * faces' removal boundaries (the part's top, machined flat), grown over every point another
     * workingstep cuts (material is wherever a feature is cut, the cuts reaching from cutMinX to
     * cutMaxX and cutMinY to cutMaxY), from below up to the highest feature's top. Outside it a
     * descent is in the air (a face's passes start beyond its boundary). A file with no planar
     * face states no top: the stock is unknown and every descent counts.
     */
    static Limits.Stock statedStock(
            StepNcProgram program, double cutMinX, double cutMinY, double cutMaxX, double cutMaxY) {
        double minX = Double.POSITIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        double top = Double.NEGATIVE_INFINITY;
        boolean face = false;
        for (MachiningWorkingstep w : program.workingsteps()) {
            org.fresa.stepnc.Feature f = w.feature();
            Transform3 place = f.placement();
            top = Math.max(top, place.applyToPoint(Vec3.ZERO).z());
            if (f.type() != org.fresa.stepnc.Feature.FeatureType.PLANAR_FACE) {
                continue;
            }
            org.fresa.geom.Box2 b;
            try {
                b = ToolpathPlanner.faceBoundary(f);
            } catch (IllegalArgumentException | UnsupportedOperationException e) {
                return Limits.Stock.UNKNOWN;
            }
            face = true;
            for (Vec3 c : List.of(
                    new Vec3(b.minX(), b.minY(), 0),
                    new Vec3(b.maxX(), b.minY(), 0),
                    new Vec3(b.maxX(), b.maxY(), 0),
                    new Vec3(b.minX(), b.maxY(), 0))) {
                Vec3 p = place.applyToPoint(c);
                minX = Math.min(minX, p.x());
                minY = Math.min(minY, p.y());
                maxX = Math.max(maxX, p.x());
                maxY = Math.max(maxY, p.y());
            }
        }
        if (!face || !Double.isFinite(top)) {
            return Limits.Stock.UNKNOWN;
        }
        return new Limits.Stock(
                Math.min(minX, cutMinX),
                Math.min(minY, cutMinY),
                Double.NEGATIVE_INFINITY,
                Math.max(maxX, cutMaxX),
                Math.max(maxY, cutMaxY),
                top);
    }

    /** The block's bounding box in the workpiece frame. */
    static Limits.Stock box(Workpiece.Block b) {
        double[] min = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] max = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        Transform3 t = b.placement();
        for (int k = 0; k < 8; k++) {
            Vec3 c = t.applyToPoint(new Vec3((k & 1) * b.xMm(), ((k >> 1) & 1) * b.yMm(), ((k >> 2) & 1) * b.zMm()));
            double[] v = {c.x(), c.y(), c.z()};
            for (int i = 0; i < 3; i++) {
                min[i] = Math.min(min[i], v[i]);
                max[i] = Math.max(max[i], v[i]);
            }
        }
        return new Limits.Stock(min[0], min[1], min[2], max[0], max[1], max[2]);
    }
}
