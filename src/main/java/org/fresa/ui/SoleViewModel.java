package org.fresa.ui;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.chart.PlotScene;
import org.fresa.geom.Box2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.grading.GradedSize;
import org.fresa.io.OutputFolder;
import org.fresa.job.Job;
import org.fresa.job.JobSettings;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.SoleService;
import org.fresa.job.TaskOutcome;
import org.fresa.model.CamInputException;
import org.fresa.model.ExactDecimal;
import org.fresa.model.Toolpath;
import org.fresa.sole.FigurePath;
import org.fresa.sole.Foot;
import org.fresa.sole.PatternKind;
import org.fresa.sole.SizeRule;
import org.fresa.sole.SizeScale;
import org.fresa.sole.SoleTread;
import org.fresa.sole.Stroke;
import org.fresa.sole.TreadFigure;
import org.fresa.sole.TreadFigures;
import org.fresa.sole.TreadItem;

/**
 * The Sole tab's state without Swing: the figure library (names, parameters, previews of the
 * thesis's calls), the job's sole plan, the selected size and foot, and the plot of the
 * selection. Planning reads files and grades, so the tab calls {@link #load} and {@link #scene}
 * off the event thread.
 */
public final class SoleViewModel {

    private static final Tolerance TOL = Tolerance.DEFAULT;

    private String macro = "SUB1A";
    private Optional<SoleService.SolePlan> plan = Optional.empty();
    private String problem = "";
    private List<String> sizes = List.of();
    private String size = "";
    private Foot foot = Foot.RIGHT;
    private Optional<Job> job = Optional.empty();
    private int selected = -1;

    /** The macros of the library in the thesis's order. */
    public List<String> macros() {
        return TreadFigures.MACROS;
    }

    public String macro() {
        return macro;
    }

    public void selectMacro(String m) {
        TreadFigures.parameters(m);
        this.macro = m.toUpperCase(java.util.Locale.ROOT);
    }

    /** The selected macro's parameters (thesis names) with the values of its thesis call, one per line. */
    public String parametersText() {
        StringBuilder sb = new StringBuilder(macro).append(" (mm)\n");
        for (String kv : TreadFigures.thesisExample(macro).split(",")) {
            sb.append(kv.replace("=", " = ")).append('\n');
        }
        if (TreadFigures.isContinuous(macro)) {
            sb.append("continuous: carries on the groove in progress\n");
        }
        if (TreadFigures.isSpecial(macro)) {
            sb.append("special design, group ")
                    .append(org.fresa.sole.SpecialDesigns.group(macro))
                    .append('\n');
        }
        if (TreadFigures.needsDrawing(macro)) {
            sb.append("outlines from a DXF drawing: the figure's file in the job\n");
        }
        return sb.toString();
    }

    /** The selected macro's tool-centre path for its thesis call (continuous ones from PRIM's point). */
    public PlotScene preview() {
        try {
            TreadFigure f =
                    TreadFigures.of(macro, TreadFigures.parseParams(TreadFigures.thesisExample(macro), macro), macro);
            Vec2 at = TreadFigures.isContinuous(macro) ? Vec2.of(-40, -40) : Vec2.ZERO;
            FigurePath p = f.path(at, TOL);
            List<Curve2> cs = new ArrayList<>();
            for (Stroke s : p.strokes()) {
                cs.addAll(s.curves());
            }
            return PlotScene.empty(macro).with(new PlotScene.Layer(macro, PlotScene.Style.FEED, cs));
        } catch (CamInputException e) {
            return PlotScene.empty(macro + ": " + e.getMessage());
        }
    }

    /** Reads the job's sole settings; a bad job leaves no plan and a problem to show. */
    public void load(Job job) {
        plan = Optional.empty();
        sizes = List.of();
        problem = "";
        selected = -1;
        this.job = Optional.empty();
        if (job.sole().isEmpty()) {
            problem = "The job has no sole settings (open a sole job, e.g. samples/jobs/sole-men40.xml).";
            return;
        }
        try {
            SoleService.SolePlan p = SoleService.plan(job.sole().get(), job.name());
            plan = Optional.of(p);
            this.job = Optional.of(job);
            sizes = SoleService.sizes(p).stream().map(ExactDecimal::of).toList();
            String base = ExactDecimal.of(job.sole().get().baseSize());
            size = sizes.contains(base) ? base : sizes.get(0);
        } catch (CamInputException e) {
            problem = e.getMessage();
        }
    }

    public String problem() {
        return problem;
    }

    public List<String> sizes() {
        return sizes;
    }

    public String size() {
        return size;
    }

    public void selectSize(String s) {
        if (!sizes.contains(s)) {
            throw new IllegalArgumentException("not a size of the job: " + s);
        }
        size = s;
    }

    public Foot foot() {
        return foot;
    }

    public void selectFoot(Foot f) {
        foot = f;
    }

    /** The outline and tread of the selected size and foot, or an empty scene naming the problem. */
    public PlotScene scene() {
        if (plan.isEmpty()) {
            return PlotScene.empty(problem.isEmpty() ? "No sole plan" : problem);
        }
        SoleService.SolePlan p = plan.get();
        GradedSize g = SoleService.graded(p, Double.parseDouble(size));
        Toolpath tp = SoleService.treadProgram(p, g, foot);
        var outline = foot == Foot.RIGHT
                ? g.output().get(0)
                : SoleTread.mirrored(g.output().get(0), SoleService.origin(p).x());
        PlotScene scene = PlotScene.empty("Sole " + g.name() + ", " + foot.id() + " foot")
                .withContour("outline", PlotScene.Style.OUTLINE, outline)
                .withToolpath(tp);
        if (selected >= 0) {
            List<Curve2> cs = new ArrayList<>();
            for (Stroke st : SoleTread.placed(p.tread().items().get(selected), SoleService.scale(p, g), foot, TOL)) {
                cs.addAll(st.curves());
            }
            scene = scene.with(
                    new PlotScene.Layer("selected: " + designs().get(selected).name(), PlotScene.Style.WARNING, cs));
        }
        return scene;
    }

    /**
     * What Generate would refuse of the selected size, said as the size is shown: the job's cavity
     * tool not smaller than an arc of the size's outline (its centre cannot follow that arc), as
     * the run says it; empty when the size's cavity is milled or the job names no cavity tool.
     */
    public Optional<String> sizeProblem() {
        if (plan.isEmpty() || plan.get().settings().cavityTool().isEmpty()) {
            return Optional.empty();
        }
        SoleService.SolePlan p = plan.get();
        org.fresa.sole.TreadTool t = p.tools().get(p.settings().cavityTool());
        if (t == null) {
            return Optional.empty();
        }
        GradedSize g = SoleService.graded(p, Double.parseDouble(size));
        return org.fresa.sole.CavityToolRule.check(g.output().get(0), t.diameterMm())
                .map(v -> "size " + g.name() + ": " + v.sentence() + " (Generate refuses this size)");
    }

    /**
     * The selected size's pair in the mould block, as the programs place it (machine frame): the
     * block's edges, the mirror line, both feet's outlines, treads and cavities; or an empty
     * scene saying why there is none.
     */
    public PlotScene pairScene() {
        if (plan.isEmpty()) {
            return PlotScene.empty(problem.isEmpty() ? "No sole plan" : problem);
        }
        SoleService.SolePlan p = plan.get();
        return SoleService.pairScene(p, SoleService.graded(p, Double.parseDouble(size)))
                .orElseGet(() -> PlotScene.empty(
                        "The job has no mould block: each foot's programs stay in the outline's frame"));
    }

    /** The edited job: the loaded one with the placed, moved and edited figures (empty before a load). */
    public Optional<Job> job() {
        return job;
    }

    /** The job's tread designs, in cutting order; indices are those of {@link #select}. */
    public List<JobSettings.SoleDesign> designs() {
        return job.map(j -> j.sole().orElseThrow().designs()).orElse(List.of());
    }

    /** The selected design's index, -1 for none. */
    public int selected() {
        return selected;
    }

    /** Selects a design by index (-1 for none). */
    public void select(int index) {
        if (index < -1 || index >= designs().size()) {
            throw new IllegalArgumentException("no design " + index);
        }
        selected = index;
    }

    /**
     * Selects the design under a point of the plot (mm, in the shown size and foot): the one with
     * the smallest bounding box, grown by 3 mm, that holds the point; none when no box does.
     *
     * @return whether a design was selected
     */
    public boolean selectAt(Vec2 plotMm) {
        selected = -1;
        if (plan.isEmpty()) {
            return false;
        }
        Vec2 p = toJobFrame(plotMm);
        double best = Double.POSITIVE_INFINITY;
        List<TreadItem> items = plan.get().tread().items();
        for (int i = 0; i < items.size(); i++) {
            Optional<Box2> b = bounds(items.get(i).strokes(TOL));
            if (b.isEmpty()) {
                continue;
            }
            Box2 g = new Box2(
                    b.get().minX() - 3,
                    b.get().minY() - 3,
                    b.get().maxX() + 3,
                    b.get().maxY() + 3);
            double area = g.width() * g.height();
            if (g.contains(p) && area < best) {
                best = area;
                selected = i;
            }
        }
        return selected >= 0;
    }

    /**
     * Where a design sits: the centre of its grooves' bounding box at the base size, right foot
     * (mm, job frame).
     */
    public Vec2 position(int index) {
        return bounds(plan.orElseThrow().tread().items().get(index).strokes(TOL))
                .map(Box2::center)
                .orElse(Vec2.ZERO);
    }

    /**
     * Maps a point of the plot (the shown size and foot) into the job's frame (base size, right
     * foot): the left foot mirrored back about x = origin, the size's pantograph undone.
     */
    public Vec2 toJobFrame(Vec2 plotMm) {
        SoleService.SolePlan p = plan.orElseThrow();
        Vec2 o = SoleService.origin(p);
        double x = foot == Foot.LEFT ? 2 * o.x() - plotMm.x() : plotMm.x();
        SizeScale sc = SoleService.scale(p, SoleService.graded(p, Double.parseDouble(size)));
        return Vec2.of(o.x() + (x - o.x()) / sc.widthFactor(), o.y() + (plotMm.y() - o.y()) / sc.lengthFactor());
    }

    /** A plot displacement (mm, shown size and foot) as a displacement in the job's frame. */
    public Vec2 deltaToJobFrame(Vec2 plotDeltaMm) {
        return toJobFrame(plotDeltaMm).minus(toJobFrame(Vec2.ZERO));
    }

    /**
     * Places the selected library figure with the centre of its grooves at a point of the plot:
     * a new design (one copy, rule position, the job's first tread tool) with the macro's thesis
     * parameters, which becomes the selection. Continuous macros carry on another groove and
     * PRIM/NOVO cut nothing, so they are refused.
     *
     * @return empty when placed, else why not
     */
    public Optional<String> place(Vec2 plotMm) {
        if (job.isEmpty()) {
            return Optional.of("Load a sole job first");
        }
        if (TreadFigures.isContinuous(macro) || macro.equals("PRIM") || macro.equals("NOVO")) {
            return Optional.of(macro + " carries on a groove started by PRIM or NOVO: it cannot be placed on its own");
        }
        if (TreadFigures.needsDrawing(macro)) {
            return Optional.of(macro + " engraves a DXF drawing's outlines: name the drawing in the job's figure"
                    + " (file attribute)");
        }
        JobSettings.SoleSettings s = job.get().sole().orElseThrow();
        Optional<String> tool = s.tools().stream()
                .map(JobSettings.SoleTool::id)
                .filter(t -> !t.equals(s.cavityTool()))
                .findFirst();
        if (tool.isEmpty()) {
            return Optional.of("The job has no tread tool: add one to the job first");
        }
        String params = TreadFigures.thesisExample(macro);
        Vec2 centre;
        try {
            centre = bounds(figurePath(macro, params).strokes())
                    .map(Box2::center)
                    .orElse(Vec2.ZERO);
        } catch (CamInputException e) {
            return Optional.of(e.getMessage());
        }
        Vec2 d = toJobFrame(plotMm).minus(centre);
        String name = uniqueName(macro);
        JobSettings.SoleDesign design = new JobSettings.SoleDesign(
                name,
                tool.get(),
                SizeRule.POSITION,
                false,
                PatternKind.COPIES,
                1,
                1,
                0,
                0,
                0,
                0,
                0,
                0,
                List.of(),
                List.of(new JobSettings.SoleFigure(macro, params)),
                List.of(copy(d.x(), d.y())));
        List<JobSettings.SoleDesign> ds = new ArrayList<>(s.designs());
        ds.add(design);
        Optional<String> why = apply(ds);
        if (why.isEmpty()) {
            selected = ds.size() - 1;
        }
        return why;
    }

    /**
     * Moves the selected design by a displacement in the job's frame (mm): its copies are
     * shifted (a single figure becomes one copy). Linear, grid and polar patterns are moved by
     * editing their figures' parameters instead.
     *
     * @return empty when moved, else why not
     */
    public Optional<String> moveSelectedBy(double dxMm, double dyMm) {
        if (selected < 0) {
            return Optional.of("Select a figure first");
        }
        JobSettings.SoleDesign d = designs().get(selected);
        List<JobSettings.SoleCopy> copies;
        if (d.pattern() == PatternKind.SINGLE) {
            copies = List.of(copy(dxMm, dyMm));
        } else if (d.pattern() == PatternKind.COPIES) {
            copies = d.copies().stream()
                    .map(c -> new JobSettings.SoleCopy(
                            c.dxMm() + dxMm, c.dyMm() + dyMm, c.mirrorXMm(), c.mirrorYMm(), c.rotateDeg()))
                    .toList();
        } else {
            return Optional.of("'" + d.name() + "' is a " + d.pattern() + " pattern: move it by its parameters");
        }
        JobSettings.SoleDesign moved = d.withCopies(copies);
        List<JobSettings.SoleDesign> ds = new ArrayList<>(designs());
        ds.set(selected, moved);
        return apply(ds);
    }

    /** Moves the selected design so that its {@link #position} lands on a point of the plot. */
    public Optional<String> moveSelectedTo(Vec2 plotMm) {
        if (selected < 0) {
            return Optional.of("Select a figure first");
        }
        Vec2 d = toJobFrame(plotMm).minus(position(selected));
        return moveSelectedBy(d.x(), d.y());
    }

    /** Removes the selected design from the job. */
    public Optional<String> deleteSelected() {
        if (selected < 0) {
            return Optional.of("Select a figure first");
        }
        List<JobSettings.SoleDesign> ds = new ArrayList<>(designs());
        ds.remove(selected);
        int was = selected;
        selected = -1;
        Optional<String> why = apply(ds);
        if (why.isPresent()) {
            selected = was;
        }
        return why;
    }

    /** One parameter of a figure: its thesis name, unit and value as text. */
    public record Parameter(String name, String unit, String value) {}

    /** The parameters of the selected design's first figure (empty when none is selected). */
    public List<Parameter> parameters() {
        if (selected < 0) {
            return List.of();
        }
        JobSettings.SoleFigure f = designs().get(selected).figures().get(0);
        Map<String, Double> vals;
        try {
            vals = TreadFigures.parseParams(f.params(), "figure");
        } catch (CamInputException e) {
            return List.of();
        }
        List<Parameter> out = new ArrayList<>();
        for (String n : TreadFigures.parameters(f.macro())) {
            Double v = vals.get(n);
            out.add(new Parameter(n, unit(n), v == null ? "" : ExactDecimal.of(v)));
        }
        return out;
    }

    /** The unit of a thesis parameter: N is a count, every other one a length or coordinate. */
    static String unit(String name) {
        return name.equals("N") ? "count" : "mm";
    }

    /**
     * Sets one parameter of the selected design's first figure; the figure is rebuilt and the
     * tread replanned, so a value that gives no path is refused.
     *
     * @return empty when set, else why not (the job is unchanged)
     */
    public Optional<String> setParameter(String name, String text) {
        if (selected < 0) {
            return Optional.of("Select a figure first");
        }
        JobSettings.SoleDesign d = designs().get(selected);
        JobSettings.SoleFigure f = d.figures().get(0);
        String k = name.trim().toUpperCase(Locale.ROOT);
        if (!TreadFigures.parameters(f.macro()).contains(k)) {
            return Optional.of(f.macro() + " has no parameter " + name);
        }
        double v;
        try {
            v = Double.parseDouble(text.trim());
        } catch (NumberFormatException e) {
            return Optional.of(k + ": expected a number in " + unit(k) + ", found '" + text.trim() + "'");
        }
        if (!Double.isFinite(v) || Math.abs(v) > 1e6) {
            return Optional.of(
                    k + ": expected a number of at most 1000000 " + unit(k) + ", found '" + text.trim() + "'");
        }
        Map<String, Double> vals;
        try {
            vals = TreadFigures.parseParams(f.params(), "figure");
        } catch (CamInputException e) {
            return Optional.of(e.getMessage());
        }
        vals.put(k, v);
        StringBuilder sb = new StringBuilder();
        vals.forEach((n, x) ->
                sb.append(sb.length() == 0 ? "" : ",").append(n).append('=').append(ExactDecimal.of(x)));
        try {
            TreadFigures.of(f.macro(), vals, d.name());
        } catch (CamInputException e) {
            return Optional.of(e.problem());
        }
        List<JobSettings.SoleFigure> figs = new ArrayList<>(d.figures());
        figs.set(0, new JobSettings.SoleFigure(f.macro(), sb.toString(), f.drawing()));
        JobSettings.SoleDesign edited = d.withFigures(figs);
        List<JobSettings.SoleDesign> ds = new ArrayList<>(designs());
        ds.set(selected, edited);
        return apply(ds);
    }

    /**
     * Writes the edited job's programs into a folder with the same service as {@code fresa sole}.
     *
     * @throws CamInputException when no job is loaded or the job is bad
     */
    public TaskOutcome generate(Path folder, ProgressMonitor progress) throws CamInputException, IOException {
        if (job.isEmpty()) {
            throw new CamInputException("sole", problem.isEmpty() ? "load a sole job first" : problem);
        }
        return SoleService.run(job.get(), new OutputFolder(folder), progress);
    }

    private Optional<String> apply(List<JobSettings.SoleDesign> ds) {
        Job j = job.orElseThrow();
        JobSettings.SoleSettings s = j.sole().orElseThrow();
        JobSettings.SoleSettings n = s.withDesigns(ds);
        try {
            plan = Optional.of(SoleService.plan(n, j.name()));
        } catch (CamInputException e) {
            return Optional.of(e.getMessage());
        }
        job = Optional.of(j.withSole(n));
        return Optional.empty();
    }

    private String uniqueName(String base) {
        List<String> names =
                designs().stream().map(JobSettings.SoleDesign::name).toList();
        int k = 1;
        while (names.contains(base + " " + k)) {
            k++;
        }
        return base + " " + k;
    }

    private static JobSettings.SoleCopy copy(double dxMm, double dyMm) {
        return new JobSettings.SoleCopy(dxMm, dyMm, OptionalDouble.empty(), OptionalDouble.empty(), 0);
    }

    private static FigurePath figurePath(String m, String params) throws CamInputException {
        return TreadFigures.of(m, TreadFigures.parseParams(params, m), m).path(Vec2.ZERO, TOL);
    }

    private static Optional<Box2> bounds(List<Stroke> strokes) {
        Box2 b = null;
        for (Stroke st : strokes) {
            for (Curve2 c : st.curves()) {
                b = b == null ? c.bounds() : b.union(c.bounds());
            }
        }
        return Optional.ofNullable(b);
    }
}
