package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.ApproachRetract;
import org.fresa.stepnc.DrillingParameters;
import org.fresa.stepnc.DrillingStrategy;
import org.fresa.stepnc.Feature;
import org.fresa.stepnc.MachiningWorkingstep;
import org.fresa.stepnc.Operation;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.Tool;

/**
 * From STEP-NC workingsteps to toolpaths: each workingstep's feature, operation, strategy, tool
 * and technology choose a generator of this package; the path is built in the feature's own
 * frame (the profile's frame for pockets) and placed into the workpiece frame through the
 * AXIS2_PLACEMENT_3D chain, so features on side faces come out right.
 *
 * <p>Conventions and defaults, where the file is silent:
 * <ul>
 * <li>Heights in the feature frame: the feature's top at z = 0, its floor at -depth, the retract
 * plane at +retract_plane (5 mm when unset, the thesis's value). Each section starts and ends on
 * the workingstep's security plane, straight above (along the plane's normal) the retract point
 * over its first and last cut, so the link between workingsteps runs in the security plane even
 * for features on side faces.
 * <li>Tools are numbered 1, 2, ... in order of first use; tool instances with the same id, body
 * and diameter are one tool.
 * <li>A pocket profile whose placement equals the feature's own placement (STEP Modeler writes
 * the feature placement again) is read as lying in the feature frame, with a note.
 * <li>Stepover: the radial cutting depth, else D (1 - overlap), else D / 2 (NIST's default,
 * the tool radius). Layers: the axial cutting depth, else full depth in one layer.
 * <li>Spindle speed and feed: the file's, checked ({@link CuttingData}): a spindle speed from
 * the cutting speed when the spindle is unset, said so; a workingstep with neither, with no
 * feed, or whose spindle and cutting speed disagree tenfold is refused (unless the cutting speed
 * is trusted, {@link PlanningChoices}). A workingstep that cuts deeper below the feature's top
 * than its tool's cutting_edge_length is refused ({@link #edgeReaches}).
 * <li>Plunges, ramps and drilling feed at half the cutting feed for milling cutters and at the
 * cutting feed for drills. A feed without a unit (STEP Modeler) is a chip load: mm/tooth for
 * milling, mm/rev for drilling, times the spindle speed ({@link FeedRate}). Each such reading is
 * reported once per distinct value.
 * <li>Loops run clockwise when rotation_direction is CW, or, without it, when the cut mode is
 * conventional; counter-clockwise otherwise. With the spindle turning clockwise (M3) a tooth
 * cuts its thickest chip first (climb) when the material is on the tool's right, and a pocket's
 * or hole's walls, outside its loops, are on the right of a counter-clockwise loop.
 * <li>Rough operations keep the file's allowances; finish operations cut to size.
 * <li>Round holes: drilling-type operations drill along the axis with the drilling strategy's
 * reduced feeds over the start and end depths; the tip goes to cutting_depth when the file
 * gives it (never deeper), else through a through hole until the full diameter has passed the
 * exit by the breakthrough ({@link #tipLength}, {@link PlanningChoices}); a through hole without
 * depth goes to the bottom of the workpiece's BLOCK along its axis; milled through holes go the
 * breakthrough (and the cutter's edge radius) below the exit; multistep drilling steps by first_depth
 * and depth_of_step (else one tool diameter); reaming and boring leave at feed; milling operations use helical
 * interpolation when the hole is at most twice the tool diameter, and the operation's strategy
 * on a circular pocket (entered on a helix) when it is wider.
 * <li>Slots along linear, circular and general paths are milled by {@link SlotMilling}: square-U,
 * rounded-U, partial circular, vee and tee profiles as far as the tool fits them, radiused, flat,
 * open, woodruff and loop ends; the others are refused with the reason.
 * <li>An operation with explicit toolpaths (AP238 CC1) follows them as given ({@link ExplicitPaths}).
 * <li>Steps, general outside profiles (closed, or open across the block) and open pockets bounded by an open general
 * profile are milled by {@link OpenSideMilling}, entered from the air beyond the block's edge at
 * depth; closed pockets, steps, open pockets and planar faces leave their bosses standing
 * ({@link BossPockets}): the feature's region (carried into the air beyond its open sides) less
 * the bosses, cleared by the region engine.
 * <li>Features other than planar faces, closed pockets, round holes, those slots, steps,
 * outside profiles and open pockets are reported and skipped.
 * </ul>
 */
public final class ToolpathPlanner {

    /** Retract distance when the operation has none (mm), the thesis's value. */
    public static final double DEFAULT_RETRACT_MM = 5;
    /** Feed when the technology has none that can be converted (mm/min). */
    public static final double DEFAULT_FEED = FeedRate.DEFAULT_MM_PER_MIN;

    /** Smallest tool diameter planned (mm). */
    static final double MIN_TOOL_MM = 0.01;
    /** Largest length planned (mm): tool diameters, depths, feature sizes. */
    static final double MAX_LENGTH_MM = 100_000;
    /** Most passes (radial or axial) one workingstep may need; more is a unit or typing mistake. */
    static final int MAX_STEPS = 100_000;

    private ToolpathPlanner() {}

    /** Refuses a span that a step would divide into more than {@link #MAX_STEPS} passes. */
    static void bounded(String spanName, double spanMm, String stepName, double stepMm) {
        if (!(spanMm / stepMm <= MAX_STEPS)) {
            throw new IllegalArgumentException(spanName + " " + spanMm + " mm in steps of " + stepName + " " + stepMm
                    + " mm would need more than " + MAX_STEPS + " passes");
        }
    }

    /**
     * The toolpath of a program and what could not be done.
     *
     * @param toolpath by workingstep, in execution order, only those planned
     * @param problems one sentence per workingstep skipped or planned with a doubt, and one per
     *     distinct feed whose unit had to be inferred
     * @param steps the planned workingsteps, one per section of the toolpath, in the same order
     * @param refusals the reason each workingstep refused outright was left out, by its instance id
     */
    public record Plan(
            Toolpath toolpath,
            List<String> problems,
            int workingsteps,
            int planned,
            List<PlannedStep> steps,
            Map<Long, String> refusals) {
        public Plan {
            problems = List.copyOf(problems);
            steps = List.copyOf(steps);
            refusals = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(refusals));
            if (steps.size() != toolpath.sections().size()) {
                throw new IllegalArgumentException("one planned step per section: " + steps.size() + " vs "
                        + toolpath.sections().size());
            }
        }

        /** The section made for the workingstep with this instance id, if it was planned. */
        public Optional<ToolpathSection> sectionOf(long workingstepInstanceId) {
            for (int i = 0; i < steps.size(); i++) {
                if (steps.get(i).workingstepInstanceId() == workingstepInstanceId) {
                    return Optional.of(toolpath.sections().get(i));
                }
            }
            return Optional.empty();
        }
    }

    /**
     * A workingstep that got a section, and the feed it was planned with.
     *
     * @param workingstepInstanceId the MACHINING_WORKINGSTEP's instance id (#n)
     * @param label the section's label
     * @param feed the cutting feed and how it was read
     */
    public record PlannedStep(long workingstepInstanceId, String label, FeedRate feed) {
        public PlannedStep {
            java.util.Objects.requireNonNull(label, "label");
            java.util.Objects.requireNonNull(feed, "feed");
        }
    }

    /** {@link #plan(StepNcProgram, Tolerance, PlanningChoices)} with the default choices. */
    public static Plan plan(StepNcProgram program, Tolerance tol) {
        return plan(program, tol, PlanningChoices.DEFAULT);
    }

    /**
     * Plans every workingstep of the program; a workingstep that cannot be planned, or must not
     * be cut as its file says ({@link CuttingData}), is reported and left out.
     */
    public static Plan plan(StepNcProgram program, Tolerance tol, PlanningChoices choices) {
        if (choices.paths() == PathConvention.THESIS) {
            return ThesisPaths.plan(program, choices);
        }
        List<ToolpathSection> sections = new ArrayList<>();
        List<PlannedStep> steps = new ArrayList<>();
        Outcome o = plan(program, tol, choices, (ws, s, step) -> {
            sections.add(s);
            steps.add(step);
        });
        return new Plan(new Toolpath(sections), o.problems(), o.workingsteps(), o.planned(), steps, o.refusals());
    }

    /**
     * Takes each section as soon as it is planned, in execution order: a program of tens of
     * thousands of workingsteps is written as it is planned, never held whole.
     */
    @FunctionalInterface
    public interface Sections<E extends Exception> {
        void accept(MachiningWorkingstep ws, ToolpathSection section, PlannedStep step) throws E;
    }

    /**
     * What planning found besides the sections: the {@link Plan} less its toolpath and steps.
     *
     * @param problems as {@link Plan#problems()}
     * @param workingsteps the program's workingsteps
     * @param planned the sections handed on
     * @param refusals as {@link Plan#refusals()}
     */
    public record Outcome(List<String> problems, int workingsteps, int planned, Map<Long, String> refusals) {
        public Outcome {
            problems = List.copyOf(problems);
            refusals = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(refusals));
        }
    }

    /**
     * {@link #plan(StepNcProgram, Tolerance, PlanningChoices)}, each section handed on as soon as it
     * is made instead of kept: the same sections in the same order, the same problems.
     */
    public static <E extends Exception> Outcome plan(
            StepNcProgram program, Tolerance tol, PlanningChoices choices, Sections<E> into) throws E {
        if (choices.paths() == PathConvention.THESIS) {
            // the thesis's paths are few and short: planned whole, then handed on
            Plan p = ThesisPaths.plan(program, choices);
            Map<Long, MachiningWorkingstep> byId = new java.util.HashMap<>();
            program.workingsteps().forEach(w -> byId.put(w.instanceId(), w));
            for (int i = 0; i < p.steps().size(); i++) {
                PlannedStep step = p.steps().get(i);
                into.accept(
                        byId.get(step.workingstepInstanceId()),
                        p.toolpath().sections().get(i),
                        step);
            }
            return new Outcome(p.problems(), p.workingsteps(), p.planned(), p.refusals());
        }
        Map<String, Integer> toolNumbers = new LinkedHashMap<>();
        List<String> problems = new ArrayList<>();
        Map<Long, String> refusals = new LinkedHashMap<>();
        Map<String, Integer> feedNotes = new LinkedHashMap<>();
        int planned = 0;
        for (MachiningWorkingstep ws : program.workingsteps()) {
            ToolpathSection made = null;
            PlannedStep step = null;
            try {
                CuttingData cutting = cuttingData(ws.operation(), choices);
                Optional<ToolpathSection> s =
                        section(ws, toolNumbers, problems, tol, cutting, new HoleContext(program, choices));
                if (s.isPresent()) {
                    made = s.get();
                    FeedRate feed = cutting.feed();
                    cutting.notes()
                            .forEach(n -> problems.add("workingstep '" + s.get().label() + "': " + n));
                    step = new PlannedStep(ws.instanceId(), s.get().label(), feed);
                    if (feed.inferred()) {
                        feedNotes.merge(feed.note(), 1, Integer::sum);
                    }
                    planned++;
                }
            } catch (IllegalArgumentException | UnsupportedOperationException e) {
                problems.add("workingstep '" + ws.id() + "' (#" + ws.instanceId() + "): " + e.getMessage());
                refusals.put(ws.instanceId(), e.getMessage());
            }
            if (made != null) {
                into.accept(ws, made, step);
            }
        }
        feedNotes.forEach(
                (note, count) -> problems.add(count + (count == 1 ? " workingstep: " : " workingsteps: ") + note));
        problems.addAll(FeatureChecks.of(program, tol));
        return new Outcome(problems, program.workingsteps().size(), planned, refusals);
    }

    /** The cutting data of an operation (the tool's diameter for the cutting speed), checked. */
    static CuttingData cuttingData(Operation op, PlanningChoices choices) {
        Tool tool = op.tool().orElseThrow(() -> new IllegalArgumentException("the operation has no tool"));
        double dia = tool.diameterMm().orElseThrow(() -> new IllegalArgumentException("the tool has no diameter"));
        return CuttingData.of(op, dia, choices.trustCuttingSpeed());
    }

    /** What hole depths need beyond the workingstep: the workpiece's block, the breakthrough asked for. */
    record HoleContext(StepNcProgram program, PlanningChoices choices) {}

    static Optional<ToolpathSection> section(
            MachiningWorkingstep ws,
            Map<String, Integer> toolNumbers,
            List<String> problems,
            Tolerance tol,
            CuttingData cutting,
            HoleContext holes) {
        Feature f = ws.feature();
        Operation op = ws.operation();
        String label = ws.id().isEmpty() ? "#" + ws.instanceId() : ws.id();
        Tool tool = op.tool().orElseThrow(() -> new IllegalArgumentException("the operation has no tool"));
        double dia = tool.diameterMm().orElseThrow(() -> new IllegalArgumentException("the tool has no diameter"));
        // writers repeat one physical tool as an instance per operation: same name, body and size, same tool
        String key = tool.id() + "|" + tool.body() + "|" + dia;
        int number = toolNumbers.computeIfAbsent(key, k -> toolNumbers.size() + 1);
        double feed = cutting.feed().feedMmPerMin();
        boolean drillingTool = op.type().isDrillingType();
        Tooling tooling = new Tooling(number, dia, cutting.spindleRpm(), feed, drillingTool ? feed : feed / 2);
        double retract = op.retractPlaneMm().orElse(DEFAULT_RETRACT_MM);
        double depth = f.depthMm().orElse(0);
        if (f.type() == Feature.FeatureType.ROUND_HOLE
                && isThrough(f)
                && f.depthMm().isEmpty()) {
            depth = stockDepth(holes.program(), f, tol);
            problems.add("workingstep '" + label + "': the through hole has no depth: " + mm(depth)
                    + " mm to the bottom of the workpiece's block");
        }
        if (!(dia >= MIN_TOOL_MM && dia <= MAX_LENGTH_MM)) {
            throw new IllegalArgumentException(
                    "tool diameter " + dia + " mm is outside " + MIN_TOOL_MM + " to " + MAX_LENGTH_MM + " mm");
        }
        if (!(Math.abs(depth) <= MAX_LENGTH_MM && Math.abs(retract) <= MAX_LENGTH_MM)) {
            throw new IllegalArgumentException(
                    "depth " + depth + " mm or retract plane " + retract + " mm is beyond " + MAX_LENGTH_MM + " mm");
        }
        double axial = op.axialCuttingDepthMm().orElse(0);
        if (axial > 0) {
            bounded(
                    "depth",
                    Math.max(Math.abs(depth), Math.abs(op.cuttingDepthMm().orElse(0))),
                    "axial cutting depth",
                    axial);
        }
        Heights h = new Heights(retract, retract, 0, -depth);
        Transform3 place = f.placement();
        if (op.type() == Operation.OperationType.OTHER && op.entity().contains("TURNING")) {
            throw new UnsupportedOperationException("turning is not supported (" + op.entity() + ")");
        }
        if (!op.toolpaths().isEmpty()) {
            // the file gives the path itself (AP238 CC1): followed as written, in the feature frame
            ToolpathSection given = ExplicitPaths.section(label, op, tooling, problems);
            edgeReaches(given, tool, op, h.topZ(), tol);
            return Optional.of(viaSecurityPlane(Placing.place(given, place), ws.securityPlane()));
        }
        if (op.type().isMilling()) {
            MillingBodies.check(tool, f);
        } else if (op.type().isDrillingType()) {
            MillingBodies.checkDrilling(tool, op.entity());
        }
        if (!f.bosses().isEmpty() && !BossPockets.LEAVES_BOSSES.contains(f.type())) {
            // cutting it as if it had none would mill its bosses away
            throw new UnsupportedOperationException(
                    f.type() + " features with bosses (its_boss) are not supported yet");
        }
        ToolpathSection local;
        switch (f.type()) {
            case PLANAR_FACE -> {
                if (f.bosses().isEmpty()) {
                    local = face(label, f, op, h, tooling, problems);
                } else {
                    // round the bosses, the face carried into the air where the stock ends
                    java.util.Optional<Contour> stock = holes.program()
                                    .workpieceOf(f)
                                    .flatMap(org.fresa.stepnc.Workpiece::block)
                                    .isPresent()
                            ? Optional.of(stockOutline(holes.program(), f, place, "planar face"))
                            : Optional.empty();
                    Contour region = BossPockets.faceRegion(faceBoundary(f), stock, tooling, tol);
                    local = withBosses(
                            label, "planar face", region, f, place, op, h, tooling, axial, tol, holes, problems);
                }
            }
            case CLOSED_POCKET -> {
                org.fresa.stepnc.Profile sp = f.profile()
                        .orElseThrow(() -> new IllegalArgumentException("the pocket has no boundary profile"));
                Transform3 pp = sp.placement();
                // STEP Modeler writes the feature's own placement (workpiece frame) as the profile's
                if (!pp.eq(Transform3.IDENTITY, tol) && pp.eq(f.placement(), tol)) {
                    pp = Transform3.IDENTITY;
                    problems.add("workingstep '" + label + "': the profile placement repeats the feature placement;"
                            + " read as the feature frame itself");
                }
                place = place.times(pp);
                if (sp instanceof org.fresa.stepnc.Profile.General g
                        && !g.closed()
                        && g.entity().equals("GENERAL_CLOSED_PROFILE")
                        && g.segments().size() > 1) {
                    sp = closedByALine(g);
                    problems.add("workingstep '" + label + "': the pocket's " + g.curveEntity() + " does not end where"
                            + " it starts; closed by a line from its last point back to its first");
                }
                Profile p = profile(sp, f.orthogonalRadiusMm().orElse(0), tol);
                if (sp instanceof org.fresa.stepnc.Profile.General
                        && f.orthogonalRadiusMm().orElse(0) > tooling.radiusMm() + tol.linear()) {
                    // corners rounder than the tool's: the tool must keep out of the fillets' material
                    p = new Profile.General(
                            filleted(p.contour(tol), f.orthogonalRadiusMm().getAsDouble(), tol),
                            ContourOffsetter.EXACT);
                }
                Profile outline = p;
                Transform3 frame = place;
                Transform3 profileFrame = pp;
                Heights heights = h;
                FilletedFloor.Above above = !f.bosses().isEmpty()
                        ? at -> BossPockets.section(
                                label,
                                outline,
                                f,
                                frame,
                                op,
                                at,
                                tooling,
                                stepover(op, tooling),
                                axial,
                                // counter-clockwise loops, as the same pocket without bosses turns
                                !clockwise(op),
                                tol,
                                holes.choices().entry(),
                                problems)
                        : at -> pocket(
                                label,
                                outline,
                                op,
                                at,
                                tooling,
                                profileFrame,
                                tol,
                                holes.choices().entry());
                double rho = filletBeyondCorner(f, tool, "pocket", tol);
                if (rho > 0) {
                    // the cutter's corner cannot follow the floor's fillet: the fillet by Z-levels
                    List<Contour> islands = BossPockets.islands(f, "pocket", place, h, tol);
                    boolean boss = !islands.isEmpty();
                    local = FilletedFloor.section(
                            label,
                            org.fresa.pocket.RegionOffsetter.oriented(p.contour(tol), islands),
                            rho,
                            heights,
                            tooling,
                            stepover(op, tooling),
                            axial,
                            boss ? 0 : sideAllowanceMm(op),
                            boss ? 0 : bottomAllowanceMm(op),
                            !clockwise(op),
                            holes.choices().entry(),
                            tol,
                            above);
                } else {
                    local = above.plan(h);
                }
            }
            case ROUND_HOLE -> {
                if (f.taper().isPresent()) {
                    taperedHoleFits(f, f.taper().get(), tool, tooling, h.topZ() - h.bottomZ(), tol);
                }
                local = hole(label, f, op, h, tooling, tol, holes.choices(), problems);
                if (f.diameterMm().isPresent()) {
                    HoleWalls.within(
                            local,
                            f.diameterMm().getAsDouble(),
                            h.topZ() - h.bottomZ(),
                            HoleWalls.toolReach(
                                    tooling.radiusMm(),
                                    tool.body().equals("BALL_ENDMILL"),
                                    tool.edgeRadiusMm().orElse(0),
                                    tipLength(op, tooling)),
                            tol);
                }
                List<String> unmoved = notInTheMoves(op, tooling.spindleRpm());
                if (!unmoved.isEmpty()) {
                    problems.add(
                            "workingstep '" + label + "': read but not in the moves: " + String.join(", ", unmoved));
                }
            }
            case SLOT -> {
                Transform3 pp = slotFrame(f);
                place = place.times(pp);
                local = SlotMilling.section(
                        label,
                        f,
                        tool,
                        tooling,
                        h,
                        slotCourse(f),
                        axial,
                        tol,
                        problems,
                        (outline, islands, layer) -> islands.isEmpty()
                                ? pocket(
                                        label,
                                        outline,
                                        op,
                                        layer,
                                        tooling,
                                        pp,
                                        tol,
                                        holes.choices().entry())
                                : SlotMilling.band(
                                        label,
                                        outline.contour(tol),
                                        islands,
                                        layer,
                                        tooling,
                                        stepover(op, tooling),
                                        axial,
                                        !clockwise(op),
                                        holes.choices().entry()));
            }
            case STEP -> {
                StepShape st = stepShape(f, holes.program(), tool, tol);
                place = place.times(st.frame());
                if (!f.bosses().isEmpty() && (st.sloped() || st.overhangs())) {
                    throw new UnsupportedOperationException("steps with a " + (st.sloped() ? "sloped" : "overhanging")
                            + " wall and bosses are not supported yet: the region round the bosses would need to"
                            + " follow the wall in each layer");
                }
                local = tool.body().equals("DOVETAIL_MILL")
                        ? DovetailStep.underWall(label, st, tool, h, tooling, tol)
                        : !f.bosses().isEmpty()
                                ? withBosses(
                                        label,
                                        "step",
                                        BossPockets.stepRegion(st, tooling),
                                        f,
                                        place,
                                        op,
                                        h,
                                        tooling,
                                        axial,
                                        tol,
                                        holes,
                                        problems)
                                : step(label, st, h, tooling, op, axial, tol, problems);
            }
            case GENERAL_OUTSIDE_PROFILE -> {
                org.fresa.stepnc.Profile sp = f.profile()
                        .orElseThrow(() -> new IllegalArgumentException("the outside profile has no feature boundary"));
                if (f.depthMm().isEmpty()) {
                    throw new IllegalArgumentException("the outside profile has no depth plane");
                }
                Transform3 pp = sp.placement();
                place = place.times(pp);
                Profile part;
                if (sp instanceof org.fresa.stepnc.Profile.General g && !g.closed()) {
                    ToolpathSection open =
                            openOutsideProfile(label, g, f, place, op, h, tooling, axial, tol, holes, problems);
                    edgeReaches(open, tool, op, h.topZ(), tol);
                    return Optional.of(viaSecurityPlane(Placing.place(open, place), ws.securityPlane()));
                }
                try {
                    part = profile(sp, 0, tol);
                } catch (UnsupportedOperationException e) {
                    throw new UnsupportedOperationException(
                            "outside profiles bounded by " + sp.entity() + " are not supported yet");
                }
                Contour stock = stockOutline(holes.program(), f, place, "outside profile");
                Contour outline = part.contour(tol);
                double reach = 0;
                for (Curve2 c : stock.curves()) {
                    reach = Math.max(reach, outline.distanceTo(c.start()));
                }
                if (reach > tooling.diameterMm() + tol.linear()) {
                    // one loop a layer, as a contour: what lies farther out stays
                    // (or falls away when the profile goes through)
                    problems.add("workingstep '" + label + "': the stock reaches " + mm(reach) + " mm beyond the"
                            + " outside profile; the contour cuts the " + mm(tooling.diameterMm()) + " mm next to it");
                }
                local = openSide(op, h, tooling, axial, tol).outsideProfile(label, outline, stock);
            }
            case OPEN_POCKET -> {
                org.fresa.stepnc.Profile sp = f.profile()
                        .orElseThrow(() -> new IllegalArgumentException("the open pocket has no open boundary"));
                boolean general = sp instanceof org.fresa.stepnc.Profile.General g
                        && !g.closed()
                        && !g.segments().isEmpty();
                if (!general
                        && !(sp instanceof org.fresa.stepnc.Profile.U)
                        && !(sp instanceof org.fresa.stepnc.Profile.Vee)
                        && !(sp instanceof org.fresa.stepnc.Profile.PartialCircular)) {
                    throw new UnsupportedOperationException("open pockets bounded by " + sp.entity()
                            + " are not supported yet: only an open GENERAL_PROFILE, closed by its open side, a"
                            + " SQUARE_U_PROFILE, a ROUNDED_U_PROFILE, a VEE_PROFILE or a"
                            + " PARTIAL_CIRCULAR_PROFILE");
                }
                Heights oh = h;
                if (isThrough(f)) {
                    if (!f.bosses().isEmpty()) {
                        throw new UnsupportedOperationException(
                                "a through open pocket has no floor for its bosses to stand on");
                    }
                    // through the block: to its bottom and past it by what a hole's milling cutter goes
                    if (holes.program()
                            .workpieceOf(f)
                            .flatMap(org.fresa.stepnc.Workpiece::block)
                            .isEmpty()) {
                        throw new IllegalArgumentException("the through open pocket needs the workpiece's BLOCK to"
                                + " find the bottom of the stock");
                    }
                    double stock = stockDepth(holes.program(), f, tol);
                    double past = throughAllowanceMm(
                            op, tooling.diameterMm(), holes.choices().breakthroughMm());
                    oh = new Heights(h.clearanceZ(), h.retractZ(), h.topZ(), h.topZ() - stock - past);
                    problems.add("workingstep '" + label + "': the through open pocket is cut " + mm(stock + past)
                            + " mm deep: to the bottom of the workpiece's block (" + mm(stock) + " mm) and "
                            + mm(past) + " mm past it");
                } else if (f.depthMm().isEmpty()) {
                    throw new IllegalArgumentException("the open pocket has no depth plane");
                }
                double rho = f.planarRadiusMm().orElse(0);
                double edge = tool.edgeRadiusMm().orElse(0);
                boolean zLevels = !isThrough(f) && f.bosses().isEmpty();
                if (!zLevels && rho > tol.linear() && Math.abs(rho - edge) > tol.linear()) {
                    throw new UnsupportedOperationException("the open pocket's floor meets its walls in a " + mm(rho)
                            + " mm radius, which a cutter with a " + mm(edge) + " mm corner would not leave");
                }
                // the fillet the cutter's corner cannot follow is milled by Z-levels
                double beyond = zLevels ? filletBeyondCorner(f, tool, "open pocket", tol) : 0;
                if (f.orthogonalRadiusMm().orElse(0) > tooling.radiusMm() + tol.linear()) {
                    throw new UnsupportedOperationException("the open pocket's corner radius "
                            + mm(f.orthogonalRadiusMm().getAsDouble()) + " mm is larger than the tool's radius: the"
                            + " corners would be cut sharper than drawn");
                }
                Transform3 pp = sp.placement();
                place = place.times(pp);
                Contour stock = stockOutline(holes.program(), f, place, "open pocket");
                List<Curve2> walls = new ArrayList<>();
                if (sp instanceof org.fresa.stepnc.Profile.U u) {
                    walls = uWalls(u, stock, problems, label, tol);
                } else if (sp instanceof org.fresa.stepnc.Profile.Vee v) {
                    walls = veeWalls(v, stock, tooling.radiusMm(), problems, label, tol);
                } else if (sp instanceof org.fresa.stepnc.Profile.PartialCircular pc) {
                    walls = partialCircleWalls(pc, stock, tol);
                } else {
                    for (org.fresa.stepnc.Profile.Segment seg : ((org.fresa.stepnc.Profile.General) sp).segments()) {
                        Vec2 a = new Vec2(seg.start().x(), seg.start().y());
                        Vec2 b = new Vec2(seg.end().x(), seg.end().y());
                        if (seg instanceof org.fresa.stepnc.Profile.Arc arc) {
                            walls.add(new Arc2(
                                    new Vec2(arc.center().x(), arc.center().y()), a, b, arc.ccw()));
                        } else if (a.distance(b) > tol.linear()) {
                            walls.add(new Segment2(a, b));
                        }
                    }
                }
                local = !f.bosses().isEmpty()
                        ? withBosses(
                                label,
                                "open pocket",
                                OpenSideMilling.carriedPastOpenSide(walls, stock, tooling.radiusMm(), tooling, tol),
                                f,
                                place,
                                op,
                                h,
                                tooling,
                                axial,
                                tol,
                                holes,
                                problems)
                        : beyond > 0
                                ? openSide(op, oh, tooling, axial, tol)
                                        .filletedOpenPocket(
                                                label, walls, stock, stepover(op, tooling), beyond, problems)
                                : openSide(op, oh, tooling, axial, tol)
                                        .openPocket(label, walls, stock, stepover(op, tooling), problems);
            }
            default ->
                throw new UnsupportedOperationException((f.type() == Feature.FeatureType.OTHER ? f.entity() : f.type())
                        + " features are not supported yet");
        }
        if (!f.bosses().isEmpty()) {
            traversesOverBosses(local, h.topZ(), BossPockets.tallestTopZ(f, place, h), tol);
        }
        edgeReaches(local, tool, op, sideTopZ(f, tool, h), tol);
        floorRidges(label, f, op, tool, tooling, problems);
        ToolpathSection placed = Placing.place(local, place);
        return Optional.of(viaSecurityPlane(placed, ws.securityPlane()));
    }

    /**
     * Refuses a tool that would cut a tapered hole's wall (change_in_diameter): going straight
     * down the axis, the tool must be no wider than the hole at any height. A straight tool must
     * fit the narrower end; a tapered one (tool_circumference_angle, its flanks leaning out from
     * its tip) is as wide at each height as its tip plus its lean. A hole that widens towards its
     * bottom cannot be made from its top at all.
     *
     * @param depthMm how deep the hole is along its axis
     */
    static void taperedHoleFits(
            Feature f, Feature.HoleTaper taper, Tool tool, Tooling t, double depthMm, Tolerance tol) {
        double top = f.diameterMm().orElse(0);
        double bottom;
        if (taper.finalDiameterMm().isPresent()) {
            bottom = taper.finalDiameterMm().getAsDouble();
        } else if (taper.angleDeg().isPresent()) {
            bottom =
                    top - 2 * depthMm * Math.tan(Math.toRadians(taper.angleDeg().getAsDouble()));
        } else {
            throw new UnsupportedOperationException("the hole's change_in_diameter (" + taper.entity()
                    + ") is not read: drilled straight, a hole that narrows would have its wall cut away");
        }
        if (bottom > top + tol.linear()) {
            throw new UnsupportedOperationException("the hole widens from " + mm(top) + " mm at its top to "
                    + mm(bottom) + " mm at its bottom (change_in_diameter): no tool from its top makes it");
        }
        double lean = tool.circumferenceAngle().orElse(0);
        double leanDeg = "rad".equals(tool.angleUnit()) ? Math.toDegrees(lean) : lean;
        double tip = t.diameterMm();
        // the tool's width where the hole's top is, its tip at the bottom
        double atTop = tip + (leanDeg > 0 && leanDeg < 90 ? 2 * depthMm * Math.tan(Math.toRadians(leanDeg)) : 0);
        if (tip > bottom + tol.linear() || atTop > top + tol.linear()) {
            throw new UnsupportedOperationException("the hole narrows from " + mm(top) + " mm at its top to "
                    + mm(bottom) + " mm at its bottom (change_in_diameter): the " + mm(tip) + " mm tool"
                    + (atTop > tip + tol.linear() ? ", " + mm(atTop) + " mm wide at the hole's top," : "")
                    + " would cut its wall; a tool no wider than the hole at every height makes it");
        }
    }

    /** A ridge on a finished floor up to this high (mm) is within the program's tolerance and not reported. */
    static final double FLOOR_RIDGE_MM = 0.01;

    /**
     * Reports the ridges a cutter with a rounded corner (a bull-nose's edge_radius, a ball end
     * mill's radius) leaves standing on a floor between passes farther apart than its flat end is
     * wide: the passes clear the floor only under the flat, and the corners of two neighbouring
     * passes meet above it. Left on the part, a ridge is material the drawing does not have.
     */
    static void floorRidges(String label, Feature f, Operation op, Tool tool, Tooling t, List<String> problems) {
        boolean floors = switch (op.type()) {
            case PLANE_ROUGH_MILLING,
                    PLANE_FINISH_MILLING,
                    BOTTOM_AND_SIDE_ROUGH_MILLING,
                    BOTTOM_AND_SIDE_FINISH_MILLING -> true;
            default -> false;
        };
        boolean flatFloor = switch (f.type()) {
            case CLOSED_POCKET, OPEN_POCKET, PLANAR_FACE, STEP -> true;
            default -> false;
        };
        if (!floors || !flatFloor) {
            return;
        }
        double r = t.radiusMm();
        double corner = tool.body().equals("BALL_ENDMILL")
                ? r
                : Math.min(Math.max(tool.edgeRadiusMm().orElse(0), 0), r);
        double s = stepover(op, t);
        double ridge = floorRidgeMm(r, corner, s);
        if (ridge > FLOOR_RIDGE_MM && ridge > bottomAllowanceMm(op) + FLOOR_RIDGE_MM) {
            double flat = r - corner;
            double most =
                    2 * (flat + Math.sqrt(corner * corner - (corner - FLOOR_RIDGE_MM) * (corner - FLOOR_RIDGE_MM)));
            problems.add("workingstep '" + label + "': passes up to " + mm(s) + " mm apart leave ridges up to "
                    + mm(ridge) + " mm high on the floor between them: the cutter's " + mm(corner)
                    + " mm corner leaves a flat end " + mm(2 * flat) + " mm across; passes at most " + mm(most)
                    + " mm apart (radial_cutting_depth) leave " + mm(FLOOR_RIDGE_MM) + " mm");
        }
    }

    /**
     * The highest ridge (mm) a cutter of the radius with a corner of the given radius leaves
     * between two straight passes the stepover apart on a flat floor.
     */
    static double floorRidgeMm(double radiusMm, double cornerMm, double stepoverMm) {
        double beyondFlat = stepoverMm / 2 - Math.max(radiusMm - cornerMm, 0);
        if (!(beyondFlat > 0)) {
            return 0;
        }
        if (beyondFlat >= cornerMm) {
            return cornerMm;
        }
        return cornerMm - Math.sqrt(cornerMm * cornerMm - beyondFlat * beyondFlat);
    }

    /**
     * How much of the floor's fillet (planar_radius) the cutter's corner (edge_radius) cannot
     * follow (mm): 0 when the corner leaves the fillet as drawn (or there is none), the fillet
     * less the corner when it is the larger.
     *
     * @throws UnsupportedOperationException when the cutter's corner is larger than the fillet:
     *     its corner would leave a larger fillet than drawn, material the drawing takes away
     */
    static double filletBeyondCorner(Feature f, Tool tool, String what, Tolerance tol) {
        double rho = f.planarRadiusMm().orElse(0);
        double edge = tool.edgeRadiusMm().orElse(0);
        if (!(rho > tol.linear()) || Math.abs(rho - edge) <= tol.linear()) {
            return 0;
        }
        if (edge > rho) {
            throw new UnsupportedOperationException("the " + what + "'s floor meets its walls in a " + mm(rho)
                    + " mm radius; a cutter with a " + mm(edge) + " mm corner would leave a " + mm(edge)
                    + " mm one, material the drawing takes away: a cutter whose corner is at most " + mm(rho)
                    + " mm mills it");
        }
        return rho - edge;
    }

    /**
     * The walls of an open pocket bounded by a U (SQUARE_U_PROFILE or ROUNDED_U_PROFILE) in its
     * profile frame, with the pocket on their right as an open GENERAL_PROFILE's: the U's bottom
     * on the frame's x axis, centred on its origin, its sides running along +y out to the stock's
     * edge, where the open side joins their ends. A square U's corners are rounded by the larger
     * of its radii (the smaller would let the tool into the other corner's fillet, whichever ISO
     * 14649-10's first one is).
     *
     * @throws UnsupportedOperationException for sides that do not stand square to the bottom, or
     *     that do not both reach the stock's edge
     */
    static List<Curve2> uWalls(
            org.fresa.stepnc.Profile.U u, Contour stock, List<String> problems, String label, Tolerance tol) {
        double w = u.widthMm();
        if (!(w > 0)) {
            throw new IllegalArgumentException("the open pocket's U has no width");
        }
        boolean rounded = u.entity().equals("ROUNDED_U_PROFILE");
        double rc = rounded
                ? w / 2
                : Math.max(u.firstRadiusMm().orElse(0), u.secondRadiusMm().orElse(0));
        if (!rounded) {
            SlotMilling.squareSides(u, "open pocket's U", label, problems);
            if (Math.abs(u.firstRadiusMm().orElse(0) - u.secondRadiusMm().orElse(0)) > tol.linear()) {
                problems.add("workingstep '" + label + "': the U's corners of "
                        + mm(u.firstRadiusMm().orElse(0)) + " and "
                        + mm(u.secondRadiusMm().orElse(0)) + " mm are both milled with the larger");
            }
            if (!(rc <= w / 2 + tol.linear())) {
                throw new IllegalArgumentException(
                        "the open pocket's U corner radius " + mm(rc) + " mm does not fit its " + mm(w) + " mm width");
            }
            rc = Math.min(rc, w / 2);
        }
        Vec2 right = stockEdgeAlong(new Vec2(w / 2, rc), Vec2.UNIT_Y, stock, "U", tol);
        Vec2 left = stockEdgeAlong(new Vec2(-w / 2, rc), Vec2.UNIT_Y, stock, "U", tol);
        List<Curve2> walls = new ArrayList<>();
        if (rc > tol.linear()) {
            walls.add(new Segment2(right, new Vec2(w / 2, rc)));
            if (w / 2 - rc > tol.linear()) {
                walls.add(new Arc2(new Vec2(w / 2 - rc, rc), new Vec2(w / 2, rc), new Vec2(w / 2 - rc, 0), false));
                walls.add(new Segment2(new Vec2(w / 2 - rc, 0), new Vec2(-w / 2 + rc, 0)));
                walls.add(new Arc2(new Vec2(-w / 2 + rc, rc), new Vec2(-w / 2 + rc, 0), new Vec2(-w / 2, rc), false));
            } else {
                walls.add(new Arc2(new Vec2(0, rc), new Vec2(w / 2, rc), new Vec2(-w / 2, rc), false));
            }
            walls.add(new Segment2(new Vec2(-w / 2, rc), left));
        } else {
            walls.add(new Segment2(right, new Vec2(w / 2, 0)));
            walls.add(new Segment2(new Vec2(w / 2, 0), new Vec2(-w / 2, 0)));
            walls.add(new Segment2(new Vec2(-w / 2, 0), left));
        }
        return walls;
    }

    /**
     * The walls of an open pocket bounded by a VEE_PROFILE in its profile frame, with the pocket on
     * their right as a U's: the vee's bottom (the middle of its blend, or its point when sharp) on
     * the frame's origin, its first wall at tilt_angle from the frame's x axis and its second at
     * the profile angle beyond, both running out to the stock's edge. An upright vee (tilt 90 deg
     * less half its angle) opens along +y as a U does; another tilt turns it about its bottom. A
     * blend smaller than the tool's radius, or none, leaves the material in the vee's point that
     * the cutter cannot reach into: reported with how far short of the bottom it stops.
     */
    static List<Curve2> veeWalls(
            org.fresa.stepnc.Profile.Vee v,
            Contour stock,
            double toolRadiusMm,
            List<String> problems,
            String label,
            Tolerance tol) {
        double angle = v.profileAngleDeg();
        if (!(angle > 0 && angle < 180)) {
            throw new IllegalArgumentException("vee profile_angle " + mm(angle) + " deg is outside 0 to 180 deg");
        }
        double rho = v.profileRadiusMm().orElse(0);
        if (!(rho >= 0 && rho <= MAX_LENGTH_MM)) {
            throw new IllegalArgumentException(
                    "vee profile_radius " + mm(rho) + " mm is outside 0 to " + mm(MAX_LENGTH_MM) + " mm");
        }
        double half = Math.toRadians(angle / 2);
        Vec2 first = Vec2.ofAngle(Math.toRadians(v.tiltAngleDeg()));
        Vec2 second = Vec2.ofAngle(Math.toRadians(v.tiltAngleDeg() + angle));
        Vec2 opens = Vec2.ofAngle(Math.toRadians(v.tiltAngleDeg() + angle / 2));
        // the walls' lines meet at the point, the blend's centre on the bisector rho / sin(half) from it
        Vec2 point = opens.times(-(rho / Math.sin(half) - rho));
        List<Curve2> walls = new ArrayList<>();
        if (rho > tol.linear()) {
            Vec2 centre = point.plus(opens.times(rho / Math.sin(half)));
            Vec2 t1 = point.plus(first.times(rho / Math.tan(half)));
            Vec2 t2 = point.plus(second.times(rho / Math.tan(half)));
            walls.add(new Segment2(stockEdgeAlong(t1, first, stock, "vee", tol), t1));
            walls.add(new Arc2(centre, t1, t2, false));
            walls.add(new Segment2(t2, stockEdgeAlong(t2, second, stock, "vee", tol)));
        } else {
            walls.add(new Segment2(stockEdgeAlong(point, first, stock, "vee", tol), point));
            walls.add(new Segment2(point, stockEdgeAlong(point, second, stock, "vee", tol)));
        }
        if (toolRadiusMm > rho + tol.linear()) {
            // the cutter touches both walls with its centre r / sin(half) from the point
            double shortOfBottomMm = (toolRadiusMm - rho) * (1 / Math.sin(half) - 1);
            problems.add("workingstep '" + label + "': the " + mm(2 * toolRadiusMm) + " mm cutter cannot reach into"
                    + " the " + mm(angle) + " deg vee's point ("
                    + (rho > tol.linear() ? mm(rho) + " mm blend" : "sharp")
                    + "): it stops " + mm(shortOfBottomMm) + " mm short of its bottom, leaving the material there");
        }
        return walls;
    }

    /**
     * The walls of an open pocket bounded by a PARTIAL_CIRCULAR_PROFILE in its profile frame, with
     * the pocket on their right as a U's: the arc as ISO 14649-10 draws it, about the frame's
     * origin from its x axis counter-clockwise by the sweep, its ends carried out to the stock's
     * edge along the line from the arc's middle through its centre, the way the profile opens (a
     * half circle about the origin drawn from the x axis opens along -y).
     *
     * @throws UnsupportedOperationException for an arc of more than a half circle, wider inside
     *     than at its mouth
     */
    static List<Curve2> partialCircleWalls(org.fresa.stepnc.Profile.PartialCircular pc, Contour stock, Tolerance tol) {
        double radius = pc.radiusMm();
        if (!(radius > 0 && radius <= MAX_LENGTH_MM)) {
            throw new IllegalArgumentException("partial circular profile radius " + mm(radius) + " mm is outside 0 to "
                    + mm(MAX_LENGTH_MM) + " mm");
        }
        double sweep = pc.sweepAngleDeg();
        if (!(sweep > 0 && sweep <= 180 + SlotMilling.SQUARE_TOLERANCE_DEG)) {
            throw new UnsupportedOperationException("the open pocket's partial circular profile sweeps " + mm(sweep)
                    + " deg: more than a half circle is wider inside than at its mouth, and the passes from the"
                    + " open side would not reach behind its walls");
        }
        Vec2 start = Vec2.ofAngle(0).times(radius);
        Vec2 end = Vec2.ofAngle(Math.toRadians(sweep)).times(radius);
        Vec2 opens = Vec2.ofAngle(Math.toRadians(sweep / 2)).negated();
        List<Curve2> walls = new ArrayList<>();
        walls.add(new Segment2(stockEdgeAlong(end, opens, stock, "partial circular profile's", tol), end));
        walls.add(new Arc2(Vec2.ZERO, end, start, false));
        walls.add(new Segment2(start, stockEdgeAlong(start, opens, stock, "partial circular profile's", tol)));
        return walls;
    }

    /**
     * Refuses a plan with a rapid move across the feature above its top but no higher than its
     * tallest boss's top: a boss may stand above the feature's top, and a rapid over it there
     * would run into it (below the top the tool moves within the region it cleared, round the
     * bosses).
     *
     * @throws UnsupportedOperationException naming the height of the lowest such traverse
     */
    static void traversesOverBosses(ToolpathSection local, double topZ, double bossesTopZ, Tolerance tol) {
        if (!(bossesTopZ > topZ + tol.linear())) {
            return;
        }
        Vec3 at = local.start();
        for (org.fresa.model.Move m : local.moves()) {
            Vec3 to = m.end();
            boolean across = Math.hypot(to.x() - at.x(), to.y() - at.y()) > tol.linear();
            double low = Math.min(at.z(), to.z());
            if (m instanceof org.fresa.model.Move.Rapid && across && low >= topZ - tol.linear() && low <= bossesTopZ) {
                throw new UnsupportedOperationException("a rapid move crosses the feature at " + mm(low)
                        + " mm, not over its tallest boss, whose top is at " + mm(bossesTopZ) + " mm: raise the"
                        + " retract plane above it");
            }
            at = to;
        }
    }

    /**
     * A tool cuts no deeper than its cutting edge (cutting_edge_length) reaches: below it an end
     * mill's shank, as wide as its flutes, would rub the wall just cut, and a drill's chips could
     * not leave the hole. The depth is from the feature's top, where the tool's side first meets
     * material (the stock's top where the feature is open to it), down to the lowest cutting move
     * of the section, in the feature frame: a hole's tip and breakthrough as planned, a through
     * pocket's allowance past the block. A tool without an edge length is not checked.
     *
     * @throws IllegalArgumentException naming both lengths and the edge that would cut it
     */
    /**
     * The highest material the tool's side meets: the feature's top, except for a T-slot mill
     * under a tee's stem, whose neck passes the stem already milled and whose disc meets only the
     * cross bar.
     */
    static double sideTopZ(Feature f, Tool tool, Heights h) {
        if (f.type() == Feature.FeatureType.SLOT
                && tool.body().equals("T_SLOT_MILL")
                && f.profile().orElse(null) instanceof org.fresa.stepnc.Profile.Tee tee) {
            return Math.min(h.topZ(), h.bottomZ() + tee.crossBarDepthMm());
        }
        return h.topZ();
    }

    static void edgeReaches(ToolpathSection local, Tool tool, Operation op, double topZ, Tolerance tol) {
        if (tool.cuttingEdgeLengthMm().isEmpty()) {
            return;
        }
        double edge = tool.cuttingEdgeLengthMm().getAsDouble();
        double lowest = Double.POSITIVE_INFINITY;
        for (Move m : local.moves()) {
            if (m instanceof Move.Linear || m instanceof Move.Circular) {
                lowest = Math.min(lowest, m.end().z());
            }
        }
        double depth = topZ - lowest;
        if (!(depth > edge + tol.linear())) {
            return;
        }
        String why = op.type().isDrillingType()
                ? "its chips could not clear the hole"
                : "its shank would rub the wall it has just cut";
        throw new IllegalArgumentException("the tool cuts " + mm(depth) + " mm below the feature's top but its"
                + " cutting edge is " + mm(edge) + " mm long: " + why + "; a tool with at least " + mm(depth)
                + " mm of cutting edge cuts it");
    }

    /**
     * Where a side of an open pocket's profile, running from a point along a direction, first
     * meets the stock's edge.
     *
     * @throws UnsupportedOperationException when it does not meet it
     */
    static Vec2 stockEdgeAlong(Vec2 from, Vec2 direction, Contour stock, String profile, Tolerance tol) {
        Segment2 ray = new Segment2(from, from.plus(direction.normalized().times(2 * MAX_LENGTH_MM)));
        Vec2 near = null;
        for (Curve2 c : stock.curves()) {
            for (Vec2 p : org.fresa.geom.Intersections.of(ray, c, tol)) {
                if (near == null || p.distance(from) < near.distance(from)) {
                    near = p;
                }
            }
        }
        if (near == null) {
            throw new UnsupportedOperationException("the open pocket's " + profile + " sides do not reach the"
                    + " stock's edge along the direction the profile opens in");
        }
        return near;
    }

    /** A general profile whose chain does not close, closed by a line from its end to its start. */
    static org.fresa.stepnc.Profile.General closedByALine(org.fresa.stepnc.Profile.General g) {
        List<org.fresa.stepnc.Profile.Segment> segs = new ArrayList<>(g.segments());
        segs.add(new org.fresa.stepnc.Profile.Line(
                segs.get(segs.size() - 1).end(), segs.get(0).start()));
        return new org.fresa.stepnc.Profile.General(g.entity(), g.placement(), g.curveEntity(), segs, true);
    }

    /**
     * The contour (counter-clockwise) with each corner that points out of the region, between two
     * straight sides, rounded by the radius (ISO 14649-10 orthogonal_radius).
     *
     * @throws UnsupportedOperationException when a fillet does not fit its sides or a corner to
     *     round meets an arc
     */
    static Contour filleted(Contour c, double radiusMm, Tolerance tol) {
        List<Curve2> cs = c.ccw().curves();
        int n = cs.size();
        double[] cutStart = new double[n];
        double[] cutEnd = new double[n];
        Arc2[] fillet = new Arc2[n];
        for (int i = 0; i < n; i++) {
            Curve2 a = cs.get(i);
            Curve2 b = cs.get((i + 1) % n);
            Vec2 u = a.endTangent().normalized();
            Vec2 w = b.startTangent().normalized();
            double turn = u.x() * w.y() - u.y() * w.x();
            if (turn <= 1e-9) {
                // straight on, or a corner pointing into the region: the tool leaves material there anyway
                continue;
            }
            if (!(a instanceof Segment2) || !(b instanceof Segment2)) {
                throw new UnsupportedOperationException("the pocket's corner at "
                        + mm(a.end().x()) + ", "
                        + mm(a.end().y()) + " meets an arc: its orthogonal_radius is rounded between straight sides"
                        + " only");
            }
            double interior = Math.PI - Math.acos(Math.max(-1, Math.min(1, u.dot(w))));
            double t = radiusMm / Math.tan(interior / 2);
            Vec2 v = a.end();
            Vec2 t1 = v.minus(u.times(t));
            Vec2 t2 = v.plus(w.times(t));
            Vec2 centre = t1.plus(u.leftNormal().times(radiusMm));
            fillet[i] = new Arc2(centre, t1, t2, true);
            cutEnd[i] = t;
            cutStart[(i + 1) % n] = t;
        }
        List<Curve2> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Curve2 x = cs.get(i);
            if (x instanceof Segment2 sg && (cutStart[i] > 0 || cutEnd[i] > 0)) {
                double len = sg.length();
                if (cutStart[i] + cutEnd[i] > len + tol.linear()) {
                    throw new UnsupportedOperationException("the pocket's orthogonal_radius " + mm(radiusMm)
                            + " mm does not fit its " + mm(len) + " mm side");
                }
                Vec2 d = sg.direction().normalized();
                Vec2 p0 = sg.start().plus(d.times(cutStart[i]));
                Vec2 p1 = sg.end().minus(d.times(cutEnd[i]));
                if (p0.distance(p1) > tol.linear()) {
                    out.add(new Segment2(p0, p1));
                }
            } else {
                out.add(x);
            }
            if (fillet[i] != null) {
                out.add(fillet[i]);
            }
        }
        return Contour.of(out, Tolerance.DRAWING);
    }

    /** An open general outside profile, cut as a contour on its right from the air to the air. */
    private static ToolpathSection openOutsideProfile(
            String label,
            org.fresa.stepnc.Profile.General g,
            Feature f,
            Transform3 place,
            Operation op,
            Heights h,
            Tooling tooling,
            double axial,
            Tolerance tol,
            HoleContext holes,
            List<String> problems) {
        List<Curve2> chain = new ArrayList<>();
        for (org.fresa.stepnc.Profile.Segment seg : g.segments()) {
            Vec2 a = new Vec2(seg.start().x(), seg.start().y());
            Vec2 b = new Vec2(seg.end().x(), seg.end().y());
            if (seg instanceof org.fresa.stepnc.Profile.Arc arc) {
                chain.add(new Arc2(new Vec2(arc.center().x(), arc.center().y()), a, b, arc.ccw()));
            } else if (a.distance(b) > tol.linear()) {
                chain.add(new Segment2(a, b));
            }
        }
        if (chain.isEmpty()) {
            throw new IllegalArgumentException("the open outside profile has no elements");
        }
        Contour stock = stockOutline(holes.program(), f, place, "outside profile");
        return openSide(op, h, tooling, axial, tol).openOutsideProfile(label, chain, stock, problems);
    }

    /**
     * A step without bosses, cut from the air beyond its open side. A wall that slopes back is cut
     * in layers no thicker than the vee slots' (docs/slots.md), each cut in to where the wall
     * stands at its bottom; the steps this leaves on the wall are reported with their height and
     * width.
     */
    private static ToolpathSection step(
            String label,
            StepShape st,
            Heights h,
            Tooling tooling,
            Operation op,
            double axial,
            Tolerance tol,
            List<String> problems) {
        double layer = axial;
        double footPerMm = 0;
        if (st.overhangs()) {
            double depth = h.topZ() - h.bottomZ();
            problems.add("workingstep '" + label + "': the wall overhangs the floor at " + mm(st.wallAngleDeg())
                    + " deg: the step is milled to the wall's top edge, and the " + mm(st.undercutMm(depth))
                    + " mm undercut under it needs a DOVETAIL_MILL");
        }
        if (st.sloped()) {
            layer = axial > 0 ? Math.min(axial, SlotMilling.SHAPED_LAYER_MM) : SlotMilling.SHAPED_LAYER_MM;
            footPerMm = st.footMm(1);
            problems.add("workingstep '" + label + "': the wall sloped at " + mm(st.wallAngleDeg())
                    + " deg is cut in " + mm(layer) + " mm layers: steps up to " + mm(layer) + " mm high and "
                    + mm(layer * footPerMm) + " mm wide are left on it");
        }
        return openSide(op, h, tooling, layer, tol)
                .step(
                        label,
                        st.lengthMm(),
                        st.widthMm(),
                        st.openStart(),
                        st.openEnd(),
                        footPerMm,
                        stepover(op, tooling));
    }

    /**
     * How the operation mills a feature open to the outside in these heights and layers: the
     * allowances a roughing leaves, climb milling unless its cutmode says conventional.
     */
    private static OpenSideMilling openSide(Operation op, Heights h, Tooling tooling, double axial, Tolerance tol) {
        return new OpenSideMilling(h, tooling, axial, sideAllowanceMm(op), bottomAllowanceMm(op), climb(op), tol);
    }

    /**
     * A step, open pocket or planar face with bosses: its region (carried into the air beyond its
     * open sides) less its bosses, cleared by the pocket module's region pocketing, cut to size.
     */
    private static ToolpathSection withBosses(
            String label,
            String what,
            Contour region,
            Feature f,
            Transform3 place,
            Operation op,
            Heights h,
            Tooling tooling,
            double axial,
            Tolerance tol,
            HoleContext holes,
            List<String> problems) {
        List<Contour> islands = BossPockets.islands(f, what, place, h, tol);
        BossPockets.inside(f, what, region, islands, tol);
        return BossPockets.section(
                label,
                what,
                region,
                islands,
                BossPockets.tallestTopZ(f, place, h),
                op,
                h,
                tooling,
                stepover(op, tooling),
                axial,
                climb(op),
                tol,
                holes.choices().entry(),
                problems);
    }

    /**
     * Climb milling unless the strategy's cutmode says conventional: with the spindle turning
     * clockwise, the material being cut on the tool's right.
     */
    /** The side allowance a rough operation leaves; a finish cuts to size. */
    static double sideAllowanceMm(Operation op) {
        return isRough(op) ? op.allowanceSideMm().orElse(0) : 0;
    }

    /** The bottom allowance a rough operation leaves; a finish cuts to size. */
    static double bottomAllowanceMm(Operation op) {
        return isRough(op) ? op.allowanceBottomMm().orElse(0) : 0;
    }

    static boolean climb(Operation op) {
        return !op.strategy()
                .flatMap(org.fresa.stepnc.Strategy::cutmode)
                .map(m -> m.equalsIgnoreCase("CONVENTIONAL"))
                .orElse(false);
    }

    /**
     * A step in its own frame (x along the open boundary from its start, z the feature axis, the
     * material kept at +y) and how far the step reaches out to the stock's edge.
     */
    record StepShape(
            Transform3 frame,
            double lengthMm,
            double widthMm,
            boolean openStart,
            boolean openEnd,
            double wallAngleDeg) {

        /** A step with a vertical wall. */
        StepShape(Transform3 frame, double lengthMm, double widthMm, boolean openStart, boolean openEnd) {
            this(frame, lengthMm, widthMm, openStart, openEnd, 90);
        }

        /** Whether the wall slopes back from its foot (profile_angle above 90 deg). */
        boolean sloped() {
            return wallAngleDeg > 90;
        }

        /** Whether the wall overhangs its floor (profile_angle under 90 deg): a half dovetail. */
        boolean overhangs() {
            return wallAngleDeg < 90;
        }

        /** How far (mm, towards +y, under the material) the overhanging wall's foot lies from its top edge. */
        double undercutMm(double depthMm) {
            return overhangs() ? depthMm / Math.tan(Math.toRadians(wallAngleDeg)) : 0;
        }

        /**
         * How far (mm, towards -y) the wall's foot lies from the open boundary at the step's top
         * for a step this deep: 0 for a vertical wall.
         */
        double footMm(double depthMm) {
            return sloped() ? -depthMm / Math.tan(Math.toRadians(wallAngleDeg)) : 0;
        }
    }

    /**
     * The step's frame and extent: ISO 14649-10 keeps the material on the left of the open
     * boundary as it runs; the step is what lies to its right, out to the workpiece's BLOCK, whose
     * side there must be parallel to the boundary. An end of the boundary at or beyond the
     * block's end is open.
     */
    static StepShape stepShape(Feature f, StepNcProgram program, Tool tool, Tolerance tol) {
        org.fresa.stepnc.TravelPath path =
                f.courseOfTravel().orElseThrow(() -> new IllegalArgumentException("the step has no open boundary"));
        if (!path.entity().equals("LINEAR_PATH")) {
            throw new UnsupportedOperationException("steps along a " + path.entity() + " are not supported yet");
        }
        double length = path.distanceMm()
                .orElseThrow(() -> new IllegalArgumentException("the step's open boundary" + " has no length"));
        if (!(length > 0 && length <= MAX_LENGTH_MM)) {
            throw new IllegalArgumentException(
                    "step length " + length + " mm is outside 0 to " + MAX_LENGTH_MM + " mm");
        }
        org.fresa.stepnc.Profile wall =
                f.profile().orElseThrow(() -> new IllegalArgumentException("the step has no wall boundary"));
        double wallAngle = 90;
        if (wall instanceof org.fresa.stepnc.Profile.Vee v) {
            // GRIMA's writers put pi / 2 there in radians, also in files not otherwise known as
            // theirs: a wall 1.57 deg from its floor is no step
            boolean radiansRight = Math.abs(v.profileAngleDeg() - Math.PI / 2) < 1e-6;
            if (!radiansRight && Math.abs(v.profileAngleDeg() - 90) > SlotMilling.SQUARE_TOLERANCE_DEG) {
                if (!(v.profileAngleDeg() > 0 && v.profileAngleDeg() < 180)) {
                    throw new UnsupportedOperationException("the step's wall stands at " + mm(v.profileAngleDeg())
                            + " deg to its floor: only walls between 0 and 180 deg to it are milled");
                }
                wallAngle = v.profileAngleDeg();
            }
            checkStepTilt(v, wallAngle, radiansRight);
            double rho = v.profileRadiusMm().orElse(0);
            double edge = tool.edgeRadiusMm().orElse(0);
            if (rho > tol.linear() && wallAngle != 90) {
                throw new UnsupportedOperationException(
                        "the step's wall at " + mm(wallAngle) + " deg meets its floor in a " + mm(rho)
                                + " mm radius: only a sloped or overhanging wall with a sharp foot is milled");
            }
            if (rho > tol.linear() && Math.abs(rho - edge) > tol.linear()) {
                throw new UnsupportedOperationException("the step's wall meets its floor in a " + mm(rho)
                        + " mm radius, which a cutter with a " + mm(edge) + " mm corner would not leave");
            }
        } else {
            throw new UnsupportedOperationException("step walls given by " + wall.entity() + " are not supported yet");
        }
        Vec3 d3 = path.placement().applyToDirection(path.direction().orElse(Vec3.UNIT_X));
        Vec2 along = new Vec2(d3.x(), d3.y());
        if (along.norm() < 1e-9) {
            throw new UnsupportedOperationException("the step's open boundary runs along the tool axis");
        }
        along = along.normalized();
        Vec3 s3 = path.placement().applyToPoint(Vec3.ZERO);
        Vec2 start = new Vec2(s3.x(), s3.y());
        Vec2 right = new Vec2(along.y(), -along.x());
        Contour stock = stockOutline(program, f, f.placement(), "step");
        double width = Double.NEGATIVE_INFINITY;
        double second = Double.NEGATIVE_INFINITY;
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (Curve2 c : stock.curves()) {
            Vec2 p = c.start().minus(start);
            double across = p.dot(right);
            if (across > width) {
                second = width;
                width = across;
            } else if (across > second) {
                second = across;
            }
            lo = Math.min(lo, p.dot(along));
            hi = Math.max(hi, p.dot(along));
        }
        if (!(width > tol.linear())) {
            throw new IllegalArgumentException(
                    "the workpiece's block lies left of the step's open boundary: nothing" + " to remove on its right");
        }
        if (width - second > tol.linear()) {
            throw new UnsupportedOperationException(
                    "the step's open boundary is not parallel to a side of the" + " workpiece's block");
        }
        Transform3 frame =
                Transform3.ofFrame(s3.minus(new Vec3(0, 0, s3.z())), Vec3.UNIT_Z, new Vec3(along.x(), along.y(), 0));
        StepShape shape =
                new StepShape(frame, length, width, lo >= -tol.linear(), hi <= length + tol.linear(), wallAngle);
        double foot = shape.footMm(f.depthMm().orElse(0));
        if (foot >= width - tol.linear()) {
            throw new UnsupportedOperationException("the step's wall sloped at " + mm(wallAngle) + " deg reaches "
                    + mm(foot) + " mm out at its floor, past the block's side " + mm(width)
                    + " mm away: the step has no floor");
        }
        return shape;
    }

    /**
     * ISO 14649-10 gives a vee's tilt_angle as the angle between one of its sides and the
     * workpiece's surface round it. A step's wall meets the block's top at the profile angle on the
     * material's side and at 180 deg less it on the air's: either tilt draws the wall standing on a
     * floor parallel to the top, as the planner mills it. Any other tilt turns the whole profile,
     * the floor with it, which a cutter along the feature's axis would cut flat.
     *
     * @throws UnsupportedOperationException for a tilt that draws a floor not parallel to the top
     */
    private static void checkStepTilt(org.fresa.stepnc.Profile.Vee v, double wallAngleDeg, boolean radians) {
        double written = v.tiltAngleDeg();
        // the writers that put the profile angle in radians put the tilt there too
        double tilt = radians && Math.abs(written) <= Math.PI + 1e-6 ? Math.toDegrees(written) : written;
        double off = Math.min(Math.abs(tilt - wallAngleDeg), Math.abs(tilt - (180 - wallAngleDeg)));
        if (off > SlotMilling.SQUARE_TOLERANCE_DEG) {
            throw new UnsupportedOperationException("the step's wall_boundary gives profile_angle "
                    + mm(v.profileAngleDeg()) + " and tilt_angle " + mm(written) + ": a wall at "
                    + mm(wallAngleDeg) + " deg to its floor meets the block's top at " + mm(wallAngleDeg)
                    + " or " + mm(180 - wallAngleDeg) + " deg, and a tilt of " + mm(tilt)
                    + " deg would tilt the floor by " + mm(off) + " deg, which is not milled: only a floor"
                    + " parallel to the top is");
        }
    }

    /**
     * The outline of the workpiece's BLOCK in a frame (its footprint on the frame's xy plane,
     * counter-clockwise), for features that reach to the stock's edge; the block's sides must
     * stand along the frame's z axis.
     */
    static Contour stockOutline(StepNcProgram program, Feature f, Transform3 frame, String what) {
        org.fresa.stepnc.Workpiece.Block b = program.workpieceOf(f)
                .flatMap(org.fresa.stepnc.Workpiece::block)
                .orElseThrow(() -> new IllegalArgumentException(
                        "the " + what + " reaches to the stock's edge and the" + " file gives no workpiece BLOCK"));
        Transform3 toFrame = frame.inverse().times(b.placement());
        Vec3 z = toFrame.applyToDirection(Vec3.UNIT_Z);
        if (Math.abs(Math.abs(z.z()) - 1) > 1e-9) {
            throw new UnsupportedOperationException(
                    "the " + what + "'s axis is not along the workpiece block's z axis");
        }
        Vec2[] corners = new Vec2[4];
        double[][] xy = {{0, 0}, {b.xMm(), 0}, {b.xMm(), b.yMm()}, {0, b.yMm()}};
        for (int i = 0; i < 4; i++) {
            Vec3 p = toFrame.applyToPoint(new Vec3(xy[i][0], xy[i][1], 0));
            corners[i] = new Vec2(p.x(), p.y());
        }
        List<Curve2> cs = new ArrayList<>();
        for (int i = 0; i < 4; i++) {
            cs.add(new Segment2(corners[i], corners[(i + 1) % 4]));
        }
        return Contour.of(cs, Tolerance.DRAWING).ccw();
    }

    static double slotLength(Feature f) {
        org.fresa.stepnc.TravelPath path =
                f.courseOfTravel().orElseThrow(() -> new IllegalArgumentException("the slot has no course of travel"));
        if (!path.entity().equals("LINEAR_PATH")) {
            throw new UnsupportedOperationException("slots along a " + path.entity() + " are not machined: the"
                    + " planner follows a LINEAR_PATH, a CIRCULAR_PATH or a GENERAL_PATH course of travel only");
        }
        double length =
                path.distanceMm().orElseThrow(() -> new IllegalArgumentException("the slot's path has no length"));
        if (!(length > 0 && length <= MAX_LENGTH_MM)) {
            throw new IllegalArgumentException(
                    "slot length " + length + " mm is outside 0 to " + MAX_LENGTH_MM + " mm");
        }
        return length;
    }

    /** The slot's course of travel in its slot frame ({@link #slotFrame}). */
    static SlotMilling.Course slotCourse(Feature f) {
        org.fresa.stepnc.TravelPath path =
                f.courseOfTravel().orElseThrow(() -> new IllegalArgumentException("the slot has no course of travel"));
        if (path.entity().equals("GENERAL_PATH")) {
            return generalCourse(path);
        }
        if (path.entity().equals("CIRCULAR_PATH")
                && path.sweepAngle().isPresent()
                && Math.abs(Math.abs(path.sweepAngle().getAsDouble()) - 2 * Math.PI) < 1e-9) {
            // a full turn: the loop about the circle's centre, where the slot frame is
            double radius = path.radiusMm()
                    .orElseThrow(() -> new IllegalArgumentException("the slot's circular path has no radius"));
            if (!(radius > 0 && radius <= MAX_LENGTH_MM)) {
                throw new IllegalArgumentException(
                        "the circular path's radius " + radius + " mm is outside 0 to " + MAX_LENGTH_MM + " mm");
            }
            return new SlotMilling.Course.General(List.of(Arc2.circle(Vec2.ZERO, radius, true)), true);
        }
        if (path.entity().equals("CIRCULAR_PATH")) {
            return new SlotMilling.Course.Arc(
                    path.radiusMm()
                            .orElseThrow(() -> new IllegalArgumentException("the slot's circular path has no radius")),
                    path.sweepAngle()
                            .orElseThrow(
                                    () -> new IllegalArgumentException("the slot's circular path has no sweep_angle")));
        }
        return new SlotMilling.Course.Straight(slotLength(f));
    }

    /**
     * A GENERAL_PATH's curve in the feature frame, flat on the feature's xy plane: open, or
     * closed (a loop), turned counter-clockwise then.
     */
    static SlotMilling.Course.General generalCourse(org.fresa.stepnc.TravelPath path) {
        if (path.curve().isEmpty()) {
            throw new UnsupportedOperationException("the slot's GENERAL_PATH has no swept_path the planner reads: a"
                    + " POLYLINE, or a COMPOSITE_CURVE of trimmed lines and circles, is machined");
        }
        Transform3 pl = path.placement();
        if (pl.zAxis().minus(Vec3.UNIT_Z).norm() > 1e-9) {
            throw new UnsupportedOperationException(
                    "the slot's general path does not lie square to the feature's axis: its axis is "
                            + axis(pl.zAxis()));
        }
        List<Curve2> cs = new ArrayList<>();
        double z0 = Double.NaN;
        for (org.fresa.stepnc.Profile.Segment s : path.curve()) {
            Vec3 a = pl.applyToPoint(s.start());
            Vec3 b = pl.applyToPoint(s.end());
            for (Vec3 p : List.of(a, b)) {
                if (Double.isNaN(z0)) {
                    z0 = p.z();
                } else if (Math.abs(p.z() - z0) > 1e-6) {
                    throw new UnsupportedOperationException("the slot's general path is not flat: it runs from z "
                            + mm(z0) + " to " + mm(p.z()) + " mm");
                }
                if (Math.max(Math.abs(p.x()), Math.abs(p.y())) > MAX_LENGTH_MM) {
                    throw new IllegalArgumentException(
                            "the slot's general path reaches beyond " + MAX_LENGTH_MM + " mm of its feature's origin");
                }
            }
            Vec2 a2 = new Vec2(a.x(), a.y());
            Vec2 b2 = new Vec2(b.x(), b.y());
            if (s instanceof org.fresa.stepnc.Profile.Arc arc) {
                Vec3 c = pl.applyToPoint(arc.center());
                cs.add(new Arc2(new Vec2(c.x(), c.y()), a2, b2, arc.ccw()));
            } else if (a2.distance(b2) > 1e-9) {
                cs.add(new Segment2(a2, b2));
            }
        }
        if (cs.isEmpty()) {
            throw new IllegalArgumentException("the slot's general path has no length");
        }
        for (int i = 0; i + 1 < cs.size(); i++) {
            if (cs.get(i).end().distance(cs.get(i + 1).start()) > 1e-6) {
                throw new IllegalArgumentException(
                        "the slot's general path is broken between its elements " + (i + 1) + " and " + (i + 2));
            }
        }
        boolean closed = cs.get(0).start().distance(cs.get(cs.size() - 1).end()) <= 1e-6;
        if (closed) {
            Contour c = Contour.of(cs, Tolerance.DRAWING).ccw();
            return new SlotMilling.Course.General(c.curves(), true);
        }
        return new SlotMilling.Course.General(cs, false);
    }

    /**
     * The slot's frame in the feature frame, z the feature's axis: along a linear path, its
     * middle with x along the path; along a circular path, the circle's centre (the path's
     * placement) with x towards the path's start.
     */
    static Transform3 slotFrame(Feature f) {
        org.fresa.stepnc.TravelPath path = f.courseOfTravel().orElseThrow();
        if (path.entity().equals("GENERAL_PATH")) {
            // the path's curve is read into the feature frame itself
            return Transform3.IDENTITY;
        }
        if (path.entity().equals("CIRCULAR_PATH")) {
            if (path.placement().zAxis().cross(Vec3.UNIT_Z).norm() > 1e-9) {
                throw new UnsupportedOperationException(
                        "the slot's circular path is not square to the feature's axis: its axis is "
                                + axis(path.placement().zAxis()));
            }
            Vec3 x = path.placement().applyToDirection(Vec3.UNIT_X);
            if (path.placement().zAxis().z() < 0) {
                // a path turning about -z sweeps clockwise seen from the tool: its frame is mirrored
                throw new UnsupportedOperationException("the slot's circular path turns about the feature's -z axis");
            }
            Vec3 centre = path.placement().applyToPoint(Vec3.ZERO);
            return Transform3.ofFrame(
                    new Vec3(centre.x(), centre.y(), 0), Vec3.UNIT_Z, new Vec3(x.x(), x.y(), 0).normalized());
        }
        Vec3 dir = path.placement().applyToDirection(path.direction().orElse(Vec3.UNIT_X));
        Vec3 along = new Vec3(dir.x(), dir.y(), 0);
        if (along.norm() < 1e-9) {
            throw new UnsupportedOperationException("the slot's path runs along the tool axis");
        }
        along = along.normalized();
        Vec3 start = path.placement().applyToPoint(Vec3.ZERO);
        Vec3 middle = start.plus(along.times(slotLength(f) / 2));
        return Transform3.ofFrame(new Vec3(middle.x(), middle.y(), 0), Vec3.UNIT_Z, along);
    }

    private static ToolpathSection face(
            String label, Feature f, Operation op, Heights h, Tooling t, List<String> problems) {
        double d = stepover(op, t);
        Vec2 course = f.courseOfTravel()
                .flatMap(c -> c.direction().map(dir -> c.placement().applyToDirection(dir)))
                .map(v -> new Vec2(v.x(), v.y()))
                .orElse(Vec2.UNIT_X);
        Box2 box = faceBoundary(f);
        bounded("the face", Math.max(box.width(), box.height()), "the stepover", d);
        boolean bidirectional = true;
        var st = op.strategy().map(org.fresa.stepnc.Strategy::type);
        if (st.isPresent() && st.get() == org.fresa.stepnc.Strategy.StrategyType.UNIDIRECTIONAL) {
            bidirectional = false;
        } else if (st.isPresent() && st.get() != org.fresa.stepnc.Strategy.StrategyType.BIDIRECTIONAL) {
            problems.add("workingstep '" + label + "': " + st.get() + " on a planar face is milled bidirectionally");
        }
        double overcut = op.overcutLengthMm().orElse(0.25 * t.diameterMm());
        double bottom = h.bottomZ() + bottomAllowanceMm(op);
        Heights hh = new Heights(h.clearanceZ(), h.retractZ(), h.topZ(), bottom);
        boolean left = !op.strategy()
                .flatMap(org.fresa.stepnc.Strategy::stepoverDirection)
                .map(x -> x.equalsIgnoreCase("RIGHT"))
                .orElse(false);
        return FaceMilling.section(
                label, box, course, hh, t, d, op.axialCuttingDepthMm().orElse(0), overcut, bidirectional, left);
    }

    /**
     * A planar face's removal boundary in the feature frame: its rectangular profile, or its
     * linear profile swept along the course of travel.
     */
    public static Box2 faceBoundary(Feature f) {
        Vec2 course = f.courseOfTravel()
                .flatMap(c -> c.direction().map(dir -> c.placement().applyToDirection(dir)))
                .map(v -> new Vec2(v.x(), v.y()))
                .orElse(Vec2.UNIT_X);
        double along = f.courseOfTravel()
                .flatMap(c ->
                        c.distanceMm().isPresent() ? Optional.of(c.distanceMm().getAsDouble()) : Optional.empty())
                .orElse(0.0);
        Box2 box;
        org.fresa.stepnc.Profile sp =
                f.profile().orElseThrow(() -> new IllegalArgumentException("the planar face has no removal boundary"));
        Vec3 o = sp.placement().applyToPoint(Vec3.ZERO);
        if (sp instanceof org.fresa.stepnc.Profile.Linear lin) {
            Vec3 x = sp.placement().applyToDirection(Vec3.UNIT_X).times(lin.lengthMm());
            Vec2 p0 = new Vec2(o.x(), o.y());
            Vec2 a = new Vec2(x.x(), x.y());
            Vec2 b = course.normalized().times(along);
            box = Box2.of(p0, p0.plus(a))
                    .including(p0.plus(b))
                    .including(p0.plus(a).plus(b));
        } else if (sp instanceof org.fresa.stepnc.Profile.Rectangular r) {
            Vec2 c = new Vec2(o.x(), o.y());
            box = Box2.of(
                    c.minus(new Vec2(r.lengthMm() / 2, r.widthMm() / 2)),
                    c.plus(new Vec2(r.lengthMm() / 2, r.widthMm() / 2)));
        } else {
            throw new UnsupportedOperationException(
                    "planar faces bounded by " + sp.entity() + " are not supported yet");
        }
        return box;
    }

    private static boolean isRough(Operation op) {
        return switch (op.type()) {
            case PLANE_ROUGH_MILLING, SIDE_ROUGH_MILLING, BOTTOM_AND_SIDE_ROUGH_MILLING -> true;
            default -> false;
        };
    }

    private static double stepover(Operation op, Tooling t) {
        if (op.radialCuttingDepthMm().isPresent() && op.radialCuttingDepthMm().getAsDouble() > 0) {
            return op.radialCuttingDepthMm().getAsDouble();
        }
        var overlap = op.strategy()
                .flatMap(s -> s.overlapFraction().isPresent()
                        ? Optional.of(s.overlapFraction().getAsDouble())
                        : Optional.empty());
        if (overlap.isPresent() && overlap.get() >= 0 && overlap.get() < 1) {
            return Stepover.nominal(t.diameterMm(), overlap.get());
        }
        return t.diameterMm() / 2;
    }

    static Profile profile(org.fresa.stepnc.Profile sp, double cornerRadiusMm, Tolerance tol) {
        if (sp instanceof org.fresa.stepnc.Profile.Rectangular r) {
            double rc = Math.min(Math.max(cornerRadiusMm, 0), Math.min(r.lengthMm(), r.widthMm()) / 2);
            return new Profile.RoundedRectangle(Vec2.ZERO, r.lengthMm(), r.widthMm(), rc);
        }
        if (sp instanceof org.fresa.stepnc.Profile.Circular c) {
            return new Profile.Circle(Vec2.ZERO, c.diameterMm() / 2);
        }
        if (sp instanceof org.fresa.stepnc.Profile.Ngon n) {
            return new Profile.RegularPolygon(Vec2.ZERO, n.sides(), n.diameterMm(), n.circumscribed());
        }
        if (sp instanceof org.fresa.stepnc.Profile.General g && g.closed()) {
            List<Curve2> cs = new ArrayList<>();
            for (org.fresa.stepnc.Profile.Segment s : g.segments()) {
                Vec2 a = new Vec2(s.start().x(), s.start().y());
                Vec2 b = new Vec2(s.end().x(), s.end().y());
                if (s instanceof org.fresa.stepnc.Profile.Arc arc) {
                    cs.add(new Arc2(new Vec2(arc.center().x(), arc.center().y()), a, b, arc.ccw()));
                } else if (a.distance(b) > tol.linear()) {
                    cs.add(new Segment2(a, b));
                }
            }
            return new Profile.General(Contour.of(cs, Tolerance.DRAWING), ContourOffsetter.EXACT);
        }
        throw new UnsupportedOperationException("pocket profile " + sp.entity() + " is not supported");
    }

    private static ToolpathSection pocket(
            String label,
            Profile p,
            Operation op,
            Heights h,
            Tooling t,
            Transform3 profilePlacement,
            Tolerance tol,
            org.fresa.pocket.EntryRule entry) {
        Strategy s = strategy(op).orElse(Strategy.CONTOUR_PARALLEL);
        Vec2 feedDir = op.strategy()
                .flatMap(org.fresa.stepnc.Strategy::feedDirection)
                .map(v -> profilePlacement.inverse().applyToDirection(v))
                .map(v -> new Vec2(v.x(), v.y()))
                .filter(v -> v.norm() > 1e-9)
                .orElse(Vec2.UNIT_X);
        boolean rough = isRough(op);
        Box2 extent = p.contour(tol).bounds();
        bounded("the pocket", Math.max(extent.width(), extent.height()), "the stepover", stepover(op, t));
        MillingPlan plan = new MillingPlan(
                s,
                stepover(op, t),
                op.axialCuttingDepthMm().orElse(0),
                rough ? op.allowanceSideMm().orElse(0) : 0,
                rough ? op.allowanceBottomMm().orElse(0) : 0,
                feedDir,
                clockwise(op),
                approach(op.approach()),
                false,
                entry);
        return PocketMilling.section(label, p, h, t, plan, tol);
    }

    /** Included point angle of a drill when the tool data has none (deg), the common twist drill's. */
    static final double DEFAULT_POINT_ANGLE_DEG = 118;
    /** Largest tool_top_angle read as a drill point (deg from the plane normal to the axis). */
    static final double MAX_TOP_ANGLE_DEG = 80;

    /**
     * Length of the drill point along the axis (mm): r tan(tool_top_angle), the top angle measured
     * between the cutting edge and the plane normal to the axis (31 deg for a 118 deg point, as
     * ISO 14649-11 example 1 and STEP Modeler's files write it); an angle above 90 deg is read as
     * the included point angle; without a usable angle, a 118 deg point. 0 for reamers, boring bars and other drilling-type operations
     * whose tool has no point.
     */
    /**
     * How far below a through hole's exit the planner may take this operation's tool (mm): a
     * drill's point ({@link #tipLength}) or a milling cutter's edge radius, plus the breakthrough.
     * What a program check allows below the stock's bottom.
     */
    public static double throughAllowanceMm(Operation op, double toolDiameterMm, double breakthroughMm) {
        if (!(toolDiameterMm > 0)) {
            return breakthroughMm;
        }
        if (op.type().isDrillingType()) {
            return tipLength(op, new Tooling(1, toolDiameterMm, 0, 1, 1)) + breakthroughMm;
        }
        double edge = op.tool()
                .flatMap(x -> x.edgeRadiusMm().isPresent()
                        ? Optional.of(x.edgeRadiusMm().getAsDouble())
                        : Optional.empty())
                .filter(r -> r > 0 && r <= toolDiameterMm / 2)
                .orElse(0.0);
        return edge + breakthroughMm;
    }

    static double tipLength(Operation op, Tooling t) {
        Operation.OperationType k = op.type();
        if (k != Operation.OperationType.DRILLING
                && k != Operation.OperationType.MULTISTEP_DRILLING
                && k != Operation.OperationType.CENTER_DRILLING) {
            return 0;
        }
        Optional<Tool> tool = op.tool();
        double fromPlane = 90 - DEFAULT_POINT_ANGLE_DEG / 2;
        if (tool.isPresent() && tool.get().topAngle().isPresent()) {
            double a = tool.get().topAngle().getAsDouble();
            double deg = "rad".equals(tool.get().angleUnit()) ? Math.toDegrees(a) : a;
            double a2 = deg > 90 ? 90 - deg / 2 : deg;
            // a point steeper than 80 deg from the plane is no drill point: keep the default
            if (a2 > 0 && a2 <= MAX_TOP_ANGLE_DEG) {
                fromPlane = a2;
            }
        }
        return t.radiusMm() * Math.tan(Math.toRadians(fromPlane));
    }

    /**
     * The moves along the axis of a drilling-type operation: the drilling strategy's reduced feeds,
     * multistep drilling's steps (first_depth, depth_of_step, else one tool diameter; retract
     * distance) and the retract feed (feed_on_retract, else the feed for reaming and boring, which
     * must not mark the wall, else rapid); dwell_time_bottom, dwell_time_step (multistep drilling)
     * in seconds as ISO 14649 gives them, spindle_stop_at_bottom (reaming, boring) and the
     * strategy's spindle speed reductions.
     */
    static DrillCycle drillCycle(Operation op, Tooling t, double tipLength) {
        DrillingStrategy s =
                op.strategy().flatMap(org.fresa.stepnc.Strategy::drilling).orElse(DrillingStrategy.NONE);
        DrillingParameters p = op.drilling().orElse(DrillingParameters.NONE);
        boolean multistep = op.type() == Operation.OperationType.MULTISTEP_DRILLING;
        double step = multistep ? positive(p.depthOfStepMm(), t.diameterMm()) : 0;
        double first = multistep ? positive(p.firstDepthMm(), step) : 0;
        boolean feedOut = op.type() == Operation.OperationType.REAMING || op.type() == Operation.OperationType.BORING;
        double retractFeed = positive(p.feedOnRetract(), feedOut ? 1 : 0);
        return new DrillCycle(
                tipLength,
                positive(s.depthOfStartMm(), 0),
                positive(s.reducedFeedAtStart(), 1),
                positive(s.depthOfEndMm(), 0),
                positive(s.reducedFeedAtEnd(), 1),
                first,
                step,
                positive(p.retractDistanceMm(), 0),
                retractFeed,
                positive(p.dwellTimeBottomS(), 0),
                multistep ? positive(p.dwellTimeStepS(), 0) : 0,
                p.spindleStopAtBottom().orElse(false),
                positive(s.reducedCutAtStart(), 1),
                positive(s.reducedCutAtEnd(), 1));
    }

    /**
     * The drilling attributes of an operation that the moves do not carry: spindle speed
     * reductions (reduced_cut_at_start/end below 1) and a spindle_stop_at_bottom when the
     * operation has no spindle speed (to reduce, or to start again at), and a dwell_time_step
     * outside multistep drilling (where there are no steps); empty for other operations. Dwells,
     * the spindle stop and speed changes are moves otherwise.
     */
    static List<String> notInTheMoves(Operation op) {
        return notInTheMoves(op, op.technology().spindleRpm().orElse(0));
    }

    /** {@link #notInTheMoves(Operation)} for an operation cut at this spindle speed (rpm, 0 for none). */
    static List<String> notInTheMoves(Operation op, double spindleRpm) {
        List<String> out = new ArrayList<>();
        boolean noSpeed = !(spindleRpm > 0);
        op.strategy().flatMap(org.fresa.stepnc.Strategy::drilling).ifPresent(d -> {
            if (noSpeed
                    && d.reducedCutAtStart().isPresent()
                    && d.reducedCutAtStart().getAsDouble() != 1) {
                out.add("reduced_cut_at_start " + d.reducedCutAtStart().getAsDouble() + " (no spindle speed)");
            }
            if (noSpeed
                    && d.reducedCutAtEnd().isPresent()
                    && d.reducedCutAtEnd().getAsDouble() != 1) {
                out.add("reduced_cut_at_end " + d.reducedCutAtEnd().getAsDouble() + " (no spindle speed)");
            }
        });
        op.drilling().ifPresent(p -> {
            if (p.dwellTimeStepS().isPresent()
                    && p.dwellTimeStepS().getAsDouble() > 0
                    && op.type() != Operation.OperationType.MULTISTEP_DRILLING) {
                out.add("dwell_time_step " + p.dwellTimeStepS().getAsDouble() + " s (no steps)");
            }
            if (p.spindleStopAtBottom().orElse(false) && noSpeed) {
                out.add("spindle_stop_at_bottom (no spindle speed to start again at)");
            }
        });
        return out;
    }

    private static double positive(java.util.OptionalDouble v, double otherwise) {
        return v.isPresent() && v.getAsDouble() > 0 && Double.isFinite(v.getAsDouble()) ? v.getAsDouble() : otherwise;
    }

    /** Whether the feature's bottom condition is a through bottom (ISO 14649-10 through_bottom_condition). */
    static boolean isThrough(Feature f) {
        return f.bottomCondition().map(b -> b.contains("THROUGH")).orElse(false);
    }

    /**
     * Distance (mm) from a feature's origin down its axis (-z of the feature frame) to where the
     * axis leaves its workpiece's BLOCK: the depth of a through hole whose file gives none.
     *
     * @throws IllegalArgumentException when the file has no block for the feature's workpiece or
     *     the axis does not pass through it
     */
    static double stockDepth(StepNcProgram program, Feature f, Tolerance tol) {
        org.fresa.stepnc.Workpiece.Block b = program.workpieceOf(f)
                .flatMap(org.fresa.stepnc.Workpiece::block)
                .orElseThrow(() -> new IllegalArgumentException("the through hole has no depth and the file gives"
                        + " no workpiece BLOCK to find the bottom of the stock"));
        Transform3 toBlock = b.placement().inverse();
        Vec3 o = toBlock.applyToPoint(f.location());
        Vec3 d = toBlock.applyToDirection(f.axis().negated());
        double[] from = {o.x(), o.y(), o.z()};
        double[] dir = {d.x(), d.y(), d.z()};
        double[] size = {b.xMm(), b.yMm(), b.zMm()};
        double in = Double.NEGATIVE_INFINITY;
        double out = Double.POSITIVE_INFINITY;
        for (int i = 0; i < 3; i++) {
            double lo = Math.min(0, size[i]);
            double hi = Math.max(0, size[i]);
            if (Math.abs(dir[i]) < 1e-12) {
                if (from[i] < lo - tol.linear() || from[i] > hi + tol.linear()) {
                    out = Double.NEGATIVE_INFINITY;
                }
                continue;
            }
            double t1 = (lo - from[i]) / dir[i];
            double t2 = (hi - from[i]) / dir[i];
            in = Math.max(in, Math.min(t1, t2));
            out = Math.min(out, Math.max(t1, t2));
        }
        if (!(out > tol.linear() && out >= in && out <= MAX_LENGTH_MM)) {
            throw new IllegalArgumentException("the through hole has no depth and its axis does not pass through the"
                    + " workpiece BLOCK (" + mm(b.xMm()) + " x " + mm(b.yMm()) + " x " + mm(b.zMm()) + " mm)");
        }
        return out;
    }

    static String mm(double v) {
        return org.fresa.model.ExactDecimal.of(Math.round(v * 1e6) / 1e6 + 0.0);
    }

    /**
     * A round hole. Drilling-type operations: the tool tip goes to cutting_depth when the file
     * gives it (ISO 14649-11: the depth the tool reaches; nothing is added to it), else to the
     * hole's depth, and through a through hole to its depth plus the tip and the breakthrough,
     * so that the full diameter passes the exit by the breakthrough. Milling operations: to the
     * hole's depth, and through a through hole to its depth plus the breakthrough plus the
     * cutter's edge radius, so that no skin is left at the exit.
     */
    private static ToolpathSection hole(
            String label,
            Feature f,
            Operation op,
            Heights h,
            Tooling t,
            Tolerance tol,
            PlanningChoices choices,
            List<String> problems) {
        double breakthroughMm = choices.breakthroughMm();
        double holeD = f.diameterMm().orElseThrow(() -> new IllegalArgumentException("the hole has no diameter"));
        boolean through = isThrough(f);
        double holeDepth = h.topZ() - h.bottomZ();
        if (op.type().isDrillingType()) {
            double tip = tipLength(op, t);
            double depth;
            if (op.cuttingDepthMm().isPresent()) {
                depth = op.cuttingDepthMm().getAsDouble();
                double past = depth - tip - holeDepth;
                // a cutting_depth meant to reach the exit that stops the full diameter short of the breakthrough
                if (through && depth >= holeDepth - tol.linear() && past < breakthroughMm - tol.linear()) {
                    problems.add("workingstep '" + label + "': cutting_depth " + mm(depth) + " mm takes the full"
                            + " diameter " + mm(past) + " mm past the exit of the through hole (" + mm(holeDepth)
                            + " mm deep, tip " + mm(tip) + " mm), less than the breakthrough " + mm(breakthroughMm)
                            + " mm; drilled to cutting_depth as the file says");
                }
            } else {
                depth = holeDepth + (through ? tip + breakthroughMm : 0);
            }
            if (!(depth > 0 && depth <= MAX_LENGTH_MM)) {
                throw new IllegalArgumentException(
                        "drilling depth " + mm(depth) + " mm is not between 0 and " + MAX_LENGTH_MM + " mm");
            }
            Heights hh = new Heights(h.clearanceZ(), h.retractZ(), h.topZ(), h.topZ() - depth);
            DrillCycle cycle = drillCycle(op, t, tip);
            if (cycle.peck() > 0) {
                bounded("depth", depth, "depth_of_step", cycle.peck());
            }
            return HoleMaking.drill(label, Vec2.ZERO, hh, t, cycle);
        }
        if (!op.type().isMilling()) {
            throw new UnsupportedOperationException(op.type() + " is not supported yet");
        }
        Heights hm = h;
        if (through) {
            // a corner radius leaves a fillet of its height at the exit: the cutter goes that much further
            double edge = op.tool()
                    .flatMap(x -> x.edgeRadiusMm().isPresent()
                            ? Optional.of(x.edgeRadiusMm().getAsDouble())
                            : Optional.empty())
                    .filter(r -> r > 0 && r <= t.radiusMm())
                    .orElse(0.0);
            hm = new Heights(h.clearanceZ(), h.retractZ(), h.topZ(), h.bottomZ() - breakthroughMm - edge);
        }
        double ap = op.axialCuttingDepthMm().orElse(0);
        if (HoleMaking.helicalClears(holeD, t.diameterMm())) {
            return HoleMaking.mill(
                    label,
                    Vec2.ZERO,
                    holeD,
                    hm,
                    t,
                    ap,
                    clockwise(op),
                    choices.entry().angleDeg(),
                    tol);
        }
        bounded("the hole", holeD, "the stepover", stepover(op, t));
        Profile circle = new Profile.Circle(Vec2.ZERO, holeD / 2);
        double room = holeD / 2 - t.radiusMm();
        Approach a = new Approach.Helix(Math.max(room / 2, 0.1), 5);
        MillingPlan plan = new MillingPlan(
                strategy(op).orElse(Strategy.CONTOUR_PARALLEL),
                stepover(op, t),
                ap,
                0,
                0,
                Vec2.UNIT_X,
                clockwise(op),
                a,
                false,
                choices.entry());
        return PocketMilling.section(label, circle, hm, t, plan, tol);
    }

    static Optional<Strategy> strategy(Operation op) {
        return op.strategy().flatMap(s -> switch (s.type()) {
            case UNIDIRECTIONAL -> Optional.of(Strategy.UNIDIRECTIONAL);
            case BIDIRECTIONAL -> Optional.of(Strategy.BIDIRECTIONAL);
            case CONTOUR_PARALLEL -> Optional.of(Strategy.CONTOUR_PARALLEL);
            case CONTOUR_SPIRAL -> Optional.of(Strategy.CONTOUR_SPIRAL);
            case BIDIRECTIONAL_CONTOUR -> Optional.of(Strategy.BIDIRECTIONAL_CONTOUR);
            case CONTOUR_BIDIRECTIONAL -> Optional.of(Strategy.CONTOUR_BIDIRECTIONAL);
            case CENTER_MILLING -> Optional.of(Strategy.CENTER_MILLING);
            default -> Optional.empty();
        });
    }

    static boolean clockwise(Operation op) {
        var s = op.strategy();
        if (s.isEmpty()) {
            return false;
        }
        if (s.get().rotationDirection().isPresent()) {
            return s.get().rotationDirection().get().equalsIgnoreCase("CW");
        }
        return !climb(op);
    }

    static Approach approach(Optional<ApproachRetract> a) {
        if (a.isEmpty()) {
            return new Approach.Plunge();
        }
        ApproachRetract ar = a.get();
        double angle = ar.angle().orElse(0);
        return switch (ar.kind()) {
            case PLUNGE_RAMP, PLUNGE_ZIGZAG ->
                angle > 0 && angle <= 90 ? new Approach.Ramp(angle) : new Approach.Plunge();
            case PLUNGE_HELIX ->
                ar.radiusMm().isPresent() && ar.radiusMm().getAsDouble() > 0 && angle > 0 && angle < 90
                        ? new Approach.Helix(ar.radiusMm().getAsDouble(), angle)
                        : new Approach.Plunge();
            default -> new Approach.Plunge();
        };
    }

    /**
     * The section starting and ending on the security plane: its first and last points moved
     * along the plane's normal onto it, joined to the section by rapids.
     *
     * <p>A tool whose axis points against the plane's normal works from the far side of the part
     * (the underside of a part whose security plane is above it): the straight link from its
     * retract point to the plane would cross the whole part, and no link through the plane
     * reaches it. Such a workingstep needs the part turned over, in another setup, and is refused
     * with that reason.
     *
     * @throws IllegalArgumentException for a tool axis against the plane's normal
     */
    static ToolpathSection viaSecurityPlane(ToolpathSection s, Optional<Transform3> plane) {
        if (plane.isEmpty()) {
            return s;
        }
        Vec3 o = plane.get().translationPart();
        Vec3 n = plane.get().zAxis();
        if (s.toolAxis().dot(n) < -AXIS_TOLERANCE) {
            throw new IllegalArgumentException("tool axis " + axis(s.toolAxis())
                    + " works from the far side of the part, against the security plane's normal " + axis(n)
                    + ": the link through the security plane would cross the part; it needs the part turned"
                    + " over, in another setup");
        }
        Vec3 first = s.start();
        Vec3 last = s.moves().isEmpty()
                ? first
                : s.moves().get(s.moves().size() - 1).end();
        Vec3 in = first.plus(n.times(o.minus(first).dot(n)));
        Vec3 out = last.plus(n.times(o.minus(last).dot(n)));
        List<Move> moves = new ArrayList<>();
        moves.add(new Move.Rapid(first));
        moves.addAll(s.moves());
        moves.add(new Move.Rapid(out));
        return new ToolpathSection(
                s.label(), s.toolAxis(), s.toolDiameterMm(), s.toolNumber(), s.spindleRpm(), in, moves);
    }

    /** How far from the plane's side an axis may lean and still be read as square to the normal. */
    static final double AXIS_TOLERANCE = 1e-9;

    /** An axis as the listings write it: "(0, 0, -1)". */
    public static String axis(Vec3 a) {
        return "(" + org.fresa.model.ExactDecimal.of(Math.round(a.x() * 1e4) / 1e4 + 0.0) + ", "
                + org.fresa.model.ExactDecimal.of(Math.round(a.y() * 1e4) / 1e4 + 0.0) + ", "
                + org.fresa.model.ExactDecimal.of(Math.round(a.z() * 1e4) / 1e4 + 0.0) + ")";
    }
}
