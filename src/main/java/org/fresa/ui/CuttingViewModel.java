package org.fresa.ui;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.fresa.chart.PlotScene;
import org.fresa.cutting.CutPath;
import org.fresa.cutting.CutPlan;
import org.fresa.cutting.CutProcess;
import org.fresa.cutting.CutSense;
import org.fresa.cutting.KerfCompensation;
import org.fresa.cutting.LeadShape;
import org.fresa.dxf.DrawingUnits;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.job.CuttingService;
import org.fresa.job.Job;
import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.model.CamInputException;
import org.fresa.model.ExactDecimal;
import org.fresa.post.CuttingPost;
import org.fresa.setting.SettingRanges;

/**
 * The Cutting tab's state without Swing: the drawing and the settings the planner types in, the
 * last result, and what the tab shows of it (the plot scene, the totals, the program text).
 */
public final class CuttingViewModel {

    /** The keys of {@link #problems()}: the names of the tab's fields. */
    public static final String DRAWING = "cutting-drawing";

    public static final String KERF = "cutting-kerf";
    public static final String LEAD_IN = "cutting-lead-in";
    public static final String LEAD_OUT = "cutting-lead-out";
    public static final String OVERCUT = "cutting-overcut";

    /** A new job's settings: the cutting module's defaults ({@link CuttingSettings#DEFAULTS}); no drawing. */
    private static final CuttingSettings DEFAULTS = CuttingSettings.DEFAULTS;

    private Path drawing;
    private String kerfMm = ExactDecimal.of(DEFAULTS.kerfMm());
    private CutProcess process = DEFAULTS.process();
    private String leadInMm = ExactDecimal.of(DEFAULTS.leadInMm());
    private String leadOutMm = ExactDecimal.of(DEFAULTS.leadOutMm());
    private LeadShape lead = DEFAULTS.lead();
    private boolean paperMode = DEFAULTS.paperMode();
    private CuttingPost post = DEFAULTS.post();
    private KerfCompensation compensation = DEFAULTS.compensation();
    private CutSense outerDirection = DEFAULTS.outerDirection();
    private CutSense holeDirection = DEFAULTS.holeDirection();
    private String overcutMm = ExactDecimal.of(DEFAULTS.overcutMm());
    private boolean avoidCutParts = DEFAULTS.avoidCutParts();
    // the job's gap tolerance and units, which the tab has no fields for, go on as the job has them
    private double toleranceMm = DEFAULTS.toleranceMm();
    private DrawingUnits units = DEFAULTS.units();
    // the planner's own order and start points over the automatic ones
    private org.fresa.cutting.CutOrderOverride cutOrder = DEFAULTS.cutOrder();
    private CuttingService.Result result;
    // what the run says of the result; null until asked
    private Said said;

    /** Takes the job's cutting settings, if it has any (the drawing, kerf, process, leads, ...). */
    public void load(Job job) {
        job.cutting().ifPresent(c -> {
            if (!c.drawing().equals(drawing)) {
                result = null;
                said = null;
            }
            drawing = c.drawing();
            kerfMm = ExactDecimal.of(c.kerfMm());
            process = c.process();
            leadInMm = ExactDecimal.of(c.leadInMm());
            leadOutMm = ExactDecimal.of(c.leadOutMm());
            lead = c.lead();
            paperMode = c.paperMode();
            post = c.post();
            compensation = c.compensation();
            outerDirection = c.outerDirection();
            holeDirection = c.holeDirection();
            overcutMm = ExactDecimal.of(c.overcutMm());
            avoidCutParts = c.avoidCutParts();
            toleranceMm = c.toleranceMm();
            units = c.units();
            cutOrder = c.cutOrder();
        });
    }

    /** The job with these cutting settings (checked), the task unchanged. */
    public Job applyTo(Job job) throws CamInputException {
        return job.withCutting(settings());
    }

    public String kerfMm() {
        return kerfMm;
    }

    public CutProcess process() {
        return process;
    }

    public String leadInMm() {
        return leadInMm;
    }

    public String leadOutMm() {
        return leadOutMm;
    }

    public LeadShape lead() {
        return lead;
    }

    public boolean paperMode() {
        return paperMode;
    }

    public CuttingPost post() {
        return post;
    }

    public KerfCompensation compensation() {
        return compensation;
    }

    public void setCompensation(KerfCompensation v) {
        compensation = v;
    }

    public CutSense outerDirection() {
        return outerDirection;
    }

    public void setOuterDirection(CutSense v) {
        outerDirection = v;
    }

    public CutSense holeDirection() {
        return holeDirection;
    }

    public void setHoleDirection(CutSense v) {
        holeDirection = v;
    }

    public String overcutMm() {
        return overcutMm;
    }

    public void setOvercutMm(String v) {
        overcutMm = v.trim();
    }

    public boolean avoidCutParts() {
        return avoidCutParts;
    }

    public void setAvoidCutParts(boolean v) {
        avoidCutParts = v;
    }

    public Optional<Path> drawing() {
        return Optional.ofNullable(drawing);
    }

    /** A new drawing: its contours are not the old one's, so the cut order is the automatic one again. */
    public void setDrawing(Path p) {
        drawing = p;
        result = null;
        said = null;
        cutOrder = org.fresa.cutting.CutOrderOverride.NONE;
    }

    public void setKerfMm(String v) {
        kerfMm = v.trim();
    }

    public void setProcess(CutProcess v) {
        process = v;
    }

    public void setLeadInMm(String v) {
        leadInMm = v.trim();
    }

    public void setLeadOutMm(String v) {
        leadOutMm = v.trim();
    }

    public void setLead(LeadShape v) {
        lead = v;
    }

    public void setPaperMode(boolean v) {
        paperMode = v;
    }

    public void setPost(CuttingPost v) {
        post = v;
    }

    /**
     * What is wrong with the typed fields, in the planner's words, by field name ({@link #DRAWING},
     * {@link #KERF}, {@link #LEAD_IN}, {@link #LEAD_OUT}, {@link #OVERCUT}); empty when Cut may run.
     */
    public java.util.Map<String, String> problems() {
        java.util.Map<String, String> out = new java.util.LinkedHashMap<>();
        if (drawing == null) {
            out.put(DRAWING, "Open the DXF drawing to cut.");
        }
        FieldProblems.number("Kerf (mm)", kerfMm, SettingRanges.Cutting.KERF).ifPresent(m -> out.put(KERF, m));
        FieldProblems.number("Lead-in (mm)", leadInMm, SettingRanges.Cutting.LEAD_IN)
                .ifPresent(m -> out.put(LEAD_IN, m));
        FieldProblems.number("Lead-out (mm)", leadOutMm, SettingRanges.Cutting.LEAD_OUT)
                .ifPresent(m -> out.put(LEAD_OUT, m));
        FieldProblems.number("Overcut (mm)", overcutMm, SettingRanges.Cutting.OVERCUT)
                .ifPresent(m -> out.put(OVERCUT, m));
        return out;
    }

    /** The settings of the typed fields; empty while {@link #problems()} is not. */
    public Optional<CuttingSettings> typedSettings() {
        if (!problems().isEmpty()) {
            return Optional.empty();
        }
        return Optional.of(new CuttingSettings(
                drawing,
                Double.parseDouble(kerfMm),
                process,
                Double.parseDouble(leadInMm),
                Double.parseDouble(leadOutMm),
                lead,
                toleranceMm,
                units,
                paperMode,
                post,
                compensation,
                outerDirection,
                holeDirection,
                Double.parseDouble(overcutMm),
                avoidCutParts,
                cutOrder));
    }

    /**
     * The settings as typed, checked.
     *
     * @throws CamInputException with the first problem of {@link #problems()}
     */
    public CuttingSettings settings() throws CamInputException {
        java.util.Map<String, String> p = problems();
        if (!p.isEmpty()) {
            throw new CamInputException("Cutting", p.values().iterator().next());
        }
        return typedSettings().orElseThrow();
    }

    public void setResult(CuttingService.Result r) {
        result = r;
        said = null;
    }

    public Optional<CuttingService.Result> result() {
        return Optional.ofNullable(result);
    }

    /**
     * What the plot shows on hover at p (mm): the contour not cut that passes within reachMm of p
     * (or holds p), named with its size, place and the reason it is not cut; empty elsewhere.
     */
    public Optional<String> notCutAt(Vec2 p, double reachMm) {
        if (result == null) {
            return Optional.empty();
        }
        CutPlan.NotCut best = null;
        double bestD = Double.POSITIVE_INFINITY;
        for (CutPlan.NotCut n : result.plan().notCut()) {
            double d = n.contour().distanceTo(p);
            if (d > reachMm && n.contour().contains(p, org.fresa.geom.Tolerance.DEFAULT)) {
                d = reachMm; // inside a small contour: still that one, unless an edge is nearer
            }
            if (d <= reachMm && d < bestD) {
                bestD = d;
                best = n;
            }
        }
        if (best == null) {
            return Optional.empty();
        }
        org.fresa.geom.Box2 b = best.contour().bounds();
        return Optional.of(String.format(
                java.util.Locale.ROOT,
                "%s (%.3f x %.3f mm at %.3f, %.3f) %s: not cut",
                best.label(),
                b.width(),
                b.height(),
                b.minX(),
                b.minY(),
                best.reason()));
    }

    /** Parts filled, holes, open chains in the warning style, cuts, leads, rapids and order numbers. */
    public PlotScene scene() {
        return result == null ? PlotScene.empty("Cutting") : sceneOf(result);
    }

    /** The plot of a result; touches no view-model state, so the tab builds it off the event thread. */
    public static PlotScene sceneOf(CuttingService.Result result) {
        CutPlan p = result.plan();
        List<Curve2> parts = new ArrayList<>();
        p.outers().forEach(c -> parts.addAll(c.curves()));
        p.holes().forEach(c -> parts.addAll(c.curves()));
        List<Curve2> holes = new ArrayList<>();
        p.holes().forEach(c -> holes.addAll(c.curves()));
        List<Curve2> open = new ArrayList<>();
        p.open().forEach(open::addAll);
        List<Curve2> cuts = new ArrayList<>();
        List<Curve2> leads = new ArrayList<>();
        List<Curve2> rapids = new ArrayList<>();
        for (List<Vec2> r : p.rapids()) {
            for (int i = 0; i + 1 < r.size(); i++) {
                if (!r.get(i).equals(r.get(i + 1))) {
                    rapids.add(new Segment2(r.get(i), r.get(i + 1)));
                }
            }
        }
        for (CutPath c : p.cuts()) {
            cuts.addAll(c.path().curves());
            leads.addAll(c.leadIn());
            leads.addAll(c.tail());
        }
        List<Curve2> uncut = new ArrayList<>();
        for (Contour c : p.uncut()) {
            uncut.addAll(c.curves());
        }
        PlotScene s = new PlotScene(result.drawing().source(), List.of(), List.of())
                .with(new PlotScene.Layer("parts", PlotScene.Style.PART, parts))
                .with(new PlotScene.Layer("holes", PlotScene.Style.HOLE, holes))
                .with(new PlotScene.Layer("open chains", PlotScene.Style.WARNING, open))
                .with(new PlotScene.Layer("not cut", PlotScene.Style.WARNING, uncut))
                .with(new PlotScene.Layer("rapids", PlotScene.Style.RAPID, rapids))
                .with(new PlotScene.Layer("cuts", PlotScene.Style.FEED, cuts))
                .with(new PlotScene.Layer("leads", PlotScene.Style.FINISH, leads));
        // pierce discs sized to the drawing, so they show at the whole-sheet zoom
        double size = s.bounds().map(b -> Math.max(b.width(), b.height())).orElse(100.0);
        double r = Math.max(1e-3, size / 300);
        List<Curve2> pierces = new ArrayList<>();
        for (CutPath c : p.cuts()) {
            pierces.add(Arc2.circle(c.pierce(), r, true));
        }
        s = s.with(new PlotScene.Layer("pierces", PlotScene.Style.PIERCE, pierces));
        // order numbers beside their pierce discs, not on them
        Vec2 beside = new Vec2(size / 90, size / 90);
        int k = 1;
        for (CutPath c : p.cuts()) {
            s = s.withLabel(c.pierce().plus(beside), Integer.toString(k++));
        }
        return s;
    }

    /**
     * What fresa cut and Job > Run say of a result, from {@link CuttingService}: the drawing's
     * warnings, the cut plan's and "nothing to cut" when no contour closes ({@link
     * CuttingService#problems}), and the program check's refusal of the program the job writes.
     */
    record Said(List<String> problems, Optional<String> refusal) {
        Said {
            problems = List.copyOf(problems);
        }

        /** All of it, the refusal last, as the run says it. */
        WarningList list() {
            List<String> all = new ArrayList<>(problems);
            refusal.ifPresent(all::add);
            return WarningList.of(all);
        }
    }

    /** What the run says of a result: posts and checks the whole program, so off the event thread. */
    static Said saidOf(CuttingService.Result result) {
        return new Said(
                CuttingService.problems(result), CuttingService.refusal(result, CuttingService.programFile(result)));
    }

    /** The result and what the run says of it ({@link #saidOf}), made together off the event thread. */
    void setResult(CuttingService.Result r, Said s) {
        result = r;
        said = s;
    }

    /** What the run says of the last result shown, all of it. */
    WarningList warnings() {
        return result == null ? WarningList.none() : said().list();
    }

    /**
     * Why a run of the last result fails (the tab says it beside Cut): the program check's refusal
     * of its program, or that there is nothing to cut; empty when the program is written.
     */
    Optional<String> refusal() {
        if (result == null) {
            return Optional.empty();
        }
        if (said().refusal().isPresent() || !result.plan().cuts().isEmpty()) {
            return said().refusal();
        }
        return Optional.of(said().problems().get(said().problems().size() - 1));
    }

    private Said said() {
        if (said == null) {
            said = saidOf(result);
        }
        return said;
    }

    /** Contours, pierces, cut and rapid lengths, the estimated time and the number of warnings. */
    public String totals() {
        return result == null ? "No drawing cut yet." : totalsOf(result, said());
    }

    /** The totals of a result (any thread), counting every line the run says of it, as the list under the plot does. */
    static String totalsOf(CuttingService.Result result, Said said) {
        var m = CuttingService.summary(result);
        List<String> warnings =
                said.list().all().stream().map(WarningList.Warning::text).toList();
        StringBuilder b = new StringBuilder(String.format(
                Locale.ROOT,
                "%d contours (%d outer, %d holes, %d open), %d pierces, cut %.1f mm, rapid %.1f mm (%d detours),"
                        + " about %.0f s; %d not cut, %d warnings",
                m.get("contours"),
                m.get("outer"),
                m.get("inner"),
                m.get("open"),
                m.get("pierces"),
                (Double) m.get("cut_length_mm"),
                (Double) m.get("rapid_length_mm"),
                (Long) m.get("rapid_detours"),
                (Double) m.get("estimated_time_s"),
                m.get("not_cut"),
                warnings.size()));
        if (!warnings.isEmpty()) {
            b.append(" (listed under the plot)");
        }
        return b.toString();
    }

    // ------------------------------------------------------------------ the cut list

    /**
     * One line of the cut list: the place in the order (1 the first), the contour, and where its
     * cut starts (the end of its lead-in), as the last cut shows them.
     */
    public record CutRow(int number, String contour, Vec2 startMm, boolean startAsked) {
        /** "12.500, 31.000": the start as the start field takes it. */
        public String start() {
            return String.format(Locale.ROOT, "%.3f, %.3f", startMm.x(), startMm.y());
        }
    }

    /** The planner's own order and start points (empty: the automatic ones). */
    public org.fresa.cutting.CutOrderOverride cutOrder() {
        return cutOrder;
    }

    /** The cuts of the last result in order, each with its start; empty before a cut. */
    public List<CutRow> cutList() {
        List<CutRow> rows = new ArrayList<>();
        if (result == null) {
            return rows;
        }
        java.util.Set<String> asked = new java.util.HashSet<>();
        for (org.fresa.cutting.CutOrderOverride.Cut c : cutOrder.cuts()) {
            if (c.startMm().isPresent()) {
                asked.add(c.contour());
            }
        }
        int k = 1;
        for (CutPath c : result.plan().cuts()) {
            rows.add(new CutRow(k++, c.label(), c.path().get(0).start(), asked.contains(c.label())));
        }
        return rows;
    }

    /**
     * The order of the last result as an override, keeping the start points the planner gave:
     * what an edit of the list starts from.
     */
    private Optional<org.fresa.cutting.CutOrderOverride> shownOrder() {
        if (result == null || result.plan().cuts().isEmpty()) {
            return Optional.empty();
        }
        java.util.Map<String, Vec2> starts = new java.util.HashMap<>();
        for (org.fresa.cutting.CutOrderOverride.Cut c : cutOrder.cuts()) {
            c.startMm().ifPresent(p -> starts.put(c.contour(), p));
        }
        List<org.fresa.cutting.CutOrderOverride.Cut> l = new ArrayList<>();
        for (org.fresa.cutting.CutOrderOverride.Cut c :
                org.fresa.cutting.CutOrderOverride.of(result.plan().cuts()).cuts()) {
            l.add(c.withStart(Optional.ofNullable(starts.get(c.contour()))));
        }
        return Optional.of(new org.fresa.cutting.CutOrderOverride(l));
    }

    /**
     * Moves cut {@code index} (0-based) one place up (delta -1) or down (+1) in the order.
     *
     * @return why the move is refused (a hole would come after its part, a part in a hole after
     *     the hole, or there is no place to go), or empty when the order took it
     */
    public Optional<String> moveCut(int index, int delta) {
        Optional<org.fresa.cutting.CutOrderOverride> now = shownOrder();
        if (now.isEmpty() || index < 0 || index >= now.get().cuts().size()) {
            return Optional.of("Cut the drawing first, then order its cuts.");
        }
        int to = index + delta;
        if (to < 0 || to >= now.get().cuts().size()) {
            return Optional.of(delta < 0 ? "The first cut cannot move up." : "The last cut cannot move down.");
        }
        List<CutPath> cuts = result.plan().cuts();
        // the cut jumped over: moving up puts the moved cut before it, moving down after it
        CutPath moved = cuts.get(index);
        CutPath other = cuts.get(to);
        CutPath outer = delta < 0 ? moved : other;
        CutPath inner = delta < 0 ? other : moved;
        if (inside(inner.part(), outer.part())) {
            return Optional.of(inner.label() + " lies inside " + outer.label() + ": it is cut before it, so nothing"
                    + " falls out uncut.");
        }
        cutOrder = now.get().moved(index, to);
        return Optional.empty();
    }

    /** True when the drawn contour a lies inside the drawn contour b. */
    private static boolean inside(Contour a, Contour b) {
        if (a == b) {
            return false;
        }
        org.fresa.geom.Box2 ab = a.bounds();
        org.fresa.geom.Box2 bb = b.bounds();
        if (!(ab.minX() >= bb.minX() && ab.maxX() <= bb.maxX() && ab.minY() >= bb.minY() && ab.maxY() <= bb.maxY())) {
            return false;
        }
        for (Curve2 c : a.curves()) {
            Vec2 p = c.pointAt(0.5);
            if (b.distanceTo(p) > 1e-6) {
                return b.contains(p, org.fresa.geom.Tolerance.DEFAULT);
            }
        }
        return false;
    }

    /**
     * Starts cut {@code index} (0-based) at the point of its path nearest p (the next cut puts it
     * there, its leads with it).
     */
    public Optional<String> setStart(int index, Vec2 p) {
        Optional<org.fresa.cutting.CutOrderOverride> now = shownOrder();
        if (now.isEmpty() || index < 0 || index >= now.get().cuts().size()) {
            return Optional.of("Cut the drawing first, then choose where a cut starts.");
        }
        if (!SettingRanges.Cutting.START_X.contains(p.x()) || !SettingRanges.Cutting.START_Y.contains(p.y())) {
            return Optional.of("Start: "
                    + SettingRanges.Cutting.START_X.problem(
                            SettingRanges.Cutting.START_X.contains(p.x()) ? p.y() : p.x()));
        }
        cutOrder = now.get().withStart(index, Optional.of(p));
        return Optional.empty();
    }

    /**
     * The start typed into the start field: "x, y" in mm (a comma, a semicolon or spaces between).
     *
     * @return the point, or empty when the text is not two numbers
     */
    public static Optional<Vec2> parseStart(String text) {
        String[] parts = text.trim().split("\\s*[,;]\\s*|\\s+");
        if (parts.length != 2) {
            return Optional.empty();
        }
        try {
            double x = Double.parseDouble(parts[0]);
            double y = Double.parseDouble(parts[1]);
            return Double.isFinite(x + y) ? Optional.of(Vec2.of(x, y)) : Optional.empty();
        } catch (NumberFormatException e) {
            return Optional.empty();
        }
    }

    /** The index (0-based) of the cut whose path passes nearest p, or -1 before a cut. */
    public int cutNearest(Vec2 p) {
        if (result == null) {
            return -1;
        }
        int best = -1;
        double bestD = Double.POSITIVE_INFINITY;
        List<CutPath> cuts = result.plan().cuts();
        for (int i = 0; i < cuts.size(); i++) {
            double d = cuts.get(i).path().distanceTo(p);
            if (d < bestD) {
                bestD = d;
                best = i;
            }
        }
        return best;
    }

    /** Back to the automatic order and start points. */
    public void resetOrder() {
        cutOrder = org.fresa.cutting.CutOrderOverride.NONE;
    }

    public String program() {
        return result == null ? "" : result.program();
    }
}
