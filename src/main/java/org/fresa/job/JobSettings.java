package org.fresa.job;

import java.nio.file.Path;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.cell.TablePlacing;
import org.fresa.cutting.CutOrderOverride;
import org.fresa.cutting.CutProcess;
import org.fresa.cutting.CutSense;
import org.fresa.cutting.CuttingOptions;
import org.fresa.cutting.KerfCompensation;
import org.fresa.cutting.LeadShape;
import org.fresa.dxf.DrawingUnits;
import org.fresa.geom.Vec2;
import org.fresa.grading.ShrinkageMode;
import org.fresa.grading.SizeSystem;
import org.fresa.model.Placement;
import org.fresa.pocket.DadContour;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.MillingDirection;
import org.fresa.pocket.PocketStrategy;
import org.fresa.pocket.PocketTechnology;
import org.fresa.post.CuttingPost;
import org.fresa.post.MillingPost;
import org.fresa.post.PocketPost;
import org.fresa.setting.SettingRanges;
import org.fresa.sole.PatternKind;
import org.fresa.sole.SizeRule;

/**
 * The settings of each module, as they appear in a job file (schemas/job.xsd) and in the tabs.
 * Paths are absolute once a job is read; they are written relative to the job file.
 */
public final class JobSettings {
    private JobSettings() {}

    /**
     * STEP-NC input, the machine-tool post used by {@code toolpath}, and the planner's choices
     * where the file is silent or doubtful ({@code toolpath} and {@code robot}).
     *
     * @param trustCuttingSpeed plan from the cutting speed where the file's spindle disagrees with it
     * @param breakthroughMm how far a through hole's tool passes its exit
     * @param entry how pockets are entered and holes milled on a helix ({@code --entry},
     *     {@code --entry-angle}, {@code --centre-cutting})
     * @param paths whose path conventions: Fresa's own or the 2016 robot thesis's
     */
    public record StepNcSettings(
            Path file,
            MillingPost post,
            boolean trustCuttingSpeed,
            double breakthroughMm,
            org.fresa.pocket.EntryRule entry,
            org.fresa.toolpath.PathConvention paths) {
        /**
         * The STEP-NC module's defaults, as {@code fresa toolpath} and {@code fresa robot}, a new
         * job and {@code schemas/job.xsd} have them; the file has none.
         */
        public static final StepNcSettings DEFAULTS = new StepNcSettings(
                Path.of(""),
                MillingPost.LINUXCNC,
                false,
                org.fresa.toolpath.PlanningChoices.DEFAULT_BREAKTHROUGH_MM,
                org.fresa.pocket.EntryRule.DEFAULT,
                org.fresa.toolpath.PathConvention.FRESA);

        public StepNcSettings {
            Objects.requireNonNull(file, "file");
            Objects.requireNonNull(post, "post");
            Objects.requireNonNull(entry, "entry");
            Objects.requireNonNull(paths, "paths");
            SettingRanges.StepNc.BREAKTHROUGH.require(breakthroughMm);
            SettingRanges.StepNc.ENTRY_ANGLE.require(entry.angleDeg());
        }

        /** The file and post with the planner's default entries and Fresa's own path conventions. */
        public StepNcSettings(Path file, MillingPost post, boolean trustCuttingSpeed, double breakthroughMm) {
            this(file, post, trustCuttingSpeed, breakthroughMm, org.fresa.pocket.EntryRule.DEFAULT);
        }

        /** These entries and Fresa's own path conventions. */
        public StepNcSettings(
                Path file,
                MillingPost post,
                boolean trustCuttingSpeed,
                double breakthroughMm,
                org.fresa.pocket.EntryRule entry) {
            this(file, post, trustCuttingSpeed, breakthroughMm, entry, org.fresa.toolpath.PathConvention.FRESA);
        }

        /** The same settings with these path conventions. */
        public StepNcSettings withPaths(org.fresa.toolpath.PathConvention p) {
            return new StepNcSettings(file, post, trustCuttingSpeed, breakthroughMm, entry, p);
        }

        /** The file and post with the planner's default choices. */
        public StepNcSettings(Path file, MillingPost post) {
            this(file, post, DEFAULTS.trustCuttingSpeed(), DEFAULTS.breakthroughMm());
        }

        /** The choices for {@link org.fresa.toolpath.ToolpathPlanner}. */
        public org.fresa.toolpath.PlanningChoices choices() {
            return new org.fresa.toolpath.PlanningChoices(trustCuttingSpeed, breakthroughMm, entry, paths);
        }
    }

    /**
     * The robot cell.
     *
     * @param robot a built-in robot name ({@code irb140}) or a robot file path
     * @param robotTable the table origin in the robot base frame
     * @param tablePiece the workpiece origin in the table frame
     * @param formats output formats, e.g. csv, xml, rapid, krl, png
     * @param spindle the spindle nose in the flange frame (x, y, z mm; rx, ry, rz deg, R = Rz Ry Rx);
     *     empty: the robot file's tool frame, or the flange
     * @param toolLengthMm the tool length from the spindle nose to the tip for every tool; empty:
     *     each STEP-NC tool's own
     */
    public record RobotSettings(
            String robot,
            Placement robotTable,
            Placement tablePiece,
            List<String> formats,
            java.util.Optional<Placement> spindle,
            java.util.OptionalDouble toolLengthMm,
            TablePlacing placing) {
        public static final List<String> DEFAULT_FORMATS = List.of("csv", "xml", "png");
        /**
         * The robot module's defaults, as {@code schemas/job.xsd}, {@code fresa robot}'s
         * {@code --formats} and a new job's Position tab have them: the IRB-140 with the table and the
         * workpiece at the robot's base, the robot file's tool frame and the STEP-NC tools' lengths.
         */
        public static final RobotSettings DEFAULTS =
                new RobotSettings("irb140", Placement.ORIGIN, Placement.ORIGIN, DEFAULT_FORMATS);

        public RobotSettings {
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(robotTable, "robotTable");
            Objects.requireNonNull(tablePiece, "tablePiece");
            formats = List.copyOf(formats);
            Objects.requireNonNull(spindle, "spindle");
            Objects.requireNonNull(toolLengthMm, "toolLengthMm");
            Objects.requireNonNull(placing, "placing");
        }

        /** The robot -> table placement as given. */
        public RobotSettings(
                String robot,
                Placement robotTable,
                Placement tablePiece,
                List<String> formats,
                java.util.Optional<Placement> spindle,
                java.util.OptionalDouble toolLengthMm) {
            this(robot, robotTable, tablePiece, formats, spindle, toolLengthMm, TablePlacing.GIVEN);
        }

        /** A cell with no spindle or tool length given. */
        public RobotSettings(String robot, Placement robotTable, Placement tablePiece, List<String> formats) {
            this(robot, robotTable, tablePiece, formats, java.util.Optional.empty(), java.util.OptionalDouble.empty());
        }
    }

    /**
     * Pocket milling technology (the 1988 thesis's data, samples/pocket/jobs.csv).
     *
     * @param post the post; {@code 7m-compat} always writes the thesis's own direction and entries
     * @param direction climb (the default: counter-clockwise around the walls with a clockwise
     *     spindle) or conventional
     * @param entry how the tool enters the material: auto (the default: a helix where it has room,
     *     else a zig-zag ramp), helix, ramp or plunge (centre-cutting tools only); {@code 7m-compat}
     *     keeps the thesis's vertical plunge
     * @param entryAngleDeg steepest descent of a helix or ramp entry (deg)
     * @param centreCutting whether the cutter cuts at its centre (may plunge)
     * @param elements the contour typed in the Pocket tab's editor, held in the job itself: when
     *     present it is the contour planned, and {@code contour} only names it (the {@code .dad}
     *     file it was opened from or is saved as); empty: the contour is read from the file
     * @param strategy how the floor is cleared: offset passes (the default), zigzag lines at an angle or
     *     adaptive walks
     */
    public record PocketSettings(
            Path contour,
            double toolDiameterMm,
            double cutFraction,
            double finishFraction,
            double zTopMm,
            double zBottomMm,
            double maxDepthPerPassMm,
            double spindleRpm,
            double feedMmPerMin,
            double finishFeedMmPerMin,
            PocketPost post,
            MillingDirection direction,
            EntryRule.Kind entry,
            double entryAngleDeg,
            boolean centreCutting,
            Optional<DadContour> elements,
            PocketStrategy strategy) {
        /**
         * The pocket module's defaults, as {@code fresa pocket}, the Pocket tab of a new job and
         * {@code schemas/job.xsd} have them. The contour and the tool diameter have none (the
         * command line and the job file must give them): a new job's tab starts with no contour and
         * this 6 mm cutter.
         */
        public static final PocketSettings DEFAULTS = new PocketSettings(
                Path.of(""),
                6,
                0.6,
                0.15,
                0,
                -5,
                2,
                3000,
                300,
                100,
                PocketPost.LINUXCNC,
                MillingDirection.CLIMB,
                EntryRule.Kind.AUTO,
                EntryRule.DEFAULT_ANGLE_DEG,
                false,
                Optional.empty(),
                PocketStrategy.DEFAULT);

        public PocketSettings {
            Objects.requireNonNull(contour, "contour");
            Objects.requireNonNull(post, "post");
            Objects.requireNonNull(direction, "direction");
            Objects.requireNonNull(entry, "entry");
            Objects.requireNonNull(elements, "elements");
            Objects.requireNonNull(strategy, "strategy");
        }

        /**
         * The entry rule of these settings.
         *
         * @throws IllegalArgumentException for an angle outside (0, 90] or a plunge asked for a tool
         *     that does not cut at its centre
         */
        public EntryRule entryRule() {
            return new EntryRule(entry, entryAngleDeg, centreCutting);
        }

        /** The same settings with other entries. */
        public PocketSettings withEntry(EntryRule.Kind kind, double angleDeg, boolean centre) {
            return with(contour, direction, kind, angleDeg, centre, elements, strategy);
        }

        /**
         * The same settings with the contour held in the job (typed in the editor); file names it.
         */
        public PocketSettings withElements(Path file, DadContour typed) {
            return with(file, direction, entry, entryAngleDeg, centreCutting, Optional.of(typed), strategy);
        }

        /** The same settings with the contour read from a file (no elements held in the job). */
        public PocketSettings withContourFile(Path file) {
            return with(file, direction, entry, entryAngleDeg, centreCutting, Optional.empty(), strategy);
        }

        /** The same settings with the thesis's technology data (tool, depths, speed and feeds). */
        public PocketSettings withTechnology(PocketTechnology t) {
            return new PocketSettings(
                    contour,
                    t.toolDiameterMm(),
                    t.cutFraction(),
                    t.finishFraction(),
                    t.zTopMm(),
                    t.zBottomMm(),
                    t.maxDepthMm(),
                    t.spindleRpm(),
                    t.feedMmPerMin(),
                    t.finishFeedMmPerMin(),
                    post,
                    direction,
                    entry,
                    entryAngleDeg,
                    centreCutting,
                    elements,
                    strategy);
        }

        /** Whether the passes are climb-milled. */
        public boolean climb() {
            return direction.climb();
        }

        /** The same settings milled in the given direction. */
        public PocketSettings withDirection(MillingDirection d) {
            return with(contour, d, entry, entryAngleDeg, centreCutting, elements, strategy);
        }

        /** The same settings with another clearing strategy. */
        public PocketSettings withStrategy(PocketStrategy s) {
            return with(contour, direction, entry, entryAngleDeg, centreCutting, elements, s);
        }

        /** The same technology and post with another contour, direction, entry or strategy. */
        private PocketSettings with(
                Path file,
                MillingDirection d,
                EntryRule.Kind kind,
                double angleDeg,
                boolean centre,
                Optional<DadContour> typed,
                PocketStrategy s) {
            return new PocketSettings(
                    file,
                    toolDiameterMm,
                    cutFraction,
                    finishFraction,
                    zTopMm,
                    zBottomMm,
                    maxDepthPerPassMm,
                    spindleRpm,
                    feedMmPerMin,
                    finishFeedMmPerMin,
                    post,
                    d,
                    kind,
                    angleDeg,
                    centre,
                    typed,
                    s);
        }
    }

    /**
     * Sheet cutting options (spec/cli.md, {@code fresa cut}).
     *
     * @param compensation software (the path is the contour offset by half the kerf) or controller
     *     (the drawn contour with G41/G42, the kerf left to the controller)
     * @param outerDirection process (the process's default), cw or ccw
     * @param holeDirection as outerDirection; process means the opposite of the outer sense
     * @param overcutMm how far each cut runs past its start before the lead-out
     * @param avoidCutParts route rapids around the parts already cut free
     * @param cutOrder the planner's own cut order and start points over the automatic ones
     *     ({@link CutOrderOverride#NONE}: the automatic order)
     */
    public record CuttingSettings(
            Path drawing,
            double kerfMm,
            CutProcess process,
            double leadInMm,
            double leadOutMm,
            LeadShape lead,
            double toleranceMm,
            DrawingUnits units,
            boolean paperMode,
            CuttingPost post,
            KerfCompensation compensation,
            CutSense outerDirection,
            CutSense holeDirection,
            double overcutMm,
            boolean avoidCutParts,
            CutOrderOverride cutOrder) {
        /**
         * The cutting module's defaults, as {@code fresa cut}, the Cutting tab of a new job and
         * {@code schemas/job.xsd} have them; the drawing has none.
         */
        public static final CuttingSettings DEFAULTS = new CuttingSettings(
                Path.of(""),
                2,
                CutProcess.PLASMA,
                3,
                1,
                LeadShape.ARC,
                CuttingOptions.DEFAULT_GAP_MM,
                DrawingUnits.AUTO,
                false,
                CuttingPost.LINUXCNC,
                KerfCompensation.SOFTWARE,
                CutSense.PROCESS,
                CutSense.PROCESS,
                0,
                true);

        public CuttingSettings {
            Objects.requireNonNull(drawing, "drawing");
            Objects.requireNonNull(process, "process");
            Objects.requireNonNull(lead, "lead");
            Objects.requireNonNull(units, "units");
            Objects.requireNonNull(post, "post");
            Objects.requireNonNull(compensation, "compensation");
            Objects.requireNonNull(outerDirection, "outerDirection");
            Objects.requireNonNull(holeDirection, "holeDirection");
            Objects.requireNonNull(cutOrder, "cutOrder");
        }

        /** The automatic cut order and start points. */
        public CuttingSettings(
                Path drawing,
                double kerfMm,
                CutProcess process,
                double leadInMm,
                double leadOutMm,
                LeadShape lead,
                double toleranceMm,
                DrawingUnits units,
                boolean paperMode,
                CuttingPost post,
                KerfCompensation compensation,
                CutSense outerDirection,
                CutSense holeDirection,
                double overcutMm,
                boolean avoidCutParts) {
            this(
                    drawing,
                    kerfMm,
                    process,
                    leadInMm,
                    leadOutMm,
                    lead,
                    toleranceMm,
                    units,
                    paperMode,
                    post,
                    compensation,
                    outerDirection,
                    holeDirection,
                    overcutMm,
                    avoidCutParts,
                    CutOrderOverride.NONE);
        }

        /** These settings with the planner's own cut order. */
        public CuttingSettings withCutOrder(CutOrderOverride o) {
            return new CuttingSettings(
                    drawing,
                    kerfMm,
                    process,
                    leadInMm,
                    leadOutMm,
                    lead,
                    toleranceMm,
                    units,
                    paperMode,
                    post,
                    compensation,
                    outerDirection,
                    holeDirection,
                    overcutMm,
                    avoidCutParts,
                    o);
        }

        /** Software compensation, the process's directions, no overcut, rapids around cut parts. */
        public CuttingSettings(
                Path drawing,
                double kerfMm,
                CutProcess process,
                double leadInMm,
                double leadOutMm,
                LeadShape lead,
                double toleranceMm,
                DrawingUnits units,
                boolean paperMode,
                CuttingPost post) {
            this(
                    drawing,
                    kerfMm,
                    process,
                    leadInMm,
                    leadOutMm,
                    lead,
                    toleranceMm,
                    units,
                    paperMode,
                    post,
                    KerfCompensation.SOFTWARE,
                    CutSense.PROCESS,
                    CutSense.PROCESS,
                    0,
                    true);
        }
    }

    /** Grading options (spec/cli.md, {@code fresa grade}); empty steps mean the system's own. */
    public record GradingSettings(
            Path outline,
            double baseSize,
            String sizes,
            boolean halfSizes,
            SizeSystem system,
            OptionalDouble lengthStepMm,
            OptionalDouble widthStepMm,
            Optional<Vec2> originMm,
            double shrinkage,
            ShrinkageMode shrinkageMode,
            Optional<HeelCoordination> coordination) {
        /**
         * The grading module's defaults, as {@code fresa grade}, the Grading tab of a new job and
         * {@code schemas/job.xsd} have them; the outline has none, and the command line asks for
         * the base size, the sizes and the system.
         */
        public static final GradingSettings DEFAULTS = new GradingSettings(
                Path.of(""),
                40,
                "36-44",
                false,
                SizeSystem.BR,
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                Optional.empty(),
                0,
                ShrinkageMode.MULTIPLICATIVE,
                Optional.empty());

        public GradingSettings {
            Objects.requireNonNull(outline, "outline");
            Objects.requireNonNull(sizes, "sizes");
            Objects.requireNonNull(system, "system");
            Objects.requireNonNull(lengthStepMm, "lengthStepMm");
            Objects.requireNonNull(widthStepMm, "widthStepMm");
            Objects.requireNonNull(originMm, "originMm");
            Objects.requireNonNull(shrinkageMode, "shrinkageMode");
            Objects.requireNonNull(coordination, "coordination");
        }

        /** Grading without heel coordination. */
        public GradingSettings(
                Path outline,
                double baseSize,
                String sizes,
                boolean halfSizes,
                SizeSystem system,
                OptionalDouble lengthStepMm,
                OptionalDouble widthStepMm,
                Optional<Vec2> originMm,
                double shrinkage,
                ShrinkageMode shrinkageMode) {
            this(
                    outline,
                    baseSize,
                    sizes,
                    halfSizes,
                    system,
                    lengthStepMm,
                    widthStepMm,
                    originMm,
                    shrinkage,
                    shrinkageMode,
                    Optional.empty());
        }
    }

    /**
     * Heel coordination (one heel per group of sizes), its heel either the elements the planner
     * designates or what lies behind a boundary line across the length axis.
     *
     * @param groupSize sizes per heel (the thesis: 3)
     * @param boundaryMm the boundary line's distance from the origin along the length axis, or
     *     empty when the heel is designated by elements
     * @param heelElements the heel's elements, e.g. {@code 1-4,18-20} (1 the outline's first), or
     *     empty when the heel is the part behind the boundary
     */
    public record HeelCoordination(int groupSize, OptionalDouble boundaryMm, String heelElements) {
        /** Sizes per heel when the job, the command line or the tab says none (job.xsd's heelGroup). */
        public static final int DEFAULT_GROUP_SIZE = 3;

        public HeelCoordination {
            Objects.requireNonNull(boundaryMm, "boundaryMm");
            Objects.requireNonNull(heelElements, "heelElements");
            if (boundaryMm.isEmpty() && heelElements.isBlank()) {
                throw new IllegalArgumentException("heel coordination needs a boundary or heel elements");
            }
        }
    }

    /**
     * The sole mould job: the right sole's outline at the base size, the sizes, the grading
     * system, origin and shrinkage, the tread designs and their tools, depths and the post.
     *
     * @param outline the base outline ({@code .contour} or DXF)
     * @param baseSize NP
     * @param sizes the sizes wanted, e.g. {@code 38-42} or {@code 40}
     * @param cavityDepthMm depth of the sole cavity
     * @param post the machine-tool post
     * @param system the size system
     * @param originMm the grading origin and foot of the mirror axis, or empty for the heel centre
     * @param shrinkage the material's shrinkage, fraction
     * @param shrinkageMode additive (thesis) or multiplicative
     * @param treadDepthMm depth of the tread grooves
     * @param clearanceMm height of rapid travel above the top face
     * @param marginMm least distance of a groove's centre line from the outline
     * @param tools the tread tools
     * @param designs the tread designs in cutting order
     * @param cavityTool the id of the tool that pockets the cavity, empty for no cavity program
     * @param block the mould block that holds the pair, or empty: each foot's programs then stay
     *     in the outline's frame
     */
    public record SoleSettings(
            Path outline,
            double baseSize,
            String sizes,
            double cavityDepthMm,
            MillingPost post,
            SizeSystem system,
            Optional<Vec2> originMm,
            double shrinkage,
            ShrinkageMode shrinkageMode,
            double treadDepthMm,
            double clearanceMm,
            double marginMm,
            List<SoleTool> tools,
            List<SoleDesign> designs,
            String cavityTool,
            Optional<SoleBlock> block) {
        /**
         * The sole module's defaults, as {@code schemas/job.xsd} has them (the sole has no command-line
         * options: {@code fresa sole JOB}); the outline has none, and there are no tools, designs or block.
         */
        public static final SoleSettings DEFAULTS = new SoleSettings(
                Path.of(""),
                40,
                "40",
                10,
                MillingPost.LINUXCNC,
                SizeSystem.BR,
                Optional.empty(),
                0,
                ShrinkageMode.MULTIPLICATIVE,
                2,
                5,
                2,
                List.of(),
                List.of(),
                "",
                Optional.empty());

        public SoleSettings {
            Objects.requireNonNull(cavityTool, "cavityTool");
            Objects.requireNonNull(block, "block");
            Objects.requireNonNull(outline, "outline");
            Objects.requireNonNull(sizes, "sizes");
            Objects.requireNonNull(post, "post");
            Objects.requireNonNull(system, "system");
            Objects.requireNonNull(originMm, "originMm");
            Objects.requireNonNull(shrinkageMode, "shrinkageMode");
            tools = List.copyOf(tools);
            designs = List.copyOf(designs);
        }

        /** A sole job without a mould block: each foot's programs in the outline's frame. */
        public SoleSettings(
                Path outline,
                double baseSize,
                String sizes,
                double cavityDepthMm,
                MillingPost post,
                SizeSystem system,
                Optional<Vec2> originMm,
                double shrinkage,
                ShrinkageMode shrinkageMode,
                double treadDepthMm,
                double clearanceMm,
                double marginMm,
                List<SoleTool> tools,
                List<SoleDesign> designs,
                String cavityTool) {
            this(
                    outline,
                    baseSize,
                    sizes,
                    cavityDepthMm,
                    post,
                    system,
                    originMm,
                    shrinkage,
                    shrinkageMode,
                    treadDepthMm,
                    clearanceMm,
                    marginMm,
                    tools,
                    designs,
                    cavityTool,
                    Optional.empty());
        }

        /** A sole job without tread designs, the defaults elsewhere. */
        public SoleSettings(Path outline, double baseSize, String sizes, double cavityDepthMm, MillingPost post) {
            this(
                    outline,
                    baseSize,
                    sizes,
                    cavityDepthMm,
                    post,
                    SizeSystem.BR,
                    Optional.empty(),
                    0,
                    ShrinkageMode.MULTIPLICATIVE,
                    2,
                    5,
                    2,
                    List.of(),
                    List.of(),
                    "");
        }

        /** The same job with other tread designs. */
        public SoleSettings withDesigns(List<SoleDesign> ds) {
            return with(ds, block);
        }

        /** The same job with another mould block (empty: none). */
        public SoleSettings withBlock(Optional<SoleBlock> b) {
            return with(designs, b);
        }

        private SoleSettings with(List<SoleDesign> ds, Optional<SoleBlock> b) {
            return new SoleSettings(
                    outline,
                    baseSize,
                    sizes,
                    cavityDepthMm,
                    post,
                    system,
                    originMm,
                    shrinkage,
                    shrinkageMode,
                    treadDepthMm,
                    clearanceMm,
                    marginMm,
                    tools,
                    ds,
                    cavityTool,
                    b);
        }
    }

    /**
     * The mould block that holds the left and right sole (Ahrens 1986, section 6.6.1, equations
     * 6.1 to 6.9), in the thesis's names. The pattern's extents CP, DPI and XTANP are measured on
     * the base outline about the part zero (the grading origin) when the job leaves them out; the
     * thesis rounds them (270, 29, 60).
     *
     * @param dMm D, the gap between the two patterns along x
     * @param dlmMm DLM, machine x of the tool's machining position on the fixture
     * @param eMm E, from that position to the mirror line (fixture dependent, may be 0)
     * @param sMm S, machine y of the block's lower edge
     * @param cmMm CM, the block's length along y
     * @param cpMm CP, the base pattern's length, or empty to measure it
     * @param dpiMm DPI, from the part zero down to the pattern's lowest point, or empty to measure it
     * @param xtanpMm XTANP, from the part zero to the inner tangent parallel to y, or empty to measure it
     */
    public record SoleBlock(
            double dMm,
            double dlmMm,
            double eMm,
            double sMm,
            double cmMm,
            OptionalDouble cpMm,
            OptionalDouble dpiMm,
            OptionalDouble xtanpMm) {
        public SoleBlock {
            Objects.requireNonNull(cpMm, "cpMm");
            Objects.requireNonNull(dpiMm, "dpiMm");
            Objects.requireNonNull(xtanpMm, "xtanpMm");
        }
    }

    /** A tread tool (the thesis's form bits). */
    public record SoleTool(
            String id,
            int number,
            double diameterMm,
            double spindleRpm,
            double feedMmPerMin,
            double plungeFeedMmPerMin) {
        public SoleTool {
            Objects.requireNonNull(id, "id");
        }
    }

    /**
     * A tread macro call: {@code macro} with its keyword parameters as the thesis writes them.
     *
     * @param drawing the DXF drawing whose outlines a LOGO figure engraves, or empty
     */
    public record SoleFigure(String macro, String params, Optional<Path> drawing) {
        public SoleFigure {
            Objects.requireNonNull(macro, "macro");
            Objects.requireNonNull(params, "params");
            Objects.requireNonNull(drawing, "drawing");
        }

        /** A call without a drawing. */
        public SoleFigure(String macro, String params) {
            this(macro, params, Optional.empty());
        }
    }

    /** An explicit copy: mirror (about x = mirrorXMm, y = mirrorYMm), rotate about the origin, translate. */
    public record SoleCopy(
            double dxMm, double dyMm, OptionalDouble mirrorXMm, OptionalDouble mirrorYMm, double rotateDeg) {
        public SoleCopy {
            Objects.requireNonNull(mirrorXMm, "mirrorXMm");
            Objects.requireNonNull(mirrorYMm, "mirrorYMm");
        }
    }

    /** One tread design: figures repeated by a pattern (see schemas/job.xsd, element sole/design). */
    public record SoleDesign(
            String name,
            String tool,
            SizeRule rule,
            boolean text,
            PatternKind pattern,
            int count,
            int rows,
            double dxMm,
            double dyMm,
            double rowShiftMm,
            double stepDeg,
            double centerXMm,
            double centerYMm,
            List<SoleFigure> lead,
            List<SoleFigure> figures,
            List<SoleCopy> copies) {
        public SoleDesign {
            Objects.requireNonNull(name, "name");
            Objects.requireNonNull(tool, "tool");
            Objects.requireNonNull(rule, "rule");
            Objects.requireNonNull(pattern, "pattern");
            lead = List.copyOf(lead);
            figures = List.copyOf(figures);
            copies = List.copyOf(copies);
        }

        /** The same design with other figures. */
        public SoleDesign withFigures(List<SoleFigure> fs) {
            return with(pattern, fs, copies);
        }

        /** The same figures placed by these explicit copies instead of the design's pattern. */
        public SoleDesign withCopies(List<SoleCopy> cs) {
            return with(PatternKind.COPIES, figures, cs);
        }

        private SoleDesign with(PatternKind p, List<SoleFigure> fs, List<SoleCopy> cs) {
            return new SoleDesign(
                    name,
                    tool,
                    rule,
                    text,
                    p,
                    count,
                    rows,
                    dxMm,
                    dyMm,
                    rowShiftMm,
                    stepDeg,
                    centerXMm,
                    centerYMm,
                    lead,
                    fs,
                    cs);
        }
    }

    /** Output formats chosen for tasks that have no format option of their own. */
    public record OutputSettings(List<String> formats) {
        public static final OutputSettings DEFAULT = new OutputSettings(List.of("csv", "png"));

        public OutputSettings {
            formats = List.copyOf(formats);
        }
    }
}
