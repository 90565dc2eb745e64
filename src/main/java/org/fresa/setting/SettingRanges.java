package org.fresa.setting;

import org.fresa.cutting.CuttingOptions;
import org.fresa.model.CamInputException;
import org.fresa.model.Placement;
import org.fresa.post.PocketPost;
import org.fresa.robot.RobotFormat;

/**
 * The ranges of every numeric setting and the choices of every enumerated one
 * ({@link SettingChoice}), one holder per module: the commands check their options against them
 * before any work, {@link org.fresa.job.JobXml} checks the job file's attributes against the same ranges and
 * choices, so that a job file cannot bring a value the option refuses.
 *
 * <p>The bounds are what a workshop meets, with room to spare: a machine travels at most 10 m
 * each way, a robot cell is at most 100 m across, spindles turn 1 to 100 000 rpm and feeds run
 * 0.1 to 100 000 mm/min (the program check's machine range), a cutter is 0.01 mm to 1 m across.
 * Counts are bounded so that no run holds more than about a million moves or figures.
 */
public final class SettingRanges {

    /** Largest coordinate on a machine tool, either way (mm). */
    public static final double MACHINE_TRAVEL_MM = 10_000;
    /** Largest coordinate of a frame in a robot cell, either way (mm), as the Position tab allows. */
    public static final double CELL_SIZE_MM = 100_000;
    /** Largest rotation of a frame, either way (deg). */
    public static final double TURN_DEG = 360;
    /** Slowest and fastest spindle (rpm). */
    public static final double MIN_SPINDLE_RPM = 1;

    public static final double MAX_SPINDLE_RPM = 100_000;
    /** Slowest and fastest feed (mm/min). */
    public static final double MIN_FEED_MM_PER_MIN = 0.1;

    public static final double MAX_FEED_MM_PER_MIN = 100_000;

    private SettingRanges() {}

    private static SettingRange spindle(String option, String attribute) {
        return SettingRange.of(option, attribute, MIN_SPINDLE_RPM, MAX_SPINDLE_RPM, "rpm");
    }

    private static SettingRange feed(String option, String attribute) {
        return SettingRange.of(option, attribute, MIN_FEED_MM_PER_MIN, MAX_FEED_MM_PER_MIN, "mm/min");
    }

    private static SettingRange coordinate(String option, String attribute) {
        return SettingRange.of(option, attribute, -MACHINE_TRAVEL_MM, MACHINE_TRAVEL_MM, "mm");
    }

    private static SettingRange angle(String option, String attribute) {
        return SettingRange.of(option, attribute, -TURN_DEG, TURN_DEG, "deg");
    }

    /** {@code fresa toolpath}, {@code fresa robot} and the job's {@code <stepnc>}. */
    public static final class StepNc {
        /** How far a through hole's tool passes its exit. */
        public static final SettingRange BREAKTHROUGH = SettingRange.of(
                "--breakthrough", "breakthroughMm", 0, org.fresa.toolpath.PlanningChoices.MAX_BREAKTHROUGH_MM, "mm");

        public static final SettingChoice<org.fresa.post.MillingPost> POST =
                SettingChoice.of("--post", "post", org.fresa.post.MillingPost.class, org.fresa.post.MillingPost::word);
        /** Steepest descent of a pocket's helix or ramp entry, as the pocket module's. */
        public static final SettingRange ENTRY_ANGLE =
                SettingRange.of("--entry-angle", "entryAngleDeg", 0.5, 90, "deg");

        private StepNc() {}

        /**
         * Whose path conventions a word names ({@code --paths}, the job's {@code paths}): one of
         * the known words, else bad input naming them.
         */
        public static org.fresa.toolpath.PathConvention paths(String source, String word)
                throws org.fresa.model.CamInputException {
            return org.fresa.toolpath.PathConvention.byWord(word)
                    .orElseThrow(() -> new org.fresa.model.CamInputException(
                            source, "unknown path conventions '" + word + "': expected fresa or thesis"));
        }
    }

    /** {@code fresa pocket} and the job's {@code <pocket>}. */
    public static final class Pocket {
        public static final SettingRange TOOL_DIAMETER =
                SettingRange.of("--tool-diameter", "toolDiameterMm", 0.01, 1000, "mm");
        public static final SettingRange CUT = SettingRange.above("--cut", "cutFraction", 0, 1, "");
        public static final SettingRange FINISH = SettingRange.of("--finish", "finishFraction", 0, 0.5, "");
        public static final SettingRange Z_TOP = coordinate("--z-top", "zTopMm");
        public static final SettingRange Z_BOTTOM = coordinate("--z-bottom", "zBottomMm");
        /** At least 1 um, no machine steps finer; the planner also refuses more than 10^6 layers. */
        public static final SettingRange MAX_DEPTH =
                SettingRange.of("--max-depth", "maxDepthPerPassMm", 0.001, 1000, "mm");

        public static final SettingRange SPINDLE = spindle("--rpm", "spindleRpm");
        public static final SettingRange FEED = feed("--feed", "feedMmPerMin");
        public static final SettingRange FINISH_FEED = feed("--finish-feed", "finishFeedMmPerMin");
        /** Steepest descent of a helix or ramp entry: below half a degree a ramp is no entry, 90 is a plunge. */
        public static final SettingRange ENTRY_ANGLE =
                SettingRange.of("--entry-angle", "entryAngleDeg", 0.5, 90, "deg");

        public static final SettingChoice<PocketPost> POST =
                SettingChoice.of("--post", "post", PocketPost.class, PocketPost::word);
        public static final SettingChoice<org.fresa.pocket.MillingDirection> DIRECTION = SettingChoice.of(
                "--direction",
                "direction",
                org.fresa.pocket.MillingDirection.class,
                org.fresa.pocket.MillingDirection::word);
        public static final SettingChoice<org.fresa.pocket.EntryRule.Kind> ENTRY = SettingChoice.of(
                "--entry", "entry", org.fresa.pocket.EntryRule.Kind.class, org.fresa.pocket.EntryRule.Kind::word);
        public static final SettingChoice<org.fresa.pocket.PocketStrategy.Kind> STRATEGY = SettingChoice.of(
                "--strategy",
                "strategy",
                org.fresa.pocket.PocketStrategy.Kind.class,
                org.fresa.pocket.PocketStrategy.Kind::word);
        public static final SettingChoice<org.fresa.pocket.PocketStrategy.Order> ORDER = SettingChoice.of(
                "--order",
                "order",
                org.fresa.pocket.PocketStrategy.Order.class,
                org.fresa.pocket.PocketStrategy.Order::word);
        /** Stock left on walls and floor: a roughing allowance of up to 10 mm. */
        public static final SettingRange STOCK_TO_LEAVE = SettingRange.of(
                "--stock-to-leave", "stockToLeaveMm", 0, org.fresa.pocket.PocketStrategy.MAX_STOCK_TO_LEAVE_MM, "mm");
        /** The zigzag lines' direction from +X: a half turn either way covers every direction, both senses. */
        public static final SettingRange ANGLE = SettingRange.of(
                "--angle",
                "angleDeg",
                -org.fresa.pocket.PocketStrategy.MAX_ANGLE_DEG,
                org.fresa.pocket.PocketStrategy.MAX_ANGLE_DEG,
                "deg");

        private Pocket() {}
    }

    /** {@code fresa cut} and the job's {@code <cutting>}. */
    public static final class Cutting {
        public static final SettingRange KERF =
                SettingRange.of("--kerf", "kerfMm", 0, CuttingOptions.MAX_KERF_MM, "mm");
        public static final SettingRange LEAD_IN =
                SettingRange.of("--lead-in", "leadInMm", 0, CuttingOptions.MAX_LEAD_MM, "mm");
        public static final SettingRange LEAD_OUT =
                SettingRange.of("--lead-out", "leadOutMm", 0, CuttingOptions.MAX_LEAD_MM, "mm");
        /** The command line's tolerance is in drawing units, the job file's in mm: 10 of either. */
        public static final SettingRange TOLERANCE = SettingRange.of("--tolerance", "toleranceMm", 0, 10, "");

        public static final SettingRange OVERCUT =
                SettingRange.of("--overcut", "overcutMm", 0, CuttingOptions.MAX_LEAD_MM, "mm");
        /**
         * A point of the planner's cut order (a contour's reference point or its start), on the
         * machine; job files only (the tab checks what it takes).
         */
        public static final SettingRange CUT_X = coordinate("", "xMm");

        public static final SettingRange CUT_Y = coordinate("", "yMm");
        public static final SettingRange START_X = coordinate("", "startXMm");
        public static final SettingRange START_Y = coordinate("", "startYMm");
        public static final SettingChoice<org.fresa.cutting.CutProcess> PROCESS = SettingChoice.of(
                "--process", "process", org.fresa.cutting.CutProcess.class, org.fresa.cutting.CutProcess::id);
        public static final SettingChoice<org.fresa.cutting.LeadShape> LEAD = SettingChoice.of(
                "--lead", "lead", org.fresa.cutting.LeadShape.class, org.fresa.cutting.LeadShape::word);
        public static final SettingChoice<org.fresa.dxf.DrawingUnits> UNITS = SettingChoice.of(
                "--units",
                "units",
                org.fresa.dxf.DrawingUnits.class,
                org.fresa.dxf.DrawingUnits::word,
                org.fresa.dxf.DrawingUnits::of);
        public static final SettingChoice<org.fresa.post.CuttingPost> POST =
                SettingChoice.of("--post", "post", org.fresa.post.CuttingPost.class, org.fresa.post.CuttingPost::id);
        public static final SettingChoice<org.fresa.cutting.KerfCompensation> COMPENSATION = SettingChoice.of(
                "--compensation",
                "compensation",
                org.fresa.cutting.KerfCompensation.class,
                org.fresa.cutting.KerfCompensation::word);
        public static final SettingChoice<org.fresa.cutting.CutSense> OUTER_DIRECTION = SettingChoice.of(
                "--outer-direction",
                "outerDirection",
                org.fresa.cutting.CutSense.class,
                org.fresa.cutting.CutSense::word);
        public static final SettingChoice<org.fresa.cutting.CutSense> HOLE_DIRECTION = SettingChoice.of(
                "--hole-direction",
                "holeDirection",
                org.fresa.cutting.CutSense.class,
                org.fresa.cutting.CutSense::word);

        private Cutting() {}
    }

    /** {@code fresa grade} and the job's {@code <grading>}. */
    public static final class Grading {
        /** The size system's own limits ({@code grading.SizeSystem}) are checked when the plan is made. */
        public static final SettingRange BASE_SIZE = SettingRange.above("--base-size", "baseSize", 0, 1000, "");

        public static final SettingRange LENGTH_STEP =
                SettingRange.above("--length-step", "lengthStepMm", 0, 100, "mm");
        public static final SettingRange WIDTH_STEP = SettingRange.of("--width-step", "widthStepMm", 0, 100, "mm");
        public static final SettingRange ORIGIN_X = coordinate("--origin", "originXMm");
        public static final SettingRange ORIGIN_Y = coordinate("--origin", "originYMm");
        public static final SettingRange SHRINKAGE = SettingRange.below("--shrinkage", "shrinkage", 0, 0.5, "");
        public static final SettingRange LENGTH_AXIS = angle("--length-axis", "lengthAxisDeg");
        public static final SettingRange COORDINATION =
                SettingRange.above("--coordination", "coordinationMm", 0, 5000, "mm");
        public static final SettingRange HEEL_GROUP =
                SettingRange.wholeNumbers("--heel-group", "heelGroup", 1, 400, "sizes");
        public static final SettingChoice<org.fresa.grading.SizeSystem> SYSTEM = SettingChoice.of(
                "--system", "system", org.fresa.grading.SizeSystem.class, org.fresa.grading.SizeSystem::id);
        public static final SettingChoice<org.fresa.grading.ShrinkageMode> SHRINKAGE_MODE = SettingChoice.of(
                "--shrinkage-mode",
                "shrinkageMode",
                org.fresa.grading.ShrinkageMode.class,
                org.fresa.grading.ShrinkageMode::id);

        private Grading() {}
    }

    /** The placements of {@code fresa robot} ({@code --robot-table}, {@code --table-piece}) and the job's {@code <robot>}. */
    public static final class Robot {
        private static final String[] ATTRIBUTES = {"xMm", "yMm", "zMm", "rxDeg", "ryDeg", "rzDeg"};
        /** Largest spindle offset from the flange and longest tool (mm): a tool is held, not a boom. */
        public static final double MAX_TOOL_MM = 5000;
        /** {@code --tool-length} and the job's {@code toolLengthMm}: from the spindle nose to the tip. */
        public static final SettingRange TOOL_LENGTH =
                SettingRange.of("--tool-length", "toolLengthMm", 0, MAX_TOOL_MM, "mm");
        /** {@code --tolerance-mm} of {@code fresa ik}: 1e-12 mm (below it doubles cannot tell) to 1 mm. */
        public static final SettingRange IK_TOLERANCE =
                SettingRange.of("--tolerance-mm", "toleranceMm", 1e-12, 1, "mm");
        /** One format of {@code --formats} and of the job's {@code formats} list. */
        public static final SettingChoice<RobotFormat> FORMAT =
                SettingChoice.of("--formats", "formats", RobotFormat.class, RobotFormat::word);
        /** {@code --method} of {@code fresa ik}: the project's solver ({@code default}) or the thesis's. */
        public static final SettingChoice<org.fresa.kin.IkOptions.Method> IK_METHOD = SettingChoice.of(
                "--method",
                "method",
                org.fresa.kin.IkOptions.Method.class,
                m -> m == org.fresa.kin.IkOptions.Method.THESIS_DLS ? "thesis-dls" : "default");

        private Robot() {}

        /** The range of one value of a placement: x, y, z (mm) or rx, ry, rz (deg). */
        public static SettingRange placement(String option, int index) {
            String attribute = ATTRIBUTES[index];
            return index < 3
                    ? SettingRange.of(option, attribute, -CELL_SIZE_MM, CELL_SIZE_MM, "mm")
                    : angle(option, attribute);
        }

        /**
         * The placement, when every value is in range.
         *
         * @throws CamInputException naming the option and the value
         */
        public static Placement check(String option, Placement p) throws CamInputException {
            double[] v = {p.xMm(), p.yMm(), p.zMm(), p.rxDeg(), p.ryDeg(), p.rzDeg()};
            for (int i = 0; i < v.length; i++) {
                SettingRange r = placement(option, i);
                if (!r.contains(v[i])) {
                    throw new CamInputException(
                            option, ATTRIBUTES[i].replaceAll("(Mm|Deg)$", "") + ": " + r.problem(v[i]));
                }
            }
            return p;
        }

        /**
         * The spindle nose in the flange frame ({@code --spindle}), when each offset is within
         * {@link #MAX_TOOL_MM} and each angle within a turn.
         *
         * @throws CamInputException naming the option and the value
         */
        public static Placement checkSpindle(String option, Placement p) throws CamInputException {
            double[] v = {p.xMm(), p.yMm(), p.zMm(), p.rxDeg(), p.ryDeg(), p.rzDeg()};
            for (int i = 0; i < v.length; i++) {
                SettingRange r = spindle(option, i);
                if (!r.contains(v[i])) {
                    throw new CamInputException(
                            option, ATTRIBUTES[i].replaceAll("(Mm|Deg)$", "") + ": " + r.problem(v[i]));
                }
            }
            return p;
        }

        /**
         * Reads {@code --spindle X,Y,Z[,RX,RY,RZ]}: the spindle nose in the flange frame (mm, deg;
         * R = Rz*Ry*Rx), each value within {@link #checkSpindle}'s ranges.
         *
         * @throws org.fresa.model.CamInputException naming the option when the text is not 3 to 6 numbers in range
         */
        public static Placement parseSpindle(String text) throws org.fresa.model.CamInputException {
            double[] v = numbers("--spindle", text, 3, 6);
            return checkSpindle(
                    "--spindle",
                    new Placement(
                            v[0],
                            v[1],
                            v[2],
                            v.length > 3 ? v[3] : 0,
                            v.length > 4 ? v[4] : 0,
                            v.length > 5 ? v[5] : 0));
        }

        /**
         * The comma-separated numbers of an option or a field ({@code X,Y,Z[,...]}), between {@code
         * min} and {@code max} of them, each finite.
         *
         * @throws org.fresa.model.CamInputException naming the option when the text is not that
         */
        public static double[] numbers(String option, String text, int min, int max)
                throws org.fresa.model.CamInputException {
            String[] parts = text.split(",", -1);
            if (parts.length < min || parts.length > max) {
                throw new org.fresa.model.CamInputException(
                        option, "expected " + min + " to " + max + " comma-separated numbers, got '" + text + "'");
            }
            double[] v = new double[parts.length];
            for (int i = 0; i < parts.length; i++) {
                try {
                    v[i] = Double.parseDouble(parts[i].trim());
                } catch (NumberFormatException e) {
                    v[i] = Double.NaN;
                }
                if (!Double.isFinite(v[i])) {
                    throw new org.fresa.model.CamInputException(
                            option, "value " + (i + 1) + " is not a number: '" + parts[i].trim() + "'");
                }
            }
            return v;
        }

        /** {@link #checkSpindle} for a job file's spindle element. */
        public static Placement requireSpindle(Placement p) {
            double[] v = {p.xMm(), p.yMm(), p.zMm(), p.rxDeg(), p.ryDeg(), p.rzDeg()};
            for (int i = 0; i < v.length; i++) {
                spindle("", i).require(v[i]);
            }
            return p;
        }

        private static SettingRange spindle(String option, int index) {
            return index < 3
                    ? SettingRange.of(option, ATTRIBUTES[index], -MAX_TOOL_MM, MAX_TOOL_MM, "mm")
                    : angle(option, ATTRIBUTES[index]);
        }

        /** {@link #check} for a job file's placement element. */
        public static Placement require(Placement p) {
            double[] v = {p.xMm(), p.yMm(), p.zMm(), p.rxDeg(), p.ryDeg(), p.rzDeg()};
            for (int i = 0; i < v.length; i++) {
                placement("", i).require(v[i]);
            }
            return p;
        }
    }

    /**
     * The numbers of a robot file ({@code schemas/robot.xsd}): a robot at most {@link #CELL_SIZE_MM}
     * across, angles within two turns either way (the Robot tab's rule), so that no product of
     * them overflows in the kinematics.
     */
    public static final class RobotFile {
        /** Joint angles, DH twists and offsets (deg), either way. */
        public static final double MAX_JOINT_DEG = 720;

        public static final SettingRange A = SettingRange.of("", "a", -CELL_SIZE_MM, CELL_SIZE_MM, "mm");
        public static final SettingRange D = SettingRange.of("", "d", -CELL_SIZE_MM, CELL_SIZE_MM, "mm");
        public static final SettingRange ALPHA = SettingRange.of("", "alpha", -MAX_JOINT_DEG, MAX_JOINT_DEG, "deg");
        public static final SettingRange THETA = SettingRange.of("", "theta", -MAX_JOINT_DEG, MAX_JOINT_DEG, "deg");
        public static final SettingRange BASE_RADIUS = SettingRange.above("", "baseRadius", 0, CELL_SIZE_MM, "mm");
        public static final SettingRange PLATFORM_RADIUS =
                SettingRange.above("", "platformRadius", 0, CELL_SIZE_MM, "mm");
        public static final SettingRange CENTRE_OFFSET = SettingRange.of("", "centreOffset", 0, CELL_SIZE_MM, "mm");
        public static final SettingRange EFFECTOR_LENGTH = SettingRange.of("", "effectorLength", 0, CELL_SIZE_MM, "mm");
        private static final String[] TOOL = {"x", "y", "z", "rx", "ry", "rz"};

        private RobotFile() {}

        /** A joint limit ({@code min} or {@code max}): deg for a revolute joint, mm for a prismatic one. */
        public static SettingRange limit(String attribute, boolean revolute) {
            return revolute
                    ? SettingRange.of("", attribute, -MAX_JOINT_DEG, MAX_JOINT_DEG, "deg")
                    : SettingRange.of("", attribute, -CELL_SIZE_MM, CELL_SIZE_MM, "mm");
        }

        /** One value of the tool frame: x, y, z (mm) or rx, ry, rz (deg). */
        public static SettingRange tool(int index) {
            return index < 3
                    ? SettingRange.of("", TOOL[index], -CELL_SIZE_MM, CELL_SIZE_MM, "mm")
                    : angle("", TOOL[index]);
        }
    }

    /** The job's {@code <sole>}, its tools, designs and copies (no command-line options: {@code fresa sole JOB}). */
    public static final class Sole {
        public static final SettingRange BASE_SIZE = SettingRange.above("", "baseSize", 0, 1000, "");
        public static final SettingRange ORIGIN_X = coordinate("", "originXMm");
        public static final SettingRange ORIGIN_Y = coordinate("", "originYMm");
        public static final SettingRange SHRINKAGE = SettingRange.below("", "shrinkage", 0, 0.5, "");
        public static final SettingRange CAVITY_DEPTH = SettingRange.above("", "cavityDepthMm", 0, 1000, "mm");
        public static final SettingRange TREAD_DEPTH = SettingRange.above("", "treadDepthMm", 0, 1000, "mm");
        public static final SettingRange CLEARANCE = SettingRange.above("", "clearanceMm", 0, 1000, "mm");
        public static final SettingRange MARGIN = SettingRange.of("", "marginMm", 0, 1000, "mm");
        public static final SettingRange TOOL_NUMBER = SettingRange.wholeNumbers("", "number", 0, 9999, "");
        public static final SettingRange TOOL_DIAMETER = SettingRange.of("", "diameterMm", 0.01, 1000, "mm");
        public static final SettingRange TOOL_SPINDLE = spindle("", "spindleRpm");
        public static final SettingRange TOOL_FEED = feed("", "feedMmPerMin");
        public static final SettingRange TOOL_PLUNGE_FEED = feed("", "plungeFeedMmPerMin");
        /** Copies of a design: count by rows at most 10^4 figures (checked by the sole service). */
        public static final SettingRange COUNT = SettingRange.wholeNumbers("", "count", 1, 10_000, "");

        public static final SettingRange ROWS = SettingRange.wholeNumbers("", "rows", 1, 10_000, "");
        public static final SettingRange DX = coordinate("", "dxMm");
        public static final SettingRange DY = coordinate("", "dyMm");
        public static final SettingRange ROW_SHIFT = coordinate("", "rowShiftMm");
        public static final SettingRange STEP = angle("", "stepDeg");
        public static final SettingRange CENTER_X = coordinate("", "centerXMm");
        public static final SettingRange CENTER_Y = coordinate("", "centerYMm");
        public static final SettingRange MIRROR_X = coordinate("", "mirrorXMm");
        public static final SettingRange MIRROR_Y = coordinate("", "mirrorYMm");
        public static final SettingRange ROTATE = angle("", "rotateDeg");
        public static final SettingChoice<org.fresa.sole.SizeRule> RULE =
                SettingChoice.of("", "rule", org.fresa.sole.SizeRule.class, org.fresa.sole.SizeRule::id);
        public static final SettingChoice<org.fresa.sole.PatternKind> PATTERN =
                SettingChoice.of("", "pattern", org.fresa.sole.PatternKind.class, org.fresa.sole.PatternKind::word);
        public static final SettingChoice<org.fresa.post.MillingPost> POST =
                SettingChoice.of("", "post", org.fresa.post.MillingPost.class, org.fresa.post.MillingPost::word);
        public static final SettingChoice<org.fresa.grading.SizeSystem> SYSTEM =
                SettingChoice.of("", "system", org.fresa.grading.SizeSystem.class, org.fresa.grading.SizeSystem::id);
        public static final SettingChoice<org.fresa.grading.ShrinkageMode> SHRINKAGE_MODE = SettingChoice.of(
                "", "shrinkageMode", org.fresa.grading.ShrinkageMode.class, org.fresa.grading.ShrinkageMode::id);
        /** The mould block (equations 6.1 to 6.9): a gap, fixture and block within the machine's travel. */
        public static final SettingRange BLOCK_D = SettingRange.of("", "dMm", 0, MACHINE_TRAVEL_MM, "mm");

        public static final SettingRange BLOCK_DLM = coordinate("", "dlmMm");
        public static final SettingRange BLOCK_E = coordinate("", "eMm");
        public static final SettingRange BLOCK_S = coordinate("", "sMm");
        public static final SettingRange BLOCK_CM = SettingRange.above("", "cmMm", 0, MACHINE_TRAVEL_MM, "mm");
        public static final SettingRange BLOCK_CP = SettingRange.above("", "cpMm", 0, MACHINE_TRAVEL_MM, "mm");
        public static final SettingRange BLOCK_DPI = coordinate("", "dpiMm");
        public static final SettingRange BLOCK_XTANP = coordinate("", "xtanpMm");

        private Sole() {}
    }
}
