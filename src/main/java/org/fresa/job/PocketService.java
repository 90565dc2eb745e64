package org.fresa.job;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.fresa.cutting.DrawingContours;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Intersections;
import org.fresa.geom.Tolerance;
import org.fresa.io.AtomicFiles;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.model.CamInputException;
import org.fresa.model.ContourFile;
import org.fresa.model.FileChecks;
import org.fresa.model.Toolpath;
import org.fresa.pocket.DadReader;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.PassPlanner;
import org.fresa.pocket.PocketPlan;
import org.fresa.pocket.PocketProfile;
import org.fresa.pocket.PocketStrategy;
import org.fresa.pocket.PocketTechnology;
import org.fresa.pocket.PocketToolpath;
import org.fresa.pocket.Recognition;
import org.fresa.pocket.RegionOffsetter;
import org.fresa.pocket.RegionPocket;
import org.fresa.pocket.SlowedMove;
import org.fresa.pocket.StrategyPocket;
import org.fresa.pocket.ToolTooLargeException;
import org.fresa.pocket.ZigzagPocket;
import org.fresa.pocket.compat.PocketReport;
import org.fresa.pocket.compat.Sinumerik7MPost;
import org.fresa.post.NcPost;
import org.fresa.post.NcPosts;
import org.fresa.post.PocketPost;

/**
 * The pocket module's service, shared by {@code fresa pocket} and {@code fresa run}: reads the
 * contour ({@code .dad} or {@code .contour}), builds the recognition tree, plans the passes and
 * writes the NC program for the chosen post.
 */
public final class PocketService {

    /** Most elements a pocket contour may have: the recognition compares elements pairwise at each event. */
    public static final int MAX_ELEMENTS = 2000;

    private PocketService() {}

    /**
     * The contour of the settings: the elements the job holds (typed in the Pocket tab), else the
     * contour file's.
     */
    public static PocketProfile readContour(PocketSettings s) throws CamInputException, IOException {
        if (s.elements().isPresent()) {
            // the editor's check, so that a job edited by hand is refused as the tab refuses it
            java.util.Optional<org.fresa.pocket.DadContour.Refusal> r =
                    s.elements().get().refusal();
            if (r.isPresent()) {
                throw new CamInputException(
                        s.contour().toString(),
                        "the job's <elements>: " + r.get().message());
            }
            return s.elements().get().profile(s.contour().toString());
        }
        return readContour(s.contour());
    }

    /**
     * Whether the settings' contour may hold islands (a drawing or {@code .contour} file): a
     * {@code .dad} file and the elements a job holds are one loop, planned by the thesis's tree.
     */
    public static boolean mayHaveIslands(PocketSettings s) {
        return s.elements().isEmpty()
                && !s.contour()
                        .getFileName()
                        .toString()
                        .toLowerCase(Locale.ROOT)
                        .endsWith(".dad");
    }

    /** Reads a contour file by its extension (the outer contour's elements; islands kept as contours). */
    public static PocketProfile readContour(Path file) throws CamInputException, IOException {
        String lower = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (lower.endsWith(".dad")) {
            FileChecks.requireInput(file, "a pocket contour (.dad records)", FileChecks.MAX_TEXT_FILE_BYTES);
            return DadReader.read(Files.readString(file, StandardCharsets.ISO_8859_1), file.toString());
        }
        try {
            return PocketProfile.fromContours(readContours(file));
        } catch (IllegalArgumentException e) {
            // a contour the pocket model cannot take (one full circle, elements that vanish when merged)
            throw new CamInputException(file.toString(), e.getMessage());
        }
    }

    /**
     * The closed contours of a {@code .contour} or {@code .dxf} file, the outer one first and
     * counter-clockwise, then the islands (closed contours inside it), clockwise.
     *
     * @throws CamInputException when there is no contour, a chain is open, or an inner contour
     *     is not inside the outer one or crosses another
     */
    public static List<Contour> readContours(Path file) throws CamInputException, IOException {
        String lower = file.getFileName().toString().toLowerCase(Locale.ROOT);
        List<Contour> contours;
        if (lower.endsWith(".dxf")) {
            DrawingContours drawing = DrawingContours.read(file);
            if (drawing.openChains() > 0) {
                throw new CamInputException(
                        file.toString(),
                        drawing.openChains() + " open chain(s) in the drawing: a pocket needs closed contours");
            }
            contours = drawing.closed();
        } else {
            FileChecks.requireInput(file, "a contour file", FileChecks.MAX_TEXT_FILE_BYTES);
            String text = Files.readString(file, StandardCharsets.ISO_8859_1);
            contours = ContourFile.read(new StringReader(text), file.toString());
        }
        if (contours.isEmpty()) {
            throw new CamInputException(file.toString(), "no contour in the file");
        }
        int elements = contours.stream().mapToInt(Contour::size).sum();
        if (elements > MAX_ELEMENTS) {
            throw new CamInputException(
                    file.toString(),
                    "the contours have " + elements + " elements; pocket milling takes at most " + MAX_ELEMENTS
                            + " (simplify the drawing)");
        }
        return outerFirst(contours, file.toString());
    }

    /** The contour that encloses all others first (counter-clockwise), then the islands (clockwise). */
    static List<Contour> outerFirst(List<Contour> contours, String source) throws CamInputException {
        int outer = 0;
        for (int i = 1; i < contours.size(); i++) {
            if (contours.get(i).area() > contours.get(outer).area()) {
                outer = i;
            }
        }
        Contour o = contours.get(outer).ccw();
        List<Contour> out = new ArrayList<>();
        out.add(o);
        Tolerance tol = Tolerance.DEFAULT;
        for (int i = 0; i < contours.size(); i++) {
            if (i == outer) {
                continue;
            }
            Contour c = contours.get(i);
            for (Curve2 k : c.curves()) {
                if (!o.contains(k.start(), tol) || !o.contains(k.pointAt(0.5), tol)) {
                    throw new CamInputException(
                            source,
                            "contour " + (i + 1)
                                    + " is not inside the outer contour: an island must lie wholly inside it");
                }
            }
            out.add(c.isCcw() ? c.reversed() : c);
        }
        for (int i = 1; i < out.size(); i++) {
            for (int j = i + 1; j < out.size(); j++) {
                if (touch(out.get(i), out.get(j), tol)) {
                    throw new CamInputException(
                            source, "islands " + i + " and " + j + " touch or overlap: draw them as one contour");
                }
            }
        }
        return out;
    }

    private static boolean touch(Contour a, Contour b, Tolerance tol) {
        for (Curve2 x : a.curves()) {
            for (Curve2 y : b.curves()) {
                if (!Intersections.of(x, y, tol).isEmpty()) {
                    return true;
                }
            }
        }
        return b.windingNumber(a.get(0).start()) != 0
                || a.windingNumber(b.get(0).start()) != 0;
    }

    /** The technology of the settings. */
    static PocketTechnology technology(PocketSettings s) throws CamInputException {
        return technology(s, s.zBottomMm());
    }

    /** The plan for the settings (no file written). */
    public static PocketPlan plan(PocketSettings s) throws CamInputException, IOException, ToolTooLargeException {
        return plan(s, s.post().thesis());
    }

    /** The plan for the settings; faithful: the thesis's pass rules exactly. */
    public static PocketPlan plan(PocketSettings s, boolean faithful)
            throws CamInputException, IOException, ToolTooLargeException {
        PocketTechnology tech = technology(s);
        PocketProfile profile = readContour(s);
        if (!profile.islands().isEmpty()) {
            throw new CamInputException(
                    s.contour().toString(),
                    "the thesis's recognition tree has no islands ("
                            + profile.islands().size() + " found): the pocket is planned by Fresa's region engine, "
                            + "written by fresa pocket or Job > Run with a post other than 7m");
        }
        return PassPlanner.plan(profile, tech, faithful);
    }

    /** The NC program text for a plan, climb-milled on the G-code posts and 7m, with the default entries. */
    public static String program(PocketPlan plan, PocketPost post, String programName)
            throws IOException, ToolTooLargeException {
        return program(plan, post, programName, true);
    }

    /** The NC program text for a plan with the default entries ({@link EntryRule#DEFAULT}). */
    public static String program(PocketPlan plan, PocketPost post, String programName, boolean climb)
            throws IOException, ToolTooLargeException {
        return program(plan, post, programName, climb, EntryRule.DEFAULT);
    }

    /**
     * The NC program text for a plan.
     *
     * @param climb climb milling (counter-clockwise passes with a clockwise spindle) or conventional
     *     on the G-code posts and {@code 7m}; {@code 7m-compat} writes the thesis's own direction (its
     *     passes as generated, conventional)
     * @param entry how each sub-area is entered at each depth on the G-code posts and {@code 7m};
     *     {@code 7m-compat} keeps the thesis's vertical plunge
     * @throws ToolTooLargeException when an entry has no room and the tool may not plunge
     */
    public static String program(PocketPlan plan, PocketPost post, String programName, boolean climb, EntryRule entry)
            throws IOException, ToolTooLargeException {
        switch (post) {
            case SINUMERIK_7M_COMPAT:
                return new Sinumerik7MPost(Sinumerik7MPost.Mode.COMPAT).write(plan);
            case SINUMERIK_7M:
                return new Sinumerik7MPost(Sinumerik7MPost.Mode.CORRECTED, climb, entry).write(plan);
            default: {
                NcPost p = post.gcode().orElseThrow().ncPost();
                StringWriter w = new StringWriter();
                p.write(PocketToolpath.of(plan, climb, entry), programName, w);
                return w.toString();
            }
        }
    }

    /**
     * Runs the pocket job as {@link #run(PocketSettings, Path, ProgressMonitor)} does, then, when the
     * program is written, the thesis's technology printout ({@link PocketReport}) to {@code report};
     * the summary names both ({@code out}, {@code report}).
     */
    public static TaskOutcome run(
            PocketSettings s, Path outFile, java.util.Optional<Path> report, ProgressMonitor progress)
            throws CamInputException, IOException {
        return run(s, outFile, report, Optional.empty(), progress);
    }

    /**
     * Runs the pocket job as {@link #run(PocketSettings, Path, Optional, ProgressMonitor)} does and,
     * for adaptive clearing, writes the moves it slowed to {@code slowed} as CSV ({@link
     * #slowedCsv}), one row a move in program order (a header only when none is slowed); the
     * summary names it ({@code slowed_csv}).
     *
     * @throws CamInputException when a list of slowed moves is asked of another strategy
     */
    public static TaskOutcome run(
            PocketSettings s, Path outFile, Optional<Path> report, Optional<Path> slowed, ProgressMonitor progress)
            throws CamInputException, IOException {
        if (slowed.isPresent() && s.strategy().kind() != PocketStrategy.Kind.ADAPTIVE) {
            throw new CamInputException(
                    "--slowed",
                    "only adaptive clearing slows its feed (--strategy adaptive); "
                            + s.strategy().kind().word() + " cuts every move at the programmed feeds");
        }
        if (slowed.isPresent()) {
            Path o = slowed.get().toAbsolutePath().normalize();
            if (o.equals(outFile.toAbsolutePath().normalize())
                    || (report.isPresent()
                            && o.equals(report.get().toAbsolutePath().normalize()))) {
                throw new CamInputException("--slowed", slowed.get() + " is the program's or the report's own file");
            }
        }
        if (report.isPresent()
                && report.get()
                        .toAbsolutePath()
                        .normalize()
                        .equals(outFile.toAbsolutePath().normalize())) {
            throw new CamInputException("--report", report.get() + " is the program's own file (--out)");
        }
        TaskOutcome o = runPlanned(s, outFile, slowed, progress);
        if (report.isEmpty() || o.exitStatus() != 0) {
            return o;
        }
        AtomicFiles.writeString(report.get(), PocketReport.of(technology(s)));
        Map<String, Object> summary = new LinkedHashMap<>(o.summary());
        summary.put("report", report.get().toString());
        List<Path> files = new ArrayList<>(o.files());
        files.add(report.get());
        return new TaskOutcome(o.exitStatus(), o.problems(), summary, files);
    }

    /**
     * Runs the pocket job and writes the NC program to outFile. A stepover asked below half the
     * tool's diameter is planned at half (the least the planners step, {@link
     * org.fresa.pocket.PocketTechnology#effectiveCut}), and the outcome says so.
     */
    public static TaskOutcome run(PocketSettings s, Path outFile, ProgressMonitor progress)
            throws CamInputException, IOException {
        return runPlanned(s, outFile, Optional.empty(), progress);
    }

    private static TaskOutcome runPlanned(
            PocketSettings s, Path outFile, Optional<Path> slowed, ProgressMonitor progress)
            throws CamInputException, IOException {
        TaskOutcome o = planAndWrite(s, outFile, slowed, progress);
        Optional<String> raised = cutRaised(s);
        if (raised.isEmpty()) {
            return o;
        }
        List<String> problems = new ArrayList<>();
        problems.add(raised.get());
        problems.addAll(o.problems());
        return new TaskOutcome(o.exitStatus(), problems, o.summary(), o.files());
    }

    /**
     * The warning for a stepover asked below the least the planners step, which they raise to it;
     * empty when the asked one is planned.
     */
    public static Optional<String> cutRaised(PocketSettings s) {
        if (s.cutFraction() >= org.fresa.pocket.PocketTechnology.LEAST_CUT
                || s.strategy().adaptive()) {
            return Optional.empty();
        }
        return Optional.of("warning: --cut " + org.fresa.model.ExactDecimal.of(s.cutFraction()) + " is planned as "
                + org.fresa.model.ExactDecimal.of(org.fresa.pocket.PocketTechnology.LEAST_CUT)
                + ": the passes step at least half the tool's diameter (the thesis's least stepover, which the"
                + " planners keep)");
    }

    /**
     * The warnings of the thesis's own plan of a pocket without islands: a tool that does not
     * pass every bottleneck, and the wall the printed program cuts where the thesis snaps a
     * junction ({@link #thesisGouge}).
     */
    public static List<String> planWarnings(PocketSettings s, PocketPlan plan) throws CamInputException, IOException {
        List<String> problems = new ArrayList<>();
        Recognition.Result rec = plan.recognition();
        double a = s.finishFraction() * s.toolDiameterMm();
        if (rec.maxToolDiameterMm() < s.toolDiameterMm() + a + 0.1) {
            problems.add("warning: the tool does not pass every bottleneck (DIAMETRO MAXIMO "
                    + String.format(Locale.ROOT, "%.3f", rec.maxToolDiameterMm()) + " mm)");
        }
        if (s.post().thesis()) {
            thesisGouge(readContour(s)).ifPresent(problems::add);
        }
        return problems;
    }

    private static TaskOutcome planAndWrite(
            PocketSettings s, Path outFile, Optional<Path> slowed, ProgressMonitor progress)
            throws CamInputException, IOException {
        List<String> problems = new ArrayList<>();
        EntryRule entry = entryRule(s);
        if (!s.strategy().offset() || !s.strategy().asThesis()) {
            return runStrategy(s, outFile, slowed, progress);
        }
        if (mayHaveIslands(s)) {
            List<Contour> contours = readContours(s.contour());
            if (contours.size() > 1) {
                return runRegion(s, contours, outFile);
            }
        }
        PocketPlan plan;
        String nc;
        Toolpath path;
        boolean thesis = s.post().thesis();
        String name = s.contour().getFileName().toString();
        try {
            plan = plan(s);
            nc = program(plan, s.post(), name, s.climb(), entry);
            path = PocketToolpath.of(plan, !thesis && s.climb(), entry);
        } catch (ToolTooLargeException e) {
            return new TaskOutcome(1, List.of(e.getMessage()), Map.of(), List.of());
        }
        Recognition.Result rec = plan.recognition();
        problems.addAll(planWarnings(s, plan));
        Optional<TaskOutcome> refused = checkAndWrite(s, outFile, nc);
        if (refused.isPresent()) {
            return refused.get();
        }
        Map<String, Object> summary = new LinkedHashMap<>();
        summary.put("contour", s.contour().toString());
        summary.put("post", s.post().word());
        summary.put("leaf_offsets", rec.leafOffsets());
        summary.put("max_hole_diameter", rec.maxHoleDiameterMm());
        summary.put("max_tool_diameter", rec.maxToolDiameterMm());
        summary.put("wall_tool_diameter", rec.wallToolDiameterMm());
        // the thesis's passes as generated: clockwise, conventional with its clockwise (M3) spindle
        summary.put("direction", thesis ? "conventional" : s.direction().word());
        summary.put("passes", plan.milled().size());
        summary.put(
                "pass_offsets", plan.generated().stream().map(p -> p.offsetMm()).toList());
        summary.put("depth_passes", plan.technology().depthPasses());
        summary.put("path_length_mm", PocketToolpath.lengthMm(path));
        summary.put("out", outFile.toString());
        return new TaskOutcome(0, problems, summary, List.of(outFile));
    }

    /**
     * The warning for a program printed as the thesis printed it ({@code 7m-compat}) from a
     * contour whose elements miss each other at a junction the thesis snaps: its passes join
     * there at the snapped point, and its finishing pass cuts the wall beyond the step by the gap
     * (cavity 02: 0.755 mm past circle 6). Every other post plans the step as an element and
     * keeps to the wall ({@link PocketProfile#withBridgedJunctions()}).
     */
    static Optional<String> thesisGouge(PocketProfile profile) {
        List<PocketProfile.SnappedJunction> snapped = profile.snappedJunctions();
        if (snapped.isEmpty()) {
            return Optional.empty();
        }
        StringBuilder where = new StringBuilder();
        for (PocketProfile.SnappedJunction j : snapped) {
            where.append(where.length() == 0 ? "" : ", ")
                    .append(String.format(
                            Locale.ROOT,
                            "%.3f mm at (%.3f, %.3f)",
                            j.gapMm(),
                            j.point().x(),
                            j.point().y()));
        }
        return Optional.of(String.format(
                Locale.ROOT,
                "warning: the thesis's program as printed cuts into the wall by up to %.3f mm where it joins"
                        + " elements that miss each other (%s); a post other than 7m-compat keeps to the wall",
                snapped.get(0).gapMm(),
                where));
    }

    /**
     * The entry rule of the settings.
     *
     * @throws CamInputException (exit 2) for an angle out of range or a plunge
     *     asked for a tool that does not cut at its centre
     */
    static EntryRule entryRule(PocketSettings s) throws CamInputException {
        try {
            return s.entryRule();
        } catch (IllegalArgumentException e) {
            String option = e.getMessage().startsWith("a plunge") ? "--entry plunge" : "--entry";
            throw new CamInputException(
                    option,
                    e.getMessage()
                            + (option.equals("--entry plunge")
                                    ? ": say so with --centre-cutting, or choose auto, helix or ramp"
                                    : ""));
        }
    }

    /**
     * The region engine's plan for a pocket with islands ({@link RegionPocket}, climb or conventional
     * milling as the settings say).
     *
     * @param contours the outer contour first, then the islands ({@link #readContours})
     * @throws CamInputException for a 7M post (the thesis knows no islands) or bad technology
     */
    public static RegionPocket.Plan regionPlan(PocketSettings s, List<Contour> contours)
            throws CamInputException, ToolTooLargeException {
        if (s.post().sevenM()) {
            throw new CamInputException(
                    "--post",
                    "the thesis's 7M posts know no islands (" + (contours.size() - 1) + " found): choose one of "
                            + String.join(", ", NcPosts.names()));
        }
        return RegionPocket.plan(
                contours.get(0), contours.subList(1, contours.size()), technology(s), s.climb(), entryRule(s));
    }

    /** The program text of a region plan for a G-code post. */
    public static String regionProgram(RegionPocket.Plan plan, PocketPost post, String programName) throws IOException {
        NcPost p = post.gcode()
                .orElseThrow(() -> new IllegalArgumentException(post.word()))
                .ncPost();
        StringWriter w = new StringWriter();
        p.write(plan.toolpath(), programName, w);
        return w.toString();
    }

    /** A pocket with islands: Fresa's region engine ({@link RegionPocket}), G-code posts only. */
    static TaskOutcome runRegion(PocketSettings s, List<Contour> contours, Path outFile)
            throws CamInputException, IOException {
        PocketTechnology tech = technology(s);
        RegionPocket.Plan plan;
        try {
            plan = regionPlan(s, contours);
        } catch (ToolTooLargeException e) {
            return new TaskOutcome(1, List.of(e.getMessage()), Map.of(), List.of());
        }
        String name = s.contour().getFileName().toString();
        String nc = regionProgram(plan, s.post(), name);
        Optional<TaskOutcome> refused = checkAndWrite(s, outFile, nc);
        if (refused.isPresent()) {
            return refused.get();
        }
        double inradius = RegionOffsetter.inradius(
                RegionOffsetter.oriented(contours.get(0), contours.subList(1, contours.size())),
                new Tolerance(1e-4, 1e-9));
        Map<String, Object> summary = new LinkedHashMap<>();
        summary.put("contour", s.contour().toString());
        summary.put("post", s.post().word());
        summary.put("islands", contours.size() - 1);
        summary.put("direction", s.direction().word());
        summary.put("max_hole_diameter", 2 * inradius);
        summary.put("passes", plan.order().size());
        summary.put(
                "pass_offsets",
                plan.levels().stream().map(RegionPocket.Level::offsetMm).toList());
        summary.put("depth_passes", tech.depthPasses());
        summary.put("path_length_mm", PocketToolpath.lengthMm(plan.toolpath()));
        summary.put("out", outFile.toString());
        return new TaskOutcome(0, List.of(), summary, List.of(outFile));
    }

    /**
     * The warnings of a strategy's plan, as {@code fresa pocket}, Job > Run and the Pocket tab give
     * them: a rest tool with nothing to cut, and the moves of adaptive clearing fed slower where the
     * walks cannot hold the stepover.
     */
    public static List<String> strategyWarnings(StrategyPocket.Planned planned) {
        List<String> out = new ArrayList<>();
        planned.slowed()
                .filter(org.fresa.pocket.EngagementFeed.Slowed::any)
                .ifPresent(w -> out.add(String.format(
                        Locale.ROOT,
                        "warning: adaptive: %d cut(s) of the contour passes, %.1f mm a layer, take what the walks cannot"
                                + " reach at the stepover (a channel or corner narrower than the tool's centre turns in, or"
                                + " a face too small for an entry), up to %.0f deg of the tool at X%.3f Y%.3f against %.0f;"
                                + " their feed drops there to as little as %.2f of the programmed feed, so that they remove"
                                + " no more per minute than the stepover's cut",
                        w.moves(),
                        w.lengthMm(),
                        w.worstDeg(),
                        w.worstAt().x(),
                        w.worstAt().y(),
                        w.boundDeg(),
                        w.lowestFactor())));
        planned.rest().filter(r -> !r.cuts()).ifPresent(r -> out.add(REST_TOOL_IDLE));
        return out;
    }

    /**
     * The toolpath of the settings' strategy when it is not the thesis's engine's: zigzag lines
     * ({@link ZigzagPocket}), or offset passes with stock left or from the outside in
     * ({@link RegionPocket}). The contour: the outer one and its islands from a drawing or
     * {@code .contour} file, or the one loop of a {@code .dad} file or of the elements the job
     * holds. Stock to leave: the region offset inwards by it and the floor raised by it.
     *
     * @throws CamInputException for a 7M post (its blocks are the thesis's passes), stock to leave
     *     as deep as the pocket, bad technology or a bad contour
     */
    public static Toolpath strategyToolpath(PocketSettings s)
            throws CamInputException, IOException, ToolTooLargeException {
        return strategyPlan(s).toolpath();
    }

    /**
     * {@link #strategyToolpath} with the rest tool's plan, when there is a rest tool.
     *
     * @throws CamInputException as {@link #strategyToolpath}, or for a rest tool not smaller than
     *     the first as {@link #restToolRange} asks
     */
    public static StrategyPocket.Planned strategyPlan(PocketSettings s)
            throws CamInputException, IOException, ToolTooLargeException {
        return strategyPlan(s, ProgressMonitor.NONE);
    }

    /**
     * {@link #strategyPlan(PocketSettings)}, telling how far adaptive clearing's walks are (the
     * fraction of the floor they have cleared) and stopping when the user asks.
     */
    public static StrategyPocket.Planned strategyPlan(PocketSettings s, ProgressMonitor progress)
            throws CamInputException, IOException, ToolTooLargeException {
        PocketStrategy st = s.strategy();
        if (s.post().sevenM()) {
            String option = !st.offset()
                    ? "--strategy"
                    : st.stockToLeaveMm() > 0 ? "--stock-to-leave" : st.restTool() ? "--rest-tool" : "--order";
            String what = !st.offset()
                    ? st.kind().word()
                    : st.stockToLeaveMm() > 0
                            ? "stock to leave"
                            : st.restTool() ? "a rest tool (a second tool, T2)" : "passes outside in";
            throw new CamInputException(
                    option,
                    "the thesis's 7M posts write its own offset passes only: " + what + " needs one of "
                            + String.join(", ", NcPosts.names()));
        }
        if (st.restTool()) {
            restToolRange(s.toolDiameterMm()).check(st.restToolDiameterMm());
        }
        List<Contour> contours = strategyContours(s);
        try {
            return StrategyPocket.plan(
                    contours.get(0),
                    contours.subList(1, contours.size()),
                    technology(s),
                    st,
                    s.climb(),
                    entryRule(s),
                    f -> {
                        progress.checkCancelled();
                        progress.progress(
                                f, String.format(Locale.ROOT, "adaptive walks: %.0f %% of the floor", 100 * f));
                    });
        } catch (IllegalArgumentException e) {
            throw new CamInputException("--stock-to-leave", e.getMessage());
        }
    }

    /**
     * The rest tool's diameters with a first tool of this diameter: from
     * {@link PocketStrategy#MIN_REST_TOOL_MM} (the smallest tool, as {@code --tool-diameter}) to
     * below the first's less {@link PocketStrategy#REST_TOOL_MARGIN_MM} (mm), as
     * {@code --rest-tool} and the job's {@code restToolDiameterMm} take them.
     */
    public static org.fresa.setting.SettingRange restToolRange(double firstToolDiameterMm) {
        return new org.fresa.setting.SettingRange(
                "--rest-tool",
                "restToolDiameterMm",
                PocketStrategy.MIN_REST_TOOL_MM,
                true,
                Math.max(2 * PocketStrategy.MIN_REST_TOOL_MM, firstToolDiameterMm - PocketStrategy.REST_TOOL_MARGIN_MM),
                false,
                "mm",
                false);
    }

    private static PocketTechnology technology(PocketSettings s, double floorMm) throws CamInputException {
        try {
            return new PocketTechnology(
                    s.toolDiameterMm(),
                    s.cutFraction(),
                    s.finishFraction(),
                    s.zTopMm(),
                    floorMm,
                    s.maxDepthPerPassMm(),
                    s.spindleRpm(),
                    s.feedMmPerMin(),
                    s.finishFeedMmPerMin());
        } catch (IllegalArgumentException e) {
            throw new CamInputException("technology", e.getMessage());
        }
    }

    /** The outer contour and its islands a strategy plans ({@link #strategyToolpath}). */
    public static List<Contour> strategyContours(PocketSettings s) throws CamInputException, IOException {
        if (mayHaveIslands(s)) {
            return readContours(s.contour());
        }
        PocketProfile profile = readContour(s);
        try {
            return List.of(profile.outline());
        } catch (IllegalArgumentException e) {
            throw new CamInputException(s.contour().toString(), e.getMessage());
        }
    }

    /** The program text of a toolpath for a G-code or APT post. */
    public static String toolpathProgram(Toolpath path, PocketPost post, String programName) throws IOException {
        NcPost p = post.gcode()
                .orElseThrow(() -> new IllegalArgumentException(post.word()))
                .ncPost();
        StringWriter w = new StringWriter();
        p.write(path, programName, w);
        return w.toString();
    }

    /** A pocket planned by its strategy ({@link #strategyToolpath}): G-code and APT posts only. */
    static TaskOutcome runStrategy(PocketSettings s, Path outFile, ProgressMonitor progress)
            throws CamInputException, IOException {
        return runStrategy(s, outFile, Optional.empty(), progress);
    }

    private static TaskOutcome runStrategy(
            PocketSettings s, Path outFile, Optional<Path> slowed, ProgressMonitor progress)
            throws CamInputException, IOException {
        StrategyPocket.Planned planned;
        try {
            planned = strategyPlan(s, progress);
        } catch (ToolTooLargeException e) {
            return new TaskOutcome(1, List.of(e.getMessage()), Map.of(), List.of());
        }
        Toolpath path = planned.toolpath();
        String nc = toolpathProgram(path, s.post(), s.contour().getFileName().toString());
        Optional<TaskOutcome> refused = checkAndWrite(s, outFile, nc);
        if (refused.isPresent()) {
            return refused.get();
        }
        PocketStrategy st = s.strategy();
        Map<String, Object> summary = new LinkedHashMap<>();
        summary.put("contour", s.contour().toString());
        summary.put("post", s.post().word());
        summary.put("strategy", st.kind().word());
        if (st.zigzag()) {
            summary.put("angle_deg", st.angleDeg());
        } else if (st.offset()) {
            summary.put("order", st.order().word());
        }
        summary.put("stock_to_leave_mm", st.stockToLeaveMm());
        if (!mayHaveIslands(s) || readContours(s.contour()).size() == 1) {
            // the thesis's measures of the contour (FURO MAXIMO, DIAMETRO MAXIMO, DIAMETRO p/
            // SUPERF) belong to the pocket, whatever strategy clears it: the command line's
            // contract gives them for every single-contour pocket
            // (a contour the thesis's recognition cannot read, e.g. one circle, has none of them)
            Optional<Recognition.Result> rec = recognition(s);
            if (rec.isPresent()) {
                summary.put("leaf_offsets", rec.get().leafOffsets());
                summary.put("max_hole_diameter", rec.get().maxHoleDiameterMm());
                summary.put("max_tool_diameter", rec.get().maxToolDiameterMm());
                summary.put("wall_tool_diameter", rec.get().wallToolDiameterMm());
            }
        }
        summary.put("direction", s.direction().word());
        summary.put("passes", planned.passes());
        summary.put(
                "depth_passes",
                technology(s, s.zBottomMm() + st.stockToLeaveMm()).depthPasses());
        summary.put("path_length_mm", PocketToolpath.lengthMm(path));
        List<String> problems = strategyWarnings(planned);
        if (planned.rest().isPresent()) {
            org.fresa.pocket.RestMachining.Plan rest = planned.rest().get();
            summary.put("rest_tool_diameter_mm", st.restToolDiameterMm());
            summary.put("rest_tool_rpm", rest.technology().spindleRpm());
            summary.put("rest_area_mm2", rest.restAreaMm2());
            summary.put("rest_pieces", rest.pieces().size());
            summary.put("rest_pieces_length_mm", rest.piecesLengthMm());
        }
        planned.slowed().ifPresent(w -> {
            summary.put("slowed_cuts", w.moves());
            summary.put("slowed_length_mm", w.lengthMm());
            summary.put("lowest_feed_factor", w.lowestFactor());
        });
        summary.put("out", outFile.toString());
        List<Path> files = new ArrayList<>(List.of(outFile));
        if (slowed.isPresent()) {
            AtomicFiles.writeString(
                    slowed.get(),
                    slowedCsv(
                            SlowedMove.of(path.sections().get(0), s.feedMmPerMin(), s.finishFeedMmPerMin()),
                            s.feedMmPerMin()));
            summary.put("slowed_csv", slowed.get().toString());
            files.add(slowed.get());
        }
        return new TaskOutcome(0, problems, summary, files);
    }

    /**
     * The slowed moves as a planner reviews them, one row a move in program order: its layer, line
     * or arc (and which way), where it starts and ends, its length, its feed and the fraction of
     * the programmed feed that is.
     */
    public static String slowedCsv(List<SlowedMove> moves, double feedMmPerMin) {
        StringBuilder b = new StringBuilder(
                "layer_z_mm,move,x_start_mm,y_start_mm,x_end_mm,y_end_mm,length_mm,feed_mm_per_min,feed_factor\n");
        for (SlowedMove m : moves) {
            String kind = m.curve() instanceof org.fresa.geom.Arc2 arc ? (arc.ccw() ? "arc_ccw" : "arc_cw") : "line";
            org.fresa.geom.Vec2 a = m.curve().start();
            org.fresa.geom.Vec2 e = m.curve().end();
            b.append(String.format(
                    Locale.ROOT,
                    "%.3f,%s,%.3f,%.3f,%.3f,%.3f,%.3f,%s,%.3f\n",
                    m.zMm(),
                    kind,
                    a.x(),
                    a.y(),
                    e.x(),
                    e.y(),
                    m.curve().length(),
                    org.fresa.model.ExactDecimal.of(m.feedMmPerMin()),
                    m.factor(feedMmPerMin)));
        }
        return b.toString();
    }

    /** The thesis's recognition of a single contour, or none where it cannot read the contour. */
    private static Optional<Recognition.Result> recognition(PocketSettings s) throws IOException {
        try {
            return Optional.of(Recognition.of(readContour(s).withUnitNormals().withBridgedJunctions()));
        } catch (CamInputException e) {
            return Optional.empty();
        }
    }

    /** The warning when the first tool leaves nothing the rest tool can reach: no T2 is written. */
    public static final String REST_TOOL_IDLE =
            "warning: the rest tool has nothing to cut: the first tool reaches everything it could; no second tool"
                    + " is written";

    /**
     * Checks the program (the program check of the settings' post and pocket) and writes it to
     * {@code outFile}; a refused program is not written and its outcome is returned.
     */
    private static Optional<TaskOutcome> checkAndWrite(PocketSettings s, Path outFile, String nc) throws IOException {
        try {
            ProgramChecks.require(
                    outFile.getFileName().toString(),
                    nc,
                    ProgramChecks.dialect(s.post().word()),
                    ProgramChecks.pocket(s));
        } catch (ProgramChecks.RefusedProgram e) {
            return Optional.of(new TaskOutcome(
                    1,
                    List.of(e.getMessage()),
                    Map.of("out", outFile.toString(), "refused", e.failure().message()),
                    List.of()));
        }
        AtomicFiles.writeString(outFile, nc);
        return Optional.empty();
    }
}
