package org.fresa.job;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.fresa.chart.PlotScene;
import org.fresa.chart.ToolpathChart;
import org.fresa.cutting.DrawingContours;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.grading.GradedSize;
import org.fresa.grading.Grader;
import org.fresa.grading.GradingPlan;
import org.fresa.grading.ShrinkageMode;
import org.fresa.grading.SizeRange;
import org.fresa.grading.SizeSystem;
import org.fresa.io.OutputFolder;
import org.fresa.model.CamInputException;
import org.fresa.model.ContourFile;
import org.fresa.model.ExactDecimal;
import org.fresa.model.FileChecks;
import org.fresa.model.Toolpath;
import org.fresa.post.NcPost;
import org.fresa.sole.Foot;
import org.fresa.sole.MouldBlock;
import org.fresa.sole.Similarity2;
import org.fresa.sole.SizeScale;
import org.fresa.sole.SoleTread;
import org.fresa.sole.TreadFigure;
import org.fresa.sole.TreadFigures;
import org.fresa.sole.TreadItem;
import org.fresa.sole.TreadPattern;
import org.fresa.sole.TreadProgram;
import org.fresa.sole.TreadTool;

/**
 * The sole mould task ({@code fresa sole}, {@code fresa run} with task sole): grades the outline
 * over the job's sizes with the grading module, places and clips the tread for each size and
 * foot, and writes per size {@code tread-NN-right.ngc}, {@code tread-NN-left.ngc},
 * {@code size-NN.csv} (the graded outline, x,y), {@code sole-NN.png} (both feet: outline and
 * tread) and, when the job names a cavity tool, {@code cavity-NN-right.ngc} and
 * {@code cavity-NN-left.ngc} pocketed by the pocket module (with the post's extension: {@code .apt}
 * for {@code post="apt"}); without one the outcome says so and the status is 1, with every tread
 * file written.
 */
public final class SoleService {

    private static final Tolerance TOL = Tolerance.DEFAULT;
    /** Most copies of a design's figures a pattern may make. */
    private static final int MAX_FIGURES = 10_000;

    private SoleService() {}

    /** The whole plan of a sole job, read and checked. */
    public record SolePlan(
            Grader grader,
            SoleTread tread,
            Map<String, TreadTool> tools,
            NcPost post,
            JobSettings.SoleSettings settings,
            java.util.Optional<MouldBlock> block) {}

    /**
     * Reads the outline, grades it and builds the tread.
     *
     * @throws CamInputException for a bad outline, size range, macro, tool or post
     */
    public static SolePlan plan(JobSettings.SoleSettings s, String source) throws CamInputException {
        List<Contour> outline = readOutline(s.outline());
        SizeSystem system;
        List<Double> sizes;
        ShrinkageMode mode;
        GradingPlan gp;
        try {
            system = s.system();
            sizes = SizeRange.parse(s.sizes(), system, false);
            mode = s.shrinkageMode();
            gp = GradingPlan.of(system, s.baseSize(), sizes).withShrinkage(s.shrinkage(), mode);
        } catch (IllegalArgumentException e) {
            throw new CamInputException(source, e.getMessage());
        }
        if (s.originMm().isPresent()) {
            gp = gp.withOrigin(s.originMm().get());
        }
        Grader grader = Grader.of(outline, gp, s.outline().toString());
        Vec2 axis = grader.frame().lengthAxis();
        if (Math.abs(axis.x()) > 1e-9 || axis.y() <= 0) {
            throw new CamInputException(
                    s.outline().toString(),
                    "the sole's length must run along +y (heel at the bottom),"
                            + " as tread figures are placed in that frame; found a length axis at "
                            + ExactDecimal.of(grader.frame().lengthAxisDeg()) + " degrees");
        }
        Map<String, TreadTool> tools = new LinkedHashMap<>();
        for (JobSettings.SoleTool t : s.tools()) {
            try {
                tools.put(
                        t.id(),
                        new TreadTool(
                                t.id(),
                                t.number(),
                                t.diameterMm(),
                                t.spindleRpm(),
                                t.feedMmPerMin(),
                                t.plungeFeedMmPerMin()));
            } catch (IllegalArgumentException e) {
                throw new CamInputException(source, e.getMessage());
            }
        }
        List<TreadItem> items = new ArrayList<>();
        for (JobSettings.SoleDesign d : s.designs()) {
            items.add(item(d, tools, source));
        }
        NcPost post = s.post().ncPost();
        SolePlan p =
                new SolePlan(grader, new SoleTread(items, s.marginMm()), tools, post, s, java.util.Optional.empty());
        if (s.block().isEmpty()) {
            return p;
        }
        MouldBlock block = block(s.block().get(), outline.get(0), grader.origin(), source);
        for (double size : sizes) {
            java.util.Optional<String> misfit = block.misfit(scale(p, grader.grade(size)));
            if (misfit.isPresent()) {
                throw new CamInputException(source, "the pair does not fit the mould block: " + misfit.get());
            }
        }
        return new SolePlan(grader, p.tread(), tools, post, s, java.util.Optional.of(block));
    }

    /**
     * The job's mould block, the pattern's extents measured on the base outline about its part
     * zero (the grading origin) where the job does not give the thesis's rounded CP, DPI, XTANP.
     */
    private static MouldBlock block(JobSettings.SoleBlock b, Contour outline, Vec2 zero, String source)
            throws CamInputException {
        MouldBlock.Pattern m = MouldBlock.Pattern.measured(outline.bounds(), zero);
        try {
            MouldBlock.Pattern pattern = new MouldBlock.Pattern(
                    b.cpMm().orElse(m.lengthMm()),
                    b.dpiMm().orElse(m.heelOverhangMm()),
                    b.xtanpMm().orElse(m.innerReachMm()));
            return new MouldBlock(b.dMm(), b.dlmMm(), b.eMm(), b.sMm(), b.cmMm(), pattern);
        } catch (IllegalArgumentException e) {
            throw new CamInputException(source, "mould block: " + e.getMessage());
        }
    }

    /** Where the part zero of a size and foot lies in the mould block, or empty without a block. */
    public static java.util.Optional<MouldBlock.PartZero> partZero(SolePlan p, GradedSize g, Foot foot) {
        return p.block().map(b -> b.partZero(scale(p, g), foot));
    }

    /**
     * A program of a size and foot, written about the part zero, placed where the block's
     * equations put that foot's part zero; unchanged without a block.
     */
    public static Toolpath placed(SolePlan p, GradedSize g, Foot foot, Toolpath partFrame) {
        return partZero(p, g, foot)
                .map(z -> z.placed(partFrame, p.grader().origin()))
                .orElse(partFrame);
    }

    /** The outline of a size and foot (the left one mirrored), placed in the block when there is one. */
    public static Contour outline(SolePlan p, GradedSize g, Foot foot) {
        Contour right = g.output().get(0);
        Contour c = foot == Foot.RIGHT
                ? right
                : SoleTread.mirrored(right, p.grader().origin().x());
        return partZero(p, g, foot).map(z -> z.placed(c, p.grader().origin())).orElse(c);
    }

    /** The block's edges y = S and S + CM across the pair (10 mm beyond it) and the mirror line x = DLM + E. */
    private static PlotScene.Layer blockLayer(MouldBlock b, SolePlan p, GradedSize g) {
        org.fresa.geom.Box2 span = outline(p, g, Foot.RIGHT)
                .bounds()
                .union(outline(p, g, Foot.LEFT).bounds());
        double x0 = span.minX() - 10;
        double x1 = span.maxX() + 10;
        double y0 = b.blockEdgeMm();
        double y1 = b.blockEdgeMm() + b.blockLengthMm();
        double m = b.mirrorLineMachineXMm();
        return new PlotScene.Layer(
                "block edges y = S, S + CM; mirror line x = DLM + E",
                PlotScene.Style.AUX,
                List.of(
                        org.fresa.geom.Segment2.of(x0, y0, x1, y0),
                        org.fresa.geom.Segment2.of(x0, y1, x1, y1),
                        org.fresa.geom.Segment2.of(m, y0, m, y1)));
    }

    /**
     * The pair in the mould block for one size: the block's lower and upper edges (y = S and
     * S + CM) across the pair, the mirror line x = DLM + E, and each foot's outline, tread and
     * cavity where the equations put it, in the machine frame. Empty when the job has no block.
     */
    public static java.util.Optional<PlotScene> pairScene(SolePlan p, GradedSize g) {
        if (p.block().isEmpty()) {
            return java.util.Optional.empty();
        }
        MouldBlock b = p.block().get();
        MouldBlock.PartZero right = partZero(p, g, Foot.RIGHT).orElseThrow();
        MouldBlock.PartZero left = partZero(p, g, Foot.LEFT).orElseThrow();
        PlotScene scene = PlotScene.empty(String.format(
                Locale.ROOT,
                "Size %s in the mould block: right ZP (%.3f, %.3f), left ZP (%.3f, %.3f)",
                g.name(),
                right.machineMm().x(),
                right.machineMm().y(),
                left.machineMm().x(),
                left.machineMm().y()));
        scene = scene.with(blockLayer(b, p, g));
        for (Foot foot : Foot.values()) {
            java.util.Optional<Toolpath> cavity;
            try {
                cavity = cavityProgram(p, g, foot);
            } catch (CamInputException e) {
                cavity = java.util.Optional.empty();
            }
            if (cavity.isPresent()) {
                scene = scene.with(new PlotScene.Layer(
                        foot.id() + " cavity",
                        PlotScene.Style.FINISH,
                        feeds(placed(p, g, foot, cavity.get()), Vec2.ZERO)));
            }
            scene = scene.withContour(foot.id() + " outline", PlotScene.Style.OUTLINE, outline(p, g, foot))
                    .with(new PlotScene.Layer(
                            foot.id() + " tread",
                            PlotScene.Style.FEED,
                            feeds(placed(p, g, foot, treadProgram(p, g, foot)), Vec2.ZERO)));
        }
        return java.util.Optional.of(scene);
    }

    private static List<Contour> readOutline(Path file) throws CamInputException {
        String name = file.toString();
        if (!name.toLowerCase(Locale.ROOT).endsWith(".contour")) {
            throw new CamInputException(name, "a sole outline must be a .contour file (lines and arcs)");
        }
        FileChecks.requireInput(file, "a sole outline (.contour)", FileChecks.MAX_TEXT_FILE_BYTES);
        try (var r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            return ContourFile.read(r, name);
        } catch (IOException e) {
            throw new CamInputException(name, "cannot read the outline (" + e.getMessage() + ")");
        }
    }

    static TreadItem item(JobSettings.SoleDesign d, Map<String, TreadTool> tools, String source)
            throws CamInputException {
        String where = source + ", design '" + d.name() + "'";
        if (!tools.containsKey(d.tool())) {
            throw new CamInputException(
                    where, "unknown tool '" + d.tool() + "', the job's tools are " + tools.keySet());
        }
        List<TreadFigure> lead = new ArrayList<>();
        for (JobSettings.SoleFigure f : d.lead()) {
            lead.add(TreadFigures.of(f.macro(), TreadFigures.parseParams(f.params(), where), where));
        }
        List<TreadFigure> figs = new ArrayList<>();
        for (JobSettings.SoleFigure f : d.figures()) {
            List<List<Curve2>> drawing =
                    f.drawing().isPresent() ? drawing(f.drawing().get()) : List.of();
            if (TreadFigures.needsDrawing(f.macro()) && f.drawing().isEmpty()) {
                throw new CamInputException(
                        where,
                        f.macro() + ": name the DXF drawing of its outlines in the figure's" + " file attribute");
            }
            figs.add(TreadFigures.of(f.macro(), TreadFigures.parseParams(f.params(), where), drawing, where));
        }
        try {
            TreadPattern pattern = switch (d.pattern()) {
                case SINGLE -> TreadPattern.single();
                case LINEAR -> TreadPattern.linear(d.dxMm(), d.dyMm(), positive(d.count(), "count"));
                case GRID ->
                    TreadPattern.grid(d.dxMm(), d.dyMm(), positive(d.count(), "count"), gridRows(d), d.rowShiftMm());
                case POLAR ->
                    TreadPattern.polar(
                            Vec2.of(d.centerXMm(), d.centerYMm()), d.stepDeg(), positive(d.count(), "count"));
                case COPIES -> copies(d.copies());
                case FILL ->
                    throw new IllegalArgumentException(
                            "pattern 'fill' is not supported here yet" + " (use grid: the outline clips it)");
            };
            TreadItem item = new TreadItem(d.name(), lead, figs, pattern, d.rule(), d.text(), d.tool());
            item.strokes(TOL);
            return item;
        } catch (IllegalArgumentException e) {
            throw new CamInputException(where, e.getMessage());
        }
    }

    /** The outlines of a logo's or text's DXF drawing: its chains of lines and arcs, closed or open. */
    private static List<List<Curve2>> drawing(Path file) throws CamInputException {
        try {
            org.fresa.cutting.Chainer.Chains chains = org.fresa.cutting.Chainer.chain(
                    org.fresa.dxf.DxfReader.read(file).curves(), DrawingContours.GAP_MM);
            List<List<Curve2>> out = new ArrayList<>();
            chains.closed().forEach(c -> out.add(c.curves()));
            out.addAll(chains.open());
            if (out.isEmpty()) {
                throw new CamInputException(file.toString(), "the drawing has no lines or arcs to engrave");
            }
            return out;
        } catch (IOException e) {
            throw new CamInputException(file.toString(), "cannot read the drawing (" + e.getMessage() + ")");
        }
    }

    /** The rows of a grid, when the grid has at most {@value #MAX_FIGURES} copies in all. */
    private static int gridRows(JobSettings.SoleDesign d) {
        long all = (long) positive(d.count(), "count") * positive(d.rows(), "rows");
        if (all > MAX_FIGURES) {
            throw new IllegalArgumentException(
                    "a grid of " + d.count() + " x " + d.rows() + " = " + all + " copies: at most " + MAX_FIGURES);
        }
        return d.rows();
    }

    private static int positive(int n, String what) {
        if (n < 1 || n > 10000) {
            throw new IllegalArgumentException(what + " must be from 1 to 10000: " + n);
        }
        return n;
    }

    private static TreadPattern copies(List<JobSettings.SoleCopy> cs) {
        if (cs.isEmpty()) {
            throw new IllegalArgumentException("pattern 'copies' needs copy elements");
        }
        List<Similarity2> l = new ArrayList<>();
        for (JobSettings.SoleCopy c : cs) {
            Similarity2 t = Similarity2.IDENTITY;
            if (c.mirrorXMm().isPresent()) {
                t = t.then(Similarity2.mirrorX(c.mirrorXMm().getAsDouble()));
            }
            if (c.mirrorYMm().isPresent()) {
                t = t.then(Similarity2.mirrorY(c.mirrorYMm().getAsDouble()));
            }
            t = t.then(Similarity2.rotation(Vec2.ZERO, c.rotateDeg()))
                    .then(Similarity2.translation(c.dxMm(), c.dyMm()));
            l.add(t);
        }
        return new TreadPattern.Copies(l);
    }

    /** The sizes the sole is made in, as its grading plan has them. */
    public static List<Double> sizes(SolePlan p) {
        return p.grader().plan().sizes();
    }

    /** The graded outline of one size (the grading of {@code fresa run}'s sole). */
    public static GradedSize graded(SolePlan p, double size) {
        return p.grader().grade(size);
    }

    /** The fixed point of the grading (mm): a left sole is the right one mirrored about its x. */
    public static Vec2 origin(SolePlan p) {
        return p.grader().origin();
    }

    /** The scale of one graded size as the tread needs it. */
    public static SizeScale scale(SolePlan p, GradedSize g) {
        return new SizeScale(
                g.name(),
                p.grader().origin(),
                g.factors().width(),
                g.factors().length(),
                1 + p.settings().shrinkage());
    }

    /** The tread program of a size and foot. */
    public static Toolpath treadProgram(SolePlan p, GradedSize g, Foot foot) {
        SizeScale sc = scale(p, g);
        List<SoleTread.ToolGrooves> grooves = p.tread()
                .grooves(sc, foot, g.output().get(0), id -> p.tools().get(id).diameterMm() / 2, TOL);
        return TreadProgram.toolpath(
                grooves, p.tools(), p.settings().treadDepthMm(), p.settings().clearanceMm());
    }

    /**
     * The cavity program of a size and foot: the graded outline (mirrored for the left foot)
     * pocketed by the pocket module ({@link org.fresa.pocket.RegionPocket}) with the cavity
     * tool's real diameter: finishing pass at R, roughing offsets from R + 0.5 mm (the thesis's
     * 0.5 mm finishing allowance at the mouth, §6.6.2.3) inwards at 60 % stepover, from the top
     * face z = 0 to z = -cavityDepth in steps of at most the cavity depth. Climb milling is chosen
     * after the mirror so both feet are cut in the same sense (the thesis's MAC3/MAC4 against
     * MAC5/MAC6). Empty when the job names no cavity tool.
     *
     * @throws CamInputException when the cavity tool is unknown or too large for the outline
     */
    public static java.util.Optional<Toolpath> cavityProgram(SolePlan p, GradedSize g, Foot foot)
            throws CamInputException {
        JobSettings.SoleSettings s = p.settings();
        if (s.cavityTool().isEmpty()) {
            return java.util.Optional.empty();
        }
        TreadTool t = p.tools().get(s.cavityTool());
        if (t == null) {
            throw new CamInputException(
                    "sole",
                    "unknown cavity tool '" + s.cavityTool() + "', the job's tools are "
                            + p.tools().keySet());
        }
        java.util.Optional<org.fresa.sole.CavityToolRule.Violation> tight =
                org.fresa.sole.CavityToolRule.check(g.output().get(0), t.diameterMm());
        if (tight.isPresent()) {
            throw new CamInputException(
                    "sole", "size " + g.name() + ": " + tight.get().sentence());
        }
        Contour outline = foot == Foot.RIGHT
                ? g.output().get(0)
                : SoleTread.mirrored(g.output().get(0), p.grader().origin().x());
        try {
            org.fresa.pocket.PocketTechnology tech = new org.fresa.pocket.PocketTechnology(
                    t.diameterMm(),
                    0.6,
                    Math.min(0.5, 0.5 / t.diameterMm()),
                    0,
                    -s.cavityDepthMm(),
                    s.cavityDepthMm(),
                    t.spindleRpm(),
                    t.feedMmPerMin(),
                    t.feedMmPerMin());
            // the region engine: the same offsets whatever the outline's element count, climb by
            // orientation (outline counter-clockwise), so the mirrored left foot is climb-milled too
            org.fresa.pocket.RegionPocket.Plan plan =
                    org.fresa.pocket.RegionPocket.plan(outline, List.of(), tech, true);
            return java.util.Optional.of(plan.toolpath());
        } catch (org.fresa.pocket.ToolTooLargeException e) {
            throw new CamInputException(
                    "sole", "size " + g.name() + ": the cavity tool is too large: " + e.getMessage());
        } catch (IllegalArgumentException e) {
            throw new CamInputException("sole", "cavity: " + e.getMessage());
        }
    }

    /** The job task. */
    public static TaskOutcome run(Job job, OutputFolder out, ProgressMonitor progress)
            throws CamInputException, IOException {
        JobSettings.SoleSettings s = JobRunner.require(job.sole(), "sole", job);
        SolePlan p = plan(s, job.name());
        out.create();
        List<Double> sizes = p.grader().plan().sizes();
        List<Object> perSize = new ArrayList<>();
        List<String> cavityProblems = new ArrayList<>();
        int k = 0;
        for (double size : sizes) {
            if (progress.isCancelled()) {
                break;
            }
            GradedSize g = p.grader().grade(size);
            progress.progress((double) k++ / sizes.size(), "size " + g.name());
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("size", g.name());
            m.put("width_factor", g.factors().width());
            m.put("length_factor", g.factors().length());
            m.put("length_mm", g.lengthMm());
            m.put("width_mm", g.widthMm());
            PlotScene scene = PlotScene.empty("Sole " + g.name()
                    + (p.block().isPresent() ? " (left, right) in the mould block" : " (right, left)"));
            Contour right = g.output().get(0);
            double shift = right.bounds().width() + 30;
            for (Foot foot : Foot.values()) {
                Toolpath tp = placed(p, g, foot, treadProgram(p, g, foot));
                java.util.Optional<MouldBlock.PartZero> zp = partZero(p, g, foot);
                if (zp.isPresent()) {
                    m.put(
                            foot.id() + "_part_zero_mm",
                            List.of(
                                    zp.get().machineMm().x(),
                                    zp.get().machineMm().y()));
                }
                String name = "tread-" + g.name() + "-" + foot.id();
                String ext = "." + p.post().fileExtension();
                writeChecked(out, name + ext, tp, p, ProgramChecks.soleTread(s), cavityProblems);
                m.put(foot.id() + "_moves", tp.moveCount());
                java.util.Optional<Toolpath> cavity;
                try {
                    cavity = cavityProgram(p, g, foot);
                } catch (CamInputException e) {
                    // the tread is still worth writing: report the cavity and carry on
                    cavityProblems.add("cavity-" + g.name() + "-" + foot.id() + ext + " not written: " + e.problem());
                    cavity = java.util.Optional.empty();
                }
                if (cavity.isPresent()) {
                    String cname = "cavity-" + g.name() + "-" + foot.id();
                    Toolpath ct = placed(p, g, foot, cavity.get());
                    writeChecked(out, cname + ext, ct, p, ProgramChecks.soleCavity(s), cavityProblems);
                    m.put(foot.id() + "_cavity_moves", ct.moveCount());
                }
                Contour outline = outline(p, g, foot);
                // without a block the left foot is drawn beside the right one; with one, where it is cut
                Vec2 dx = Vec2.of(foot == Foot.RIGHT || p.block().isPresent() ? 0 : shift, 0);
                if (cavity.isPresent()) {
                    scene = scene.with(new PlotScene.Layer(
                            foot.id() + " cavity",
                            PlotScene.Style.FINISH,
                            feeds(placed(p, g, foot, cavity.get()), dx)));
                }
                scene = scene.withContour(foot.id() + " outline", PlotScene.Style.OUTLINE, outline.translated(dx))
                        .with(new PlotScene.Layer(foot.id() + " tread", PlotScene.Style.FEED, feeds(tp, dx)));
            }
            out.writeString("size-" + g.name() + ".csv", csv(g));
            if (p.block().isPresent()) {
                scene = scene.with(blockLayer(p.block().get(), p, g));
            }
            PlotScene sc = scene;
            out.write("sole-" + g.name() + ".png", os -> ToolpathChart.writePng(sc, 1000, 1100, os));
            perSize.add(m);
        }
        progress.progress(1, "done");
        Map<String, Object> summary = new LinkedHashMap<>();
        summary.put(
                "origin", List.of(p.grader().origin().x(), p.grader().origin().y()));
        summary.put("post", p.post().name());
        p.block().ifPresent(b -> {
            Map<String, Object> bm = new LinkedHashMap<>();
            bm.put("d_mm", b.pairGapMm());
            bm.put("dlm_mm", b.mirrorStationMm());
            bm.put("e_mm", b.mirrorOffsetMm());
            bm.put("s_mm", b.blockEdgeMm());
            bm.put("cm_mm", b.blockLengthMm());
            bm.put("cp_mm", b.pattern().lengthMm());
            bm.put("dpi_mm", b.pattern().heelOverhangMm());
            bm.put("xtanp_mm", b.pattern().innerReachMm());
            bm.put("mirror_line_x_mm", b.mirrorLineMachineXMm());
            summary.put("block", bm);
        });
        summary.put("designs", s.designs().size());
        summary.put("sizes", perSize);
        boolean cavity = !s.cavityTool().isEmpty();
        summary.put("cavity", cavity ? "pocketed with tool " + s.cavityTool() : "no cavity tool named");
        List<String> problems = new ArrayList<>(cavityProblems);
        if (!cavity) {
            problems.add("cavity programs are not written: the job names no cavityTool;"
                    + " the tread programs, outlines and sheets are written");
        }
        return new TaskOutcome(problems.isEmpty() ? 0 : 1, problems, summary, out.written());
    }

    /** Writes the program when it passes the program check; otherwise says why it is not written. */
    private static void writeChecked(
            OutputFolder out,
            String file,
            Toolpath tp,
            SolePlan p,
            org.fresa.check.Limits limits,
            List<String> problems)
            throws IOException {
        java.io.StringWriter w = new java.io.StringWriter();
        p.post().write(tp, file.replaceFirst("\\.[a-z]+$", ""), w);
        try {
            ProgramChecks.require(
                    file, w.toString(), ProgramChecks.dialect(p.post().name()), limits);
            out.writeString(file, w.toString());
        } catch (ProgramChecks.RefusedProgram e) {
            problems.add(e.getMessage());
        }
    }

    private static List<Curve2> feeds(Toolpath tp, Vec2 dx) {
        PlotScene one = PlotScene.empty("").withToolpath(tp);
        List<Curve2> out = new ArrayList<>();
        for (PlotScene.Layer l : one.layers()) {
            if (l.style() == PlotScene.Style.FEED) {
                for (Curve2 c : l.curves()) {
                    out.add(c.translated(dx));
                }
            }
        }
        return out;
    }

    private static String csv(GradedSize g) {
        StringBuilder sb = new StringBuilder("x,y\n");
        for (Vec2 v : g.exact().get(0).points(0.5)) {
            sb.append(ExactDecimal.of(v.x()))
                    .append(',')
                    .append(ExactDecimal.of(v.y()))
                    .append('\n');
        }
        return sb.toString();
    }
}
