package org.fresa.ui;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.chart.GradingChart;
import org.fresa.chart.PlotScene;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Vec2;
import org.fresa.grading.GradedSize;
import org.fresa.grading.GradingResult;
import org.fresa.grading.ShrinkageMode;
import org.fresa.grading.SizeSystem;
import org.fresa.io.OutputFolder;
import org.fresa.job.GradingService;
import org.fresa.job.Job;
import org.fresa.job.JobSettings;
import org.fresa.job.JobSettings.GradingSettings;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.TaskOutcome;
import org.fresa.model.CamInputException;
import org.fresa.model.ExactDecimal;
import org.fresa.setting.SettingRanges;

/**
 * The Grading tab's state without Swing: the base outline, the grading options as the planner
 * typed them, the origin (typed, picked on the plot, or the heel centre), and the last graded
 * result with its table and plot. Text fields are kept as text and parsed by {@link #settings()},
 * which reports the first bad field as a {@link CamInputException} naming it.
 */
public final class GradingViewModel {

    /** The size systems offered. */
    public static final List<SizeSystem> SYSTEMS = SettingRanges.Grading.SYSTEM.values();
    /** The shrinkage modes offered. */
    public static final List<ShrinkageMode> SHRINKAGE_MODES =
            List.of(ShrinkageMode.MULTIPLICATIVE, ShrinkageMode.ADDITIVE);
    /** The grading table's column titles. */
    public static final List<String> COLUMNS = List.of(
            "Size",
            "Length (mm)",
            "Width (mm)",
            "ALFA",
            "BETA",
            "Length factor",
            "Width factor",
            "Max deviation (mm)",
            "Last girth (mm)");
    /** The width fittings offered for the last girth column (table 3.1), "" for none. */
    public static final List<String> FITTINGS;

    static {
        List<String> f = new ArrayList<>(List.of(""));
        f.addAll(org.fresa.grading.LastGirths.FITTINGS);
        FITTINGS = List.copyOf(f);
    }

    private Optional<Path> outlineFile = Optional.empty();
    private List<Contour> outline = List.of();
    private SizeSystem system = GradingSettings.DEFAULTS.system();
    private String baseSize = ExactDecimal.of(GradingSettings.DEFAULTS.baseSize());
    private String sizes = GradingSettings.DEFAULTS.sizes();
    private boolean halfSizes = GradingSettings.DEFAULTS.halfSizes();
    private String lengthStep = "";
    private String widthStep = "";
    private String origin = "";
    private String shrinkage = ExactDecimal.of(GradingSettings.DEFAULTS.shrinkage());
    private ShrinkageMode shrinkageMode = GradingSettings.DEFAULTS.shrinkageMode();
    private String fitting = "";
    private String heelElements = "";
    private String heelGroup = Integer.toString(JobSettings.HeelCoordination.DEFAULT_GROUP_SIZE);
    /** A job's boundary-line coordination, kept while no heel elements are designated. */
    private OptionalDouble heelBoundaryMm = OptionalDouble.empty();

    private Optional<GradingResult> result = Optional.empty();

    /** Reads the base outline (a .contour file) and forgets the last result. */
    public void openOutline(Path file) throws CamInputException, IOException {
        List<Contour> read = GradingService.readOutline(file);
        outline = read;
        outlineFile = Optional.of(file.toAbsolutePath());
        result = Optional.empty();
    }

    public Optional<Path> outlineFile() {
        return outlineFile;
    }

    public List<Contour> outline() {
        return outline;
    }

    /** Takes the grading settings of a job (when it has some) into the fields. */
    public void load(Job job) {
        job.grading().ifPresent(g -> {
            system = g.system();
            baseSize = ExactDecimal.of(g.baseSize());
            sizes = g.sizes();
            halfSizes = g.halfSizes();
            lengthStep = g.lengthStepMm().isPresent()
                    ? ExactDecimal.of(g.lengthStepMm().getAsDouble())
                    : "";
            widthStep = g.widthStepMm().isPresent()
                    ? ExactDecimal.of(g.widthStepMm().getAsDouble())
                    : "";
            origin = g.originMm()
                    .map(o -> ExactDecimal.of(o.x()) + "," + ExactDecimal.of(o.y()))
                    .orElse("");
            shrinkage = ExactDecimal.of(g.shrinkage());
            shrinkageMode = g.shrinkageMode();
            heelElements = g.coordination()
                    .map(JobSettings.HeelCoordination::heelElements)
                    .orElse("");
            heelGroup =
                    g.coordination().map(h -> Integer.toString(h.groupSize())).orElse("3");
            heelBoundaryMm = g.coordination()
                    .map(JobSettings.HeelCoordination::boundaryMm)
                    .orElse(OptionalDouble.empty());
            if (outlineFile.isEmpty() || !outlineFile.get().equals(g.outline())) {
                try {
                    openOutline(g.outline());
                } catch (CamInputException | IOException e) {
                    outlineFile = Optional.of(g.outline());
                    outline = List.of();
                }
            }
        });
    }

    /**
     * The settings of the fields.
     *
     * @throws CamInputException naming the field that does not parse, or a missing outline
     */
    public GradingSettings settings() throws CamInputException {
        if (outlineFile.isEmpty()) {
            throw new CamInputException("Outline", "open a base outline first");
        }
        return new GradingSettings(
                outlineFile.get(),
                number("Base size", baseSize),
                sizes.trim(),
                halfSizes,
                system,
                optional("Length step", lengthStep),
                optional("Width step", widthStep),
                parsedOrigin(),
                number("Shrinkage", shrinkage),
                shrinkageMode,
                heel());
    }

    /** The heel coordination of the fields: the designated elements, else a job's boundary, else none. */
    private Optional<JobSettings.HeelCoordination> heel() throws CamInputException {
        if (heelElements.isBlank() && heelBoundaryMm.isEmpty()) {
            return Optional.empty();
        }
        double g = number("Heel group", heelGroup);
        if (g != Math.rint(g) || g < 1 || g > 400) {
            throw new CamInputException(
                    "Heel group", "expected a whole number of sizes from 1 to 400, found '" + heelGroup + "'");
        }
        if (!heelElements.isBlank()) {
            try {
                org.fresa.grading.Coordination.parseElements(heelElements);
            } catch (IllegalArgumentException e) {
                throw new CamInputException("Heel elements", e.getMessage());
            }
            return Optional.of(new JobSettings.HeelCoordination((int) g, OptionalDouble.empty(), heelElements.trim()));
        }
        return Optional.of(new JobSettings.HeelCoordination((int) g, heelBoundaryMm, ""));
    }

    /**
     * The outline's elements the planner designates as the heel for coordination (figure 4.4),
     * e.g. {@code 1-4,18-20}, 1 the first element; empty for no coordination by elements.
     */
    public String heelElements() {
        return heelElements;
    }

    public void setHeelElements(String s) {
        heelElements = s;
    }

    /** Sizes per heel. */
    public String heelGroup() {
        return heelGroup;
    }

    public void setHeelGroup(String s) {
        heelGroup = s;
    }

    /** The keys of {@link #problems()}: the names of the tab's fields. */
    public static final String OUTLINE = "grading-outline";

    public static final String ORIGIN = "grading-origin";
    public static final String SYSTEM = "grading-system";
    public static final String BASE_SIZE = "grading-base-size";
    public static final String SIZES = "grading-sizes";
    public static final String LENGTH_STEP = "grading-length-step";
    public static final String WIDTH_STEP = "grading-width-step";
    public static final String SHRINKAGE = "grading-shrinkage";
    public static final String SHRINKAGE_MODE = "grading-shrinkage-mode";

    /** The field of each setting the grading names in {@code GradingService.refusals}, with its label. */
    private static final java.util.Map<String, String[]> FIELDS = java.util.Map.of(
            "system",
            new String[] {SYSTEM, "System"},
            "sizes",
            new String[] {SIZES, "Sizes"},
            "baseSize",
            new String[] {BASE_SIZE, "Base size"},
            "lengthStep",
            new String[] {LENGTH_STEP, "Length step (mm)"},
            "widthStep",
            new String[] {WIDTH_STEP, "Width step (mm)"},
            "shrinkage",
            new String[] {SHRINKAGE, "Shrinkage"},
            "shrinkageMode",
            new String[] {SHRINKAGE_MODE, "Shrinkage mode"},
            "settings",
            new String[] {SIZES, "Grading"});

    /**
     * What is wrong with the typed fields, by field name (the constants above), in the planner's
     * words: first whether each field reads as what it holds, then what the grading says of the
     * values (a range A-B with A > B, a size the system does not have, ...). Empty when Grade may run.
     */
    public java.util.Map<String, String> problems() {
        java.util.Map<String, String> out = new java.util.LinkedHashMap<>();
        if (outlineFile.isEmpty()) {
            out.put(OUTLINE, "Open the base outline to grade (.contour or .dxf).");
        } else if (outline.isEmpty()) {
            out.put(OUTLINE, "Outline: " + outlineFile.get().getFileName() + " cannot be read; open another one.");
        }
        readable(out, BASE_SIZE, "Base size", baseSize, false);
        readable(out, LENGTH_STEP, "Length step (mm)", lengthStep, true);
        readable(out, WIDTH_STEP, "Width step (mm)", widthStep, true);
        readable(out, SHRINKAGE, "Shrinkage", shrinkage, false);
        try {
            parsedOrigin();
        } catch (CamInputException e) {
            out.put(
                    ORIGIN,
                    "Origin X,Y: expected X,Y in mm (or empty for the heel centre), found '" + origin.trim() + "'.");
        }
        if (sizes.trim().isEmpty()) {
            out.put(SIZES, "Sizes: a range A-B is needed (e.g. 36-44).");
        }
        if (!out.isEmpty() && !(out.size() == 1 && out.containsKey(OUTLINE))) {
            return out;
        }
        try {
            GradingSettings s = new GradingSettings(
                    outlineFile.orElse(Path.of("")),
                    number("Base size", baseSize),
                    sizes.trim(),
                    halfSizes,
                    system,
                    optional("Length step", lengthStep),
                    optional("Width step", widthStep),
                    parsedOrigin(),
                    number("Shrinkage", shrinkage),
                    shrinkageMode);
            GradingService.refusals(s, GradingService.Options.DEFAULT).forEach((k, m) -> {
                String[] f = FIELDS.getOrDefault(k, new String[] {SIZES, "Grading"});
                out.putIfAbsent(f[0], f[1] + ": " + m + (m.endsWith(".") ? "" : "."));
            });
        } catch (CamInputException e) {
            // every field was read above
            throw new IllegalStateException(e);
        }
        return out;
    }

    private static void readable(
            java.util.Map<String, String> out, String key, String label, String text, boolean mayBeEmpty) {
        String t = text.trim();
        if (t.isEmpty() && mayBeEmpty) {
            return;
        }
        try {
            if (Double.isFinite(Double.parseDouble(t))) {
                return;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        out.put(key, FieldProblems.notANumber(label, t));
    }

    /** The settings of the fields; empty while {@link #problems()} is not. */
    public Optional<GradingSettings> typedSettings() {
        if (!problems().isEmpty()) {
            return Optional.empty();
        }
        try {
            return Optional.of(settings());
        } catch (CamInputException e) {
            return Optional.empty();
        }
    }

    /** The job with these grading settings, what it runs unchanged. */
    public Job applyTo(Job job) throws CamInputException {
        return job.withGrading(settings());
    }

    /** Grades the outline with the fields' settings (call off the event thread for long runs). */
    public GradingResult grade() throws CamInputException {
        return grade(settings());
    }

    /**
     * Grades the outline with the given settings: touches no state, so the tab calls it off the
     * event thread with the settings it read on it.
     *
     * @throws CamInputException when there is no outline or the settings are refused
     */
    public GradingResult grade(GradingSettings s) throws CamInputException {
        List<Contour> base = outline;
        if (base.isEmpty()) {
            throw new CamInputException("Outline", "open a base outline first");
        }
        String name = s.outline().getFileName().toString();
        return GradingService.grade(base, name, s, GradingService.Options.DEFAULT);
    }

    /** Keeps a result computed by {@link #grade()} for the table and the plot. */
    public void setResult(GradingResult r) {
        result = Optional.of(r);
    }

    /** Forgets the last result (the settings shown are no longer the ones graded). */
    public void clearResult() {
        result = Optional.empty();
    }

    public Optional<GradingResult> result() {
        return result;
    }

    /** Writes every size's files, the table and the plot into the folder. */
    public TaskOutcome export(Path dir, ProgressMonitor progress) throws CamInputException, IOException {
        if (outline.isEmpty()) {
            throw new CamInputException("Outline", "open a base outline first");
        }
        String name = outlineFile.map(p -> p.getFileName().toString()).orElse("outline");
        return GradingService.write(
                outline, name, settings(), GradingService.Options.DEFAULT, new OutputFolder(dir), progress);
    }

    /** The origin picked on the plot (mm, kept to 0.001); the last result no longer applies. */
    public void pickOrigin(Vec2 p) {
        origin = ExactDecimal.of(round3(p.x())) + "," + ExactDecimal.of(round3(p.y()));
        result = Optional.empty();
    }

    private static double round3(double v) {
        return Math.round(v * 1000) / 1000.0 + 0.0;
    }

    /** The table rows, one per graded size, as text. */
    public List<List<String>> tableRows() {
        List<List<String>> rows = new ArrayList<>();
        result.ifPresent(r -> {
            for (GradedSize g : r.sizes()) {
                rows.add(List.of(
                        g.name(),
                        fmt(g.lengthMm(), 3),
                        fmt(g.widthMm(), 3),
                        fmt(g.factors().alfa(), 6),
                        fmt(g.factors().beta(), 6),
                        fmt(g.factors().length(), 6),
                        fmt(g.factors().width(), 6),
                        g.maxDeviationMm().isPresent() ? fmt(g.maxDeviationMm().getAsDouble(), 4) : "",
                        girth(g.factors().size())));
            }
        });
        return rows;
    }

    /**
     * The width fitting whose last girths (table 3.1, French sizes 29 to 42, Brazilian 27 to 40)
     * the table shows, "" for none.
     */
    public String fitting() {
        return fitting;
    }

    public void setFitting(String f) {
        if (!FITTINGS.contains(f)) {
            throw new IllegalArgumentException("width fitting must be one of " + FITTINGS + ": " + f);
        }
        fitting = f;
    }

    /** The girth of a graded size for the chosen fitting, "" without one or outside table 3.1. */
    private String girth(double size) {
        if (fitting.isEmpty()) {
            return "";
        }
        SizeSystem sys = system;
        OptionalDouble french = org.fresa.grading.LastGirths.frenchSize(sys, size);
        if (french.isEmpty()) {
            return "";
        }
        OptionalDouble g = org.fresa.grading.LastGirths.girthMm(french.getAsDouble(), fitting);
        return g.isPresent() ? fmt(g.getAsDouble(), 1) : "";
    }

    private static String fmt(double v, int decimals) {
        return String.format(Locale.ROOT, "%." + decimals + "f", v);
    }

    /**
     * What the plot shows: the nested graded outlines when graded, else the base outline; and
     * the origin (typed or the heel centre) as a small cross.
     */
    public PlotScene scene() {
        PlotScene s;
        Optional<Vec2> o;
        if (result.isPresent()) {
            GradingResult r = result.get();
            s = GradingChart.scene(
                    "Graded sizes", GradingService.sizeOutlines(r), r.frame().lengthAxis());
            o = Optional.of(r.frame().origin());
        } else {
            s = PlotScene.empty(outline.isEmpty() ? "Open a base outline" : "Base outline");
            for (Contour c : outline) {
                s = s.withContour("base", PlotScene.Style.OUTLINE, c);
            }
            s = withHeelElements(s);
            o = originOrEmpty();
        }
        if (o.isPresent()) {
            Vec2 c = o.get();
            s = s.with(new PlotScene.Layer(
                            "origin",
                            PlotScene.Style.WARNING,
                            List.of(
                                    new org.fresa.geom.Segment2(c.plus(new Vec2(-4, 0)), c.plus(new Vec2(4, 0))),
                                    new org.fresa.geom.Segment2(c.plus(new Vec2(0, -4)), c.plus(new Vec2(0, 4))),
                                    Arc2.circle(c, 2, true))))
                    .withLabel(c.plus(new Vec2(5, 5)), "origin");
        }
        return s;
    }

    /** The designated heel elements drawn over the base outline, when they read. */
    private PlotScene withHeelElements(PlotScene s) {
        if (outline.isEmpty() || heelElements.isBlank()) {
            return s;
        }
        java.util.SortedSet<Integer> heel;
        try {
            heel = org.fresa.grading.Coordination.parseElements(heelElements);
        } catch (IllegalArgumentException e) {
            return s;
        }
        List<org.fresa.geom.Curve2> cs = new ArrayList<>();
        List<org.fresa.geom.Curve2> all = outline.get(0).curves();
        for (int i : heel) {
            if (i <= all.size()) {
                cs.add(all.get(i - 1));
            }
        }
        return s.with(new PlotScene.Layer("heel elements " + heelElements.trim(), PlotScene.Style.FINISH, cs));
    }

    private Optional<Vec2> originOrEmpty() {
        try {
            return parsedOrigin();
        } catch (CamInputException e) {
            return Optional.empty();
        }
    }

    private Optional<Vec2> parsedOrigin() throws CamInputException {
        String t = origin.trim();
        if (t.isEmpty()) {
            return Optional.empty();
        }
        String[] p = t.split(",");
        if (p.length == 2) {
            try {
                double x = Double.parseDouble(p[0].trim());
                double y = Double.parseDouble(p[1].trim());
                if (Double.isFinite(x) && Double.isFinite(y)) {
                    return Optional.of(new Vec2(x, y));
                }
            } catch (NumberFormatException e) {
                // reported below
            }
        }
        throw new CamInputException(
                "Origin", "expected X,Y in mm (or empty for the heel centre), found '" + origin + "'");
    }

    private static double number(String field, String text) throws CamInputException {
        try {
            double d = Double.parseDouble(text.trim());
            if (Double.isFinite(d)) {
                return d;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new CamInputException(field, "expected a number, found '" + text + "'");
    }

    private static OptionalDouble optional(String field, String text) throws CamInputException {
        return text.trim().isEmpty() ? OptionalDouble.empty() : OptionalDouble.of(number(field, text));
    }

    public SizeSystem system() {
        return system;
    }

    public void setSystem(SizeSystem s) {
        system = java.util.Objects.requireNonNull(s, "system");
    }

    public String baseSize() {
        return baseSize;
    }

    public void setBaseSize(String s) {
        baseSize = s;
    }

    public String sizes() {
        return sizes;
    }

    public void setSizes(String s) {
        sizes = s;
    }

    public boolean halfSizes() {
        return halfSizes;
    }

    public void setHalfSizes(boolean b) {
        halfSizes = b;
    }

    public String lengthStep() {
        return lengthStep;
    }

    public void setLengthStep(String s) {
        lengthStep = s;
    }

    public String widthStep() {
        return widthStep;
    }

    public void setWidthStep(String s) {
        widthStep = s;
    }

    public String origin() {
        return origin;
    }

    public void setOrigin(String s) {
        origin = s;
    }

    public String shrinkage() {
        return shrinkage;
    }

    public void setShrinkage(String s) {
        shrinkage = s;
    }

    public ShrinkageMode shrinkageMode() {
        return shrinkageMode;
    }

    public void setShrinkageMode(ShrinkageMode s) {
        shrinkageMode = java.util.Objects.requireNonNull(s, "shrinkageMode");
    }
}
