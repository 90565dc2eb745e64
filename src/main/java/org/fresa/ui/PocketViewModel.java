package org.fresa.ui;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.fresa.chart.PlotScene;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.job.Job;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.job.PocketService;
import org.fresa.model.CamInputException;
import org.fresa.model.ExactDecimal;
import org.fresa.model.Toolpath;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.LoopState;
import org.fresa.pocket.MillingDirection;
import org.fresa.pocket.PocketElement;
import org.fresa.pocket.PocketPlan;
import org.fresa.pocket.PocketStrategy;
import org.fresa.pocket.PocketToolpath;
import org.fresa.pocket.RecognitionNode;
import org.fresa.pocket.RegionPocket;
import org.fresa.pocket.ToolTooLargeException;
import org.fresa.post.PocketPost;
import org.fresa.setting.SettingRange;
import org.fresa.setting.SettingRanges.Pocket;

/**
 * The Pocket tab's state without Swing: the settings being edited and the last computed result
 * (the contour with element numbers, the recognition tree as text, the toolpath plot, the NC text).
 */
public final class PocketViewModel {

    /**
     * A computed pocket.
     *
     * @param scene contour (element numbers as labels), recognition subcontours and toolpath
     * @param report the thesis's sizes and the recognition tree, like its Appendix C
     * @param nc the NC program for the chosen post
     * @param refusal the program check's first failure: the program is not written (Job > Run
     *     ends with exit 1), the tab shows the block highlighted
     */
    public record Result(PlotScene scene, String report, String nc, Optional<org.fresa.check.Failure> refusal) {

        /** A result whose program is checked against the settings' limits. */
        static Result checked(PlotScene scene, String report, String nc, PocketSettings settings) {
            return new Result(
                    scene,
                    report,
                    nc,
                    org.fresa.check.ProgramCheck.of(
                                    nc,
                                    org.fresa.job.ProgramChecks.dialect(
                                            settings.post().word()),
                                    org.fresa.job.ProgramChecks.pocket(settings))
                            .failure());
        }
    }

    /** Every post the pocket module writes: the thesis's 7M dialect, then the G-code posts. */
    public static final List<PocketPost> POSTS = Pocket.POST.values();
    /** The milling directions, the default first. */
    public static final List<MillingDirection> DIRECTIONS = Pocket.DIRECTION.values();
    /** The technology fields, in the order shown, with their units. */
    public static final List<String> LABELS = List.of(
            "Tool diameter (mm)",
            "Cut fraction",
            "Finish fraction",
            "Z top (mm)",
            "Z bottom (mm)",
            "Max depth per pass (mm)",
            "Spindle (rpm)",
            "Feed (mm/min)",
            "Finish feed (mm/min)");
    /** The field names of the technology fields (for tests and accessibility). */
    public static final List<String> NAMES = List.of(
            "pocket-tool",
            "pocket-cut",
            "pocket-finish",
            "pocket-z-top",
            "pocket-z-bottom",
            "pocket-max-depth",
            "pocket-spindle",
            "pocket-feed",
            "pocket-finish-feed");

    private static final List<SettingRange> RANGES = List.of(
            Pocket.TOOL_DIAMETER,
            Pocket.CUT,
            Pocket.FINISH,
            Pocket.Z_TOP,
            Pocket.Z_BOTTOM,
            Pocket.MAX_DEPTH,
            Pocket.SPINDLE,
            Pocket.FEED,
            Pocket.FINISH_FEED);
    /** The key of the contour field in {@link #problems()}. */
    public static final String CONTOUR = "pocket-contour";
    /** The names of the entry fields: the kind, the angle (a key of {@link #problems()}) and centre-cutting. */
    public static final String ENTRY = "pocket-entry";

    public static final String ENTRY_ANGLE = "pocket-entry-angle";
    public static final String CENTRE_CUTTING = "pocket-centre-cutting";
    /** The entry field's label. */
    public static final String ENTRY_ANGLE_LABEL = "Entry angle (deg)";
    /** The names of the strategy fields: the pattern, the zigzag angle and the stock (keys of {@link #problems()}), the order. */
    public static final String STRATEGY = "pocket-strategy";

    public static final String ANGLE = "pocket-angle";
    public static final String STOCK_TO_LEAVE = "pocket-stock-to-leave";
    public static final String ORDER = "pocket-order";
    /** The strategy fields' labels. */
    public static final String ANGLE_LABEL = "Zigzag angle (deg)";

    public static final String STOCK_TO_LEAVE_LABEL = "Stock to leave (mm)";
    /** The rest tool's field (a key of {@link #problems()}): empty for none. */
    public static final String REST_TOOL = "pocket-rest-tool";
    /** The rest tool's label. */
    public static final String REST_TOOL_LABEL = "Rest tool (mm)";
    /** The strategies the tab offers, as the job and the command line name them. */
    public static final List<String> STRATEGIES = org.fresa.model.EnumWords.all(
            org.fresa.pocket.PocketStrategy.Kind.class, org.fresa.pocket.PocketStrategy.Kind::word);

    public static final List<String> ORDERS = org.fresa.model.EnumWords.all(
            org.fresa.pocket.PocketStrategy.Order.class, org.fresa.pocket.PocketStrategy.Order::word);
    /** The kinds of entry the tab offers, as the job and the command line name them. */
    public static final List<String> ENTRIES = org.fresa.pocket.EntryRule.Kind.words();
    /** A new job's technology: the pocket module's defaults ({@link PocketSettings#DEFAULTS}); no contour. */
    private PocketSettings settings = PocketSettings.DEFAULTS;
    // the fields as typed
    private String contourText = "";
    private final String[] values = new String[LABELS.size()];
    private PocketPost post = PocketSettings.DEFAULTS.post();
    private MillingDirection direction = PocketSettings.DEFAULTS.direction();
    private String entry = PocketSettings.DEFAULTS.entry().word();
    private String entryAngle = ExactDecimal.of(PocketSettings.DEFAULTS.entryAngleDeg());
    private boolean centreCutting = PocketSettings.DEFAULTS.centreCutting();
    private String strategy = PocketSettings.DEFAULTS.strategy().kind().word();
    private String angle = ExactDecimal.of(PocketSettings.DEFAULTS.strategy().angleDeg());
    private String stockToLeave =
            ExactDecimal.of(PocketSettings.DEFAULTS.strategy().stockToLeaveMm());
    private String order = PocketSettings.DEFAULTS.strategy().order().word();
    // empty: no rest tool
    private String restTool = "";
    // the contour typed in the editor, held in the job; empty: the contour file is read
    private Optional<org.fresa.pocket.DadContour> elements = Optional.empty();

    public PocketViewModel() {
        showTechnology(PocketSettings.DEFAULTS);
    }

    private void showTechnology(PocketSettings p) {
        double[] v = {
            p.toolDiameterMm(),
            p.cutFraction(),
            p.finishFraction(),
            p.zTopMm(),
            p.zBottomMm(),
            p.maxDepthPerPassMm(),
            p.spindleRpm(),
            p.feedMmPerMin(),
            p.finishFeedMmPerMin()
        };
        for (int i = 0; i < v.length; i++) {
            values[i] = ExactDecimal.of(v[i]);
        }
    }

    /** Shows the job's pocket settings, or a new job's (no contour) when it has none. */
    public void load(Job job) {
        result = Optional.empty();
        error = Optional.empty();
        if (job.pocket().isEmpty()) {
            return;
        }
        PocketSettings p = job.pocket().get();
        settings = p;
        contourText = p.contour().toString();
        elements = p.elements();
        showTechnology(p);
        post = p.post();
        direction = p.direction();
        entry = p.entry().word();
        entryAngle = ExactDecimal.of(p.entryAngleDeg());
        centreCutting = p.centreCutting();
        strategy = p.strategy().kind().word();
        angle = ExactDecimal.of(p.strategy().angleDeg());
        stockToLeave = ExactDecimal.of(p.strategy().stockToLeaveMm());
        order = p.strategy().order().word();
        restTool = p.strategy().restTool() ? ExactDecimal.of(p.strategy().restToolDiameterMm()) : "";
    }

    public String contourText() {
        return contourText;
    }

    public void setContourText(String t) {
        contourText = t.trim();
    }

    /** The contour typed in the editor, which the job holds; empty when the contour file is read. */
    public Optional<org.fresa.pocket.DadContour> elements() {
        return elements;
    }

    /** Holds the typed contour in the job (present) or reads the contour file again (empty). */
    public void setElements(Optional<org.fresa.pocket.DadContour> typed) {
        elements = java.util.Objects.requireNonNull(typed, "elements");
    }

    /**
     * The contour the editor opens on: the typed one the job holds, else the {@code .dad} file's
     * records; none for another kind of file (the editor writes the thesis's records only) or a
     * file that cannot be read.
     */
    public org.fresa.pocket.DadContour editorContour() {
        if (elements.isPresent()) {
            return elements.get();
        }
        if (contourText.toLowerCase(Locale.ROOT).endsWith(".dad")) {
            try {
                Path file = Path.of(contourText);
                return org.fresa.pocket.DadReader.contour(
                        java.nio.file.Files.readString(file, java.nio.charset.StandardCharsets.ISO_8859_1),
                        file.toString());
            } catch (IOException | CamInputException | java.nio.file.InvalidPathException e) {
                // the planner's message for the file comes with Compute
            }
        }
        return new org.fresa.pocket.DadContour(List.of());
    }

    /**
     * The name of the typed contour: the contour file named (it came from or is saved as it), else
     * the one a job gives a typed contour with no file ({@code contour.dad}).
     */
    Path typedContourName() {
        return Path.of(contourText.isEmpty() ? "contour.dad" : contourText).toAbsolutePath();
    }

    public String value(int i) {
        return values[i];
    }

    public void setValue(int i, String t) {
        values[i] = t.trim();
    }

    public PocketPost post() {
        return post;
    }

    public void setPost(PocketPost p) {
        post = java.util.Objects.requireNonNull(p, "post");
    }

    public MillingDirection direction() {
        return direction;
    }

    public void setDirection(MillingDirection d) {
        direction = java.util.Objects.requireNonNull(d, "direction");
    }

    public String entry() {
        return entry;
    }

    public void setEntry(String e) {
        if (!ENTRIES.contains(e)) {
            throw new IllegalArgumentException("unknown entry " + e);
        }
        entry = e;
    }

    public String entryAngle() {
        return entryAngle;
    }

    public void setEntryAngle(String t) {
        entryAngle = t.trim();
    }

    public boolean centreCutting() {
        return centreCutting;
    }

    public void setCentreCutting(boolean c) {
        centreCutting = c;
    }

    public String strategy() {
        return strategy;
    }

    public void setStrategy(String w) {
        if (!STRATEGIES.contains(w)) {
            throw new IllegalArgumentException("unknown strategy " + w);
        }
        strategy = w;
    }

    public String angle() {
        return angle;
    }

    public void setAngle(String t) {
        angle = t.trim();
    }

    public String stockToLeave() {
        return stockToLeave;
    }

    public void setStockToLeave(String t) {
        stockToLeave = t.trim();
    }

    public String order() {
        return order;
    }

    public void setOrder(String w) {
        if (!ORDERS.contains(w)) {
            throw new IllegalArgumentException("unknown order " + w);
        }
        order = w;
    }

    /** The rest tool's diameter as typed (mm), empty for none. */
    public String restTool() {
        return restTool;
    }

    public void setRestTool(String t) {
        restTool = t.trim();
    }

    /** The rest tool's diameter (mm), 0 when the field is empty. */
    private double restToolMm() {
        return restTool.isEmpty() ? 0 : Double.parseDouble(restTool);
    }

    /** A typed number's problem against its range, as the other fields word it. */
    private static Optional<String> numberProblem(String label, String text, org.fresa.setting.SettingRange range) {
        try {
            double v = Double.parseDouble(text);
            return range.contains(v) ? Optional.empty() : Optional.of(label + ": " + range.problem(v) + ".");
        } catch (NumberFormatException e) {
            return Optional.of(label + ": '" + text + "' is not a number"
                    + (text.contains(",") ? " (decimals take a point: " + text.replace(',', '.') + ")." : "."));
        }
    }

    /**
     * What is wrong with the typed fields, in the planner's words, by field name ({@link #CONTOUR}
     * or one of {@link #NAMES}); empty when Compute may run.
     */
    public Map<String, String> problems() {
        Map<String, String> out = new LinkedHashMap<>();
        if (contourText.isEmpty() && elements.isEmpty()) {
            out.put(CONTOUR, "Choose the contour to pocket (.dad or .contour file) or type its elements.");
        }
        for (int i = 0; i < values.length; i++) {
            String label = LABELS.get(i);
            try {
                double v = Double.parseDouble(values[i]);
                if (!RANGES.get(i).contains(v)) {
                    out.put(NAMES.get(i), label + ": " + RANGES.get(i).problem(v) + ".");
                }
            } catch (NumberFormatException e) {
                out.put(
                        NAMES.get(i),
                        label + ": '" + values[i] + "' is not a number"
                                + (values[i].contains(",")
                                        ? " (decimals take a point: " + values[i].replace(',', '.') + ")."
                                        : "."));
            }
        }
        try {
            double a = Double.parseDouble(entryAngle);
            if (!Pocket.ENTRY_ANGLE.contains(a)) {
                out.put(ENTRY_ANGLE, ENTRY_ANGLE_LABEL + ": " + Pocket.ENTRY_ANGLE.problem(a) + ".");
            }
        } catch (NumberFormatException e) {
            out.put(
                    ENTRY_ANGLE,
                    ENTRY_ANGLE_LABEL + ": '" + entryAngle + "' is not a number"
                            + (entryAngle.contains(",")
                                    ? " (decimals take a point: " + entryAngle.replace(',', '.') + ")."
                                    : "."));
        }
        numberProblem(ANGLE_LABEL, angle, Pocket.ANGLE).ifPresent(m -> out.put(ANGLE, m));
        numberProblem(STOCK_TO_LEAVE_LABEL, stockToLeave, Pocket.STOCK_TO_LEAVE)
                .ifPresent(m -> out.put(STOCK_TO_LEAVE, m));
        if (!restTool.isEmpty()) {
            // bounded by the first tool's diameter as typed, as --rest-tool is by --tool-diameter
            double first;
            try {
                first = Double.parseDouble(values[0]);
            } catch (NumberFormatException e) {
                first = Pocket.TOOL_DIAMETER.max();
            }
            if (!Pocket.TOOL_DIAMETER.contains(first)) {
                first = Pocket.TOOL_DIAMETER.max();
            }
            numberProblem(REST_TOOL_LABEL, restTool, PocketService.restToolRange(first))
                    .ifPresent(m -> out.put(REST_TOOL, m));
        }
        return out;
    }

    /** The settings of the typed fields; empty while {@link #problems()} is not. */
    public Optional<PocketSettings> typedSettings() {
        if (!problems().isEmpty()) {
            return Optional.empty();
        }
        double[] v = new double[values.length];
        for (int i = 0; i < v.length; i++) {
            v[i] = Double.parseDouble(values[i]);
        }
        PocketSettings s = new PocketSettings(
                        typedContourName(),
                        v[0],
                        v[1],
                        v[2],
                        v[3],
                        v[4],
                        v[5],
                        v[6],
                        v[7],
                        v[8],
                        post,
                        direction,
                        EntryRule.Kind.AUTO,
                        EntryRule.DEFAULT_ANGLE_DEG,
                        false,
                        Optional.empty(),
                        PocketStrategy.DEFAULT)
                .withEntry(
                        org.fresa.setting.SettingRanges.Pocket.ENTRY.require(entry),
                        Double.parseDouble(entryAngle),
                        centreCutting)
                .withStrategy(new org.fresa.pocket.PocketStrategy(
                        Pocket.STRATEGY.require(strategy),
                        Double.parseDouble(angle),
                        Double.parseDouble(stockToLeave),
                        Pocket.ORDER.require(order),
                        restToolMm()));
        return Optional.of(elements.isPresent() ? s.withElements(s.contour(), elements.get()) : s);
    }

    private Optional<Result> result = Optional.empty();
    private Optional<String> error = Optional.empty();

    public PocketSettings settings() {
        return settings;
    }

    public void setSettings(PocketSettings s) {
        settings = s;
    }

    public Optional<Result> result() {
        return result;
    }

    public Optional<String> error() {
        return error;
    }

    /** The outcome of one computation: a result or the reason there is none. */
    public record Outcome(Optional<Result> result, Optional<String> error) {}

    /** Computes with the current settings (the tab does it in the background with {@link #outcome}). */
    public void compute() {
        show(outcome(settings));
    }

    /** Takes an outcome computed for the current settings. */
    public void show(Outcome o) {
        result = o.result();
        error = o.error();
    }

    /**
     * Why the computed program cannot be saved, or empty when it may: there is none yet, or it
     * fails the program check (it is never written, as Job > Run would not write it).
     */
    /**
     * The status line after a computation: "done", or the warnings the program is written with
     * (they head the report, which is not in front), so that they are seen before Save.
     */
    public static String doneLine(Result r) {
        List<String> warnings =
                r.report().lines().filter(l -> l.startsWith("warning: ")).toList();
        if (warnings.isEmpty()) {
            return "done";
        }
        return warnings.size() == 1
                ? "done, with a " + warnings.get(0)
                : "done, with " + warnings.size() + " warnings (Recognition tree): " + warnings.get(0);
    }

    public Optional<String> saveProblem() {
        if (result.isEmpty()) {
            return Optional.of("There is no program to save: press Compute first.");
        }
        return result.get()
                .refusal()
                .map(f -> "The program is not saved: it fails the program check at " + f.message());
    }

    /**
     * Plans the pocket of these settings: touches no view-model state, so any thread may call it.
     * A plunge asked for a cutter not said to cut at its centre is planned as asked, so that the
     * planner sees the block the program check refuses (Job > Run refuses such settings outright).
     */
    public static Outcome outcome(PocketSettings checked) {
        return outcome(checked, org.fresa.job.ProgressMonitor.NONE);
    }

    /** {@link #outcome(PocketSettings)}, telling how far adaptive clearing is and stopping at Cancel. */
    public static Outcome outcome(PocketSettings checked, org.fresa.job.ProgressMonitor progress) {
        Outcome o = planned(checked, progress);
        Optional<String> raised = PocketService.cutRaised(checked);
        if (o.result().isEmpty() || raised.isEmpty()) {
            return o;
        }
        Result r = o.result().get();
        return new Outcome(
                Optional.of(new Result(r.scene(), raised.get() + "\n" + r.report(), r.nc(), r.refusal())), o.error());
    }

    private static Outcome planned(PocketSettings checked, org.fresa.job.ProgressMonitor progress) {
        PocketSettings settings = checked.entry() == org.fresa.pocket.EntryRule.Kind.PLUNGE && !checked.centreCutting()
                ? checked.withEntry(org.fresa.pocket.EntryRule.Kind.PLUNGE, checked.entryAngleDeg(), true)
                : checked;
        try {
            String name = settings.contour().getFileName().toString();
            if (!settings.strategy().offset() || !settings.strategy().asThesis()) {
                // the program fresa pocket and Job > Run write for these settings
                org.fresa.pocket.StrategyPocket.Planned planned = PocketService.strategyPlan(settings, progress);
                Toolpath path = planned.toolpath();
                List<Contour> contours = PocketService.strategyContours(settings);
                List<Curve2> walls = new ArrayList<>();
                for (Contour c : contours) {
                    walls.addAll(c.curves());
                }
                PlotScene scene = PlotScene.empty("pocket")
                        .with(new PlotScene.Layer("contour and islands", PlotScene.Style.OUTLINE, walls))
                        .withToolpathByTool(path);
                if (planned.slowed()
                        .filter(org.fresa.pocket.EngagementFeed.Slowed::any)
                        .isPresent()) {
                    // where adaptive clearing drops its feed: the planner looks there first
                    scene = scene.with(new PlotScene.Layer(
                            "slowed feed",
                            PlotScene.Style.WARNING,
                            slowed(path.sections().get(0), settings.feedMmPerMin(), settings.finishFeedMmPerMin())));
                }
                org.fresa.pocket.PocketStrategy st = settings.strategy();
                String report = String.format(
                        Locale.ROOT,
                        "%s, %d island(s), stock to leave %s mm%s%n",
                        st.zigzag()
                                ? "zigzag at " + ExactDecimal.of(st.angleDeg()) + " deg"
                                : st.adaptive() ? "adaptive" : "offset " + st.order(),
                        contours.size() - 1,
                        ExactDecimal.of(st.stockToLeaveMm()),
                        String.format(Locale.ROOT, ", path %.1f mm", PocketToolpath.lengthMm(path)));
                if (planned.rest().isPresent() && planned.rest().get().cuts()) {
                    org.fresa.pocket.RestMachining.Plan rest = planned.rest().get();
                    report += String.format(
                            Locale.ROOT,
                            "rest tool T2 D%s at %.0f rpm: %.2f mm2 of rest in %d piece(s), %.1f mm a layer%n",
                            ExactDecimal.of(st.restToolDiameterMm()),
                            rest.technology().spindleRpm(),
                            rest.restAreaMm2(),
                            rest.pieces().size(),
                            rest.piecesLengthMm());
                }
                // the warnings fresa pocket and Job > Run give for this plan, above its sizes
                StringBuilder told = new StringBuilder();
                for (String w : PocketService.strategyWarnings(planned)) {
                    told.append(w).append('\n');
                }
                report = told + report;
                return new Outcome(
                        Optional.of(Result.checked(
                                scene, report, PocketService.toolpathProgram(path, settings.post(), name), checked)),
                        Optional.empty());
            }
            if (PocketService.mayHaveIslands(settings)) {
                List<Contour> contours = PocketService.readContours(settings.contour());
                if (contours.size() > 1) {
                    RegionPocket.Plan rp = PocketService.regionPlan(settings, contours);
                    return new Outcome(
                            Optional.of(Result.checked(
                                    regionScene(contours, rp),
                                    regionReport(contours, rp),
                                    PocketService.regionProgram(rp, settings.post(), name),
                                    checked)),
                            Optional.empty());
                }
            }
            PocketPlan plan = PocketService.plan(settings);
            String nc = PocketService.program(
                    plan,
                    settings.post(),
                    settings.contour().getFileName().toString(),
                    settings.climb(),
                    settings.entryRule());
            // the warnings fresa pocket and Job > Run give for this plan, above its sizes
            StringBuilder told = new StringBuilder();
            for (String w : PocketService.planWarnings(settings, plan)) {
                told.append(w).append('\n');
            }
            return new Outcome(
                    Optional.of(Result.checked(scene(plan, settings), told + report(plan), nc, checked)),
                    Optional.empty());
        } catch (CamInputException e) {
            return new Outcome(Optional.empty(), Optional.of(plannerWords(e)));
        } catch (java.nio.file.NoSuchFileException e) {
            return new Outcome(Optional.empty(), Optional.of("There is no file " + settings.contour() + "."));
        } catch (IOException e) {
            return new Outcome(Optional.empty(), Optional.of("Cannot read " + settings.contour() + "."));
        } catch (ToolTooLargeException | IllegalArgumentException e) {
            return new Outcome(Optional.empty(), Optional.of(sentence(e.getMessage())));
        }
    }

    /** The level feed moves of a section at neither of its programmed feeds, as lines and arcs in the plane. */
    static List<Curve2> slowed(org.fresa.model.ToolpathSection s, double feedMmPerMin, double finishFeedMmPerMin) {
        return org.fresa.pocket.SlowedMove.of(s, feedMmPerMin, finishFeedMmPerMin).stream()
                .map(org.fresa.pocket.SlowedMove::curve)
                .toList();
    }

    /** The plot's title when there is no contour to draw. */
    static final String NO_CONTOUR = "Choose a contour or type its elements";

    /**
     * The contour file drawn as read, before any Compute: the contours Compute will pocket (the
     * outer one and its islands), or, when the file cannot be read, the reader's message as the
     * plot's title, so that a wrong file is seen as it is chosen.
     */
    public PlotScene fileScene() {
        Path file;
        try {
            file = Path.of(contourText.trim());
        } catch (java.nio.file.InvalidPathException e) {
            return PlotScene.empty(NO_CONTOUR);
        }
        if (contourText.isBlank() || !java.nio.file.Files.isRegularFile(file)) {
            return PlotScene.empty(NO_CONTOUR);
        }
        try {
            if (file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".dad")) {
                // read for its message only: a readable .dad file is shown by the editor's records
                PocketService.readContour(file);
                return PlotScene.empty("Press Compute");
            }
            List<Curve2> walls = new ArrayList<>();
            List<Contour> contours = PocketService.readContours(file);
            for (Contour c : contours) {
                walls.addAll(c.curves());
            }
            String islands = contours.size() == 2
                    ? ", 1 island"
                    : contours.size() > 2 ? ", " + (contours.size() - 1) + " islands" : "";
            return PlotScene.empty(file.getFileName() + " as read" + islands + ": press Compute")
                    .with(new PlotScene.Layer("contour", PlotScene.Style.OUTLINE, walls));
        } catch (CamInputException e) {
            return PlotScene.empty(plannerWords(e));
        } catch (IOException e) {
            return PlotScene.empty("Cannot read " + file.getFileName() + ".");
        }
    }

    /** A refusal as the planner reads it: the problem, with the file it is in, never an option name. */
    static String plannerWords(CamInputException e) {
        String source = e.source();
        String problem = sentence(e.problem());
        if (source.startsWith("--") || source.equals("technology") || source.isEmpty()) {
            return problem;
        }
        String file = source.substring(source.lastIndexOf('/') + 1);
        return file + (e.line().isPresent() ? ", line " + e.line().getAsInt() : "") + ": " + problem;
    }

    private static String sentence(String s) {
        String t = String.valueOf(s).trim();
        if (t.isEmpty()) {
            return "The pocket cannot be planned.";
        }
        t = Character.toUpperCase(t.charAt(0)) + t.substring(1);
        return t.endsWith(".") ? t : t + ".";
    }

    /** A pocket with islands: the contours, every offset level and the toolpath. */
    private static PlotScene regionScene(List<Contour> contours, RegionPocket.Plan plan) {
        List<Curve2> walls = new ArrayList<>();
        for (Contour c : contours) {
            walls.addAll(c.curves());
        }
        List<Curve2> offsets = new ArrayList<>();
        for (RegionPocket.Level l : plan.levels()) {
            for (Contour c : l.loops()) {
                offsets.addAll(c.curves());
            }
        }
        return PlotScene.empty("pocket")
                .with(new PlotScene.Layer("contour and islands", PlotScene.Style.OUTLINE, walls))
                .with(new PlotScene.Layer("offsets", PlotScene.Style.AUX, offsets))
                .withToolpath(plan.toolpath());
    }

    private static String regionReport(List<Contour> contours, RegionPocket.Plan plan) {
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(
                Locale.ROOT,
                "%d island(s): Fresa's region engine (the thesis's tree has none)%n",
                contours.size() - 1));
        for (RegionPocket.Level l : plan.levels()) {
            long faces = l.loops().stream().filter(Contour::isCcw).count();
            sb.append(String.format(
                    Locale.ROOT,
                    "offset %8.3f  %d sub-area(s), %d loop(s)%n",
                    l.offsetMm(),
                    faces,
                    l.loops().size()));
        }
        return sb.toString();
    }

    static List<Curve2> curves(LoopState s, double t) {
        List<Curve2> out = new ArrayList<>();
        Optional<List<Vec2>> vs = s.vertices(t);
        if (vs.isEmpty()) {
            return out;
        }
        List<Vec2> v = vs.get();
        for (int i = 0; i < s.size(); i++) {
            PocketElement e = s.get(i);
            Vec2 a = v.get(i);
            Vec2 b = v.get((i + 1) % s.size());
            if (a.distance(b) < 1e-9) {
                continue;
            }
            if (e.arc() && Math.abs(a.distance(e.center()) - b.distance(e.center())) < 1e-6) {
                out.add(new Arc2(e.center(), a, b, e.k() == 1));
            } else {
                out.add(new Segment2(a, b));
            }
        }
        return out;
    }

    private static PlotScene scene(PocketPlan plan, PocketSettings settings) throws ToolTooLargeException {
        LoopState ref = plan.recognition().reference();
        PlotScene scene =
                PlotScene.empty("pocket").with(new PlotScene.Layer("contour", PlotScene.Style.OUTLINE, curves(ref, 0)));
        List<Curve2> sub = new ArrayList<>();
        collectSubcontours(plan.recognition().root(), sub);
        scene = scene.with(new PlotScene.Layer("subcontours", PlotScene.Style.AUX, sub));
        scene = scene.withToolpath(PocketToolpath.of(plan, settings.climb(), settings.entryRule()));
        Optional<List<Vec2>> v = ref.vertices(0);
        if (v.isPresent()) {
            for (int i = 0; i < ref.size(); i++) {
                PocketElement e = ref.get(i);
                if (!e.zeroRadius()) {
                    Vec2 a = v.get().get(i), b = v.get().get((i + 1) % ref.size());
                    scene = scene.withLabel(a.interpolate(b, 0.5), Integer.toString(e.number()));
                }
            }
        }
        return scene;
    }

    private static void collectSubcontours(RecognitionNode n, List<Curve2> out) {
        for (LoopState s : n.states()) {
            if (s.tFrom() > 0) {
                out.addAll(curves(s, s.tFrom() + 1e-6));
            }
        }
        for (RecognitionNode c : n.children()) {
            collectSubcontours(c, out);
        }
    }

    /** The reported sizes and the tree, one subcontour per line. */
    static String report(PocketPlan plan) {
        StringBuilder sb = new StringBuilder();
        var r = plan.recognition();
        sb.append(String.format(Locale.ROOT, "FURO MAXIMO (largest hole)        %.3f mm%n", r.maxHoleDiameterMm()));
        sb.append(String.format(Locale.ROOT, "DIAMETRO MAXIMO (largest tool)    %.3f mm%n", r.maxToolDiameterMm()));
        sb.append(String.format(Locale.ROOT, "DIAMETRO p/ SUPERF (wall tool)    %.3f mm%n%n", r.wallToolDiameterMm()));
        tree(r.root(), "", sb);
        sb.append(System.lineSeparator()).append("passes (generation order):");
        plan.generated().forEach(p -> sb.append(String.format(Locale.ROOT, " %.4f", p.offsetMm())));
        return sb.toString();
    }

    private static void tree(RecognitionNode n, String indent, StringBuilder sb) {
        for (LoopState s : n.states()) {
            sb.append(indent)
                    .append("SC")
                    .append(n.id())
                    .append(' ')
                    .append(s.elements().stream().map(PocketElement::toString).toList())
                    .append(String.format(Locale.ROOT, "  t = %.6f%n", s.tFrom()));
        }
        if (n.isLeaf()) {
            sb.append(indent).append(String.format(Locale.ROOT, "F  t = %.6f%n", n.leafT()));
        } else {
            sb.append(indent).append(String.format(Locale.ROOT, "divides at t = %.6f%n", n.splitT()));
            for (RecognitionNode c : n.children()) {
                tree(c, indent + "    ", sb);
            }
        }
    }

    /** The same settings with another contour file. */
    static PocketSettings withContour(PocketSettings s, Path contour) {
        return new PocketSettings(
                contour,
                s.toolDiameterMm(),
                s.cutFraction(),
                s.finishFraction(),
                s.zTopMm(),
                s.zBottomMm(),
                s.maxDepthPerPassMm(),
                s.spindleRpm(),
                s.feedMmPerMin(),
                s.finishFeedMmPerMin(),
                s.post(),
                s.direction(),
                s.entry(),
                s.entryAngleDeg(),
                s.centreCutting(),
                s.elements(),
                s.strategy());
    }
}
