package org.fresa.job;

import java.io.IOException;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.chart.GradingChart;
import org.fresa.cutting.DrawingContours;
import org.fresa.dxf.DxfWriter;
import org.fresa.geom.Contour;
import org.fresa.geom.Vec2;
import org.fresa.grading.ArcMode;
import org.fresa.grading.Coordination;
import org.fresa.grading.GradedOutline;
import org.fresa.grading.GradedSize;
import org.fresa.grading.Grader;
import org.fresa.grading.GradingPlan;
import org.fresa.grading.GradingResult;
import org.fresa.grading.ShrinkageMode;
import org.fresa.grading.SizeRange;
import org.fresa.grading.SizeSystem;
import org.fresa.io.OutputFolder;
import org.fresa.job.JobSettings.GradingSettings;
import org.fresa.model.CamInputException;
import org.fresa.model.ContourFile;
import org.fresa.model.ExactDecimal;
import org.fresa.model.FileChecks;

/**
 * The grading task ({@code fresa grade}, {@code fresa run} with task grade, the Grading tab):
 * grades a base outline over a size range and writes, per size, {@code size-N.dxf} (lines and
 * arcs) and {@code size-N.csv}, then {@code grading.csv} and {@code grading.png}.
 *
 * <p>{@code size-N.csv} has columns {@code x,y} (mm): points on the <em>exact</em> graded sole
 * outline (the affine image of the base, whose arcs are elliptic), in order of travel from the
 * first element's start, the closing point not repeated; every corner is a point, and elliptic
 * arcs are sampled so the polygon is within 0.001 mm of the outline. The DXF holds the outline as
 * lines and circular arcs (biarcs within 0.005 mm of the exact outline by default), and further
 * contours of the input (holes, marks) graded with the same map.
 *
 * <p>{@code grading.csv}: one row per size with {@code size, length_mm, width_mm, alfa, beta,
 * length_factor, width_factor, heel_size, max_deviation_mm}; alfa and beta are the thesis's
 * factors before shrinkage, the two factors after it are what was applied, lengths and widths are
 * measured along and across the length axis, max_deviation_mm is how far the DXF departs from
 * the exact outline (empty under heel coordination).
 */
public final class GradingService {

    /** The chord tolerance of the CSV points, mm. */
    public static final double CSV_CHORD_MM = 0.001;

    private static final String SETTINGS = "grading settings";

    /**
     * Choices beyond the job file's grading settings (command-line options of {@code fresa grade}).
     *
     * @param arcMode biarcs (default) or the thesis's 3-point arcs
     * @param lengthAxisDeg the length axis, or empty to find it
     * @param coordination one heel per group of sizes, or empty
     */
    public record Options(ArcMode arcMode, OptionalDouble lengthAxisDeg, Optional<Coordination> coordination) {
        public static final Options DEFAULT = new Options(ArcMode.BIARC, OptionalDouble.empty(), Optional.empty());
    }

    private GradingService() {}

    /** Reads the settings' outline and grades it with the default options. */
    public static TaskOutcome run(GradingSettings s, OutputFolder out, ProgressMonitor progress)
            throws CamInputException, IOException {
        return run(s, Options.DEFAULT, out, progress);
    }

    /** Reads the settings' outline and grades it. */
    public static TaskOutcome run(GradingSettings s, Options o, OutputFolder out, ProgressMonitor progress)
            throws CamInputException, IOException {
        String name = s.outline().getFileName().toString();
        return write(readOutline(s.outline()), name, s, o, out, progress);
    }

    /**
     * The contours of a {@code .contour} file, or the closed contours of a DXF drawing (chained
     * at 0.001 mm, largest first, so the outline comes before any inner contour).
     */
    public static List<Contour> readOutline(Path file) throws CamInputException, IOException {
        String name = file.getFileName().toString();
        if (name.toLowerCase(Locale.ROOT).endsWith(".dxf")) {
            List<Contour> closed = DrawingContours.read(file).closed();
            if (closed.isEmpty()) {
                throw new CamInputException(
                        name,
                        "no closed outline in the drawing (expected lines, arcs or "
                                + "polylines that form a closed contour)");
            }
            return closed;
        }
        FileChecks.requireInput(file, "a sole outline (.dxf or .contour)", FileChecks.MAX_TEXT_FILE_BYTES);
        try (Reader r = Files.newBufferedReader(file)) {
            return ContourFile.read(r, file.getFileName().toString());
        }
    }

    /**
     * The grading plan of the settings.
     *
     * @throws CamInputException for a system, range, step, origin or shrinkage that cannot be used
     */
    public static GradingPlan plan(GradingSettings s, Options o) throws CamInputException {
        try {
            SizeSystem system = s.system();
            List<Double> sizes = SizeRange.parse(s.sizes(), system, s.halfSizes());
            double vc = s.lengthStepMm().orElse(system.lengthStepMm());
            double vl = s.widthStepMm().orElse(system.widthStepMm());
            if (!(vc > 0) || !(vl >= 0) || !Double.isFinite(vc) || !Double.isFinite(vl)) {
                throw new IllegalArgumentException("steps must be > 0 mm: length " + vc + ", width " + vl);
            }
            if (!(s.shrinkage() >= 0) || !(s.shrinkage() < 0.5)) {
                throw new IllegalArgumentException(
                        "shrinkage must be a fraction in [0, 0.5), e.g. 0.02: " + s.shrinkage());
            }
            if (!Double.isFinite(s.baseSize())) {
                throw new IllegalArgumentException("base size must be a number");
            }
            ShrinkageMode mode = s.shrinkageMode();
            // the command line's coordination before the job's
            Optional<Coordination> co = o.coordination().isPresent()
                    ? o.coordination()
                    : s.coordination().map(GradingService::coordination);
            return new GradingPlan(
                    system,
                    s.baseSize(),
                    sizes,
                    vc,
                    vl,
                    s.originMm(),
                    o.lengthAxisDeg(),
                    s.shrinkage(),
                    mode,
                    o.arcMode(),
                    GradingPlan.DEFAULT_ARC_TOLERANCE_MM,
                    co);
        } catch (IllegalArgumentException e) {
            throw new CamInputException(SETTINGS, e.getMessage());
        }
    }

    /** The job's heel coordination as the grading module takes it. */
    static Coordination coordination(JobSettings.HeelCoordination h) {
        if (h.boundaryMm().isPresent() && !h.heelElements().isBlank()) {
            throw new IllegalArgumentException("heel coordination: give heelElements or coordinationMm, not both");
        }
        if (h.boundaryMm().isPresent()) {
            return new Coordination(h.boundaryMm().getAsDouble(), h.groupSize());
        }
        return Coordination.ofHeelElements(Coordination.parseElements(h.heelElements()), h.groupSize());
    }

    /**
     * What the grading says of each setting it refuses, in its own words, by setting:
     * {@code system}, {@code sizes}, {@code baseSize}, {@code lengthStep}, {@code widthStep},
     * {@code shrinkage}, {@code shrinkageMode}, or {@code settings} for a refusal of their
     * combination; empty when {@link #plan} accepts them. The GUI marks the field of each.
     */
    public static Map<String, String> refusals(GradingSettings s, Options o) {
        Map<String, String> out = new LinkedHashMap<>();
        SizeSystem system = s.system();
        try {
            SizeRange.parse(s.sizes(), system, s.halfSizes());
        } catch (IllegalArgumentException e) {
            out.put("sizes", e.getMessage());
        }
        try {
            system.checkSize(s.baseSize(), "base size");
        } catch (IllegalArgumentException e) {
            out.put("baseSize", e.getMessage());
        }
        double vc = s.lengthStepMm().orElse(system.lengthStepMm());
        double vl = s.widthStepMm().orElse(system.widthStepMm());
        if (!(vc > 0) || !Double.isFinite(vc)) {
            out.put("lengthStep", "the length step must be above 0 mm, found " + ExactDecimal.of(vc));
        }
        if (!(vl >= 0) || !Double.isFinite(vl)) {
            out.put("widthStep", "the width step must be at least 0 mm, found " + ExactDecimal.of(vl));
        }
        if (!(s.shrinkage() >= 0) || !(s.shrinkage() < 0.5)) {
            out.put(
                    "shrinkage",
                    "shrinkage must be a fraction in [0, 0.5), e.g. 0.02, found " + ExactDecimal.of(s.shrinkage()));
        }
        if (out.isEmpty()) {
            try {
                plan(s, o);
            } catch (CamInputException e) {
                out.put("settings", e.getMessage());
            }
        }
        return out;
    }

    /** Grades the outline (headless, no files), for the GUI's preview. */
    public static GradingResult grade(List<Contour> outline, String source, GradingSettings s, Options o)
            throws CamInputException {
        return Grader.of(outline, plan(s, o), source).gradeAll();
    }

    /** Grades the outline and writes the files. */
    public static TaskOutcome write(
            List<Contour> outline,
            String source,
            GradingSettings s,
            Options o,
            OutputFolder out,
            ProgressMonitor progress)
            throws CamInputException, IOException {
        GradingPlan plan = plan(s, o);
        Grader grader = Grader.of(outline, plan, source);
        out.create();
        List<GradedSize> done = new ArrayList<>();
        int n = plan.sizes().size();
        for (int i = 0; i < n; i++) {
            progress.checkCancelled();
            double size = plan.sizes().get(i);
            progress.progress((double) i / (n + 1), "size " + ExactDecimal.of(size));
            GradedSize g = grader.grade(size);
            out.writeString("size-" + g.name() + ".dxf", DxfWriter.write(g.output(), "OUTLINE"));
            out.writeString("size-" + g.name() + ".csv", csv(g.exact().get(0)));
            done.add(g);
        }
        GradingResult result = new GradingResult(grader.frame(), grader.rule(), done);
        out.writeString("grading.csv", table(result));
        progress.progress((double) n / (n + 1), "plot");
        out.write(
                "grading.png",
                os -> GradingChart.writePng(
                        "Graded sizes, " + source,
                        sizeOutlines(result),
                        result.frame().lengthAxis(),
                        1200,
                        1400,
                        os));
        return new TaskOutcome(0, List.of(), summary(result, source, plan), out.written());
    }

    /** The outlines of every size for {@link GradingChart}, the base size marked. */
    public static List<GradingChart.SizeOutline> sizeOutlines(GradingResult r) {
        List<GradingChart.SizeOutline> l = new ArrayList<>();
        for (GradedSize g : r.sizes()) {
            l.add(new GradingChart.SizeOutline(
                    g.name(), g.output(), g.size() == r.rule().baseSize()));
        }
        return l;
    }

    /** The points of size-N.csv (see the class comment). */
    static String csv(GradedOutline outline) {
        StringBuilder sb = new StringBuilder("x,y\n");
        for (Vec2 p : outline.points(CSV_CHORD_MM)) {
            sb.append(ExactDecimal.of(p.x() + 0.0))
                    .append(',')
                    .append(ExactDecimal.of(p.y() + 0.0))
                    .append('\n');
        }
        return sb.toString();
    }

    /** grading.csv (see the class comment). */
    static String table(GradingResult r) {
        StringBuilder sb = new StringBuilder(
                "size,length_mm,width_mm,alfa,beta,length_factor,width_factor,heel_size,max_deviation_mm\n");
        for (GradedSize g : r.sizes()) {
            sb.append(String.join(
                            ",",
                            g.name(),
                            ExactDecimal.of(g.lengthMm()),
                            ExactDecimal.of(g.widthMm()),
                            ExactDecimal.of(g.factors().alfa()),
                            ExactDecimal.of(g.factors().beta()),
                            ExactDecimal.of(g.factors().length()),
                            ExactDecimal.of(g.factors().width()),
                            exactOrEmpty(g.heelSize()),
                            exactOrEmpty(g.maxDeviationMm())))
                    .append('\n');
        }
        return sb.toString();
    }

    /** A column that a size may leave empty (no heel coordination, no deviation measured). */
    private static String exactOrEmpty(java.util.OptionalDouble v) {
        return v.isPresent() ? ExactDecimal.of(v.getAsDouble()) : "";
    }

    private static Map<String, Object> summary(GradingResult r, String source, GradingPlan plan) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("outline", source);
        m.put("system", plan.system().id());
        m.put("base_size", plan.baseSize());
        m.put("length_step_mm", plan.lengthStepMm());
        m.put("width_step_mm", plan.widthStepMm());
        m.put("base_length_mm", r.rule().baseLengthMm());
        m.put("base_width_mm", r.rule().baseWidthMm());
        m.put("origin", List.of(r.frame().origin().x(), r.frame().origin().y()));
        m.put("length_axis_deg", r.frame().lengthAxisDeg());
        m.put("shrinkage", plan.shrinkage());
        m.put("shrinkage_mode", plan.shrinkageMode().id());
        m.put(
                "arc_mode",
                plan.coordination().isPresent()
                        ? ArcMode.THREE_POINT.id()
                        : plan.arcMode().id());
        m.put("coordination", plan.coordination().isPresent());
        double worst = 0;
        List<Object> sizes = new ArrayList<>();
        for (GradedSize g : r.sizes()) {
            Map<String, Object> s = new LinkedHashMap<>();
            s.put("size", g.size());
            s.put("name", g.name());
            s.put("length_mm", g.lengthMm());
            s.put("width_mm", g.widthMm());
            s.put("alfa", g.factors().alfa());
            s.put("beta", g.factors().beta());
            s.put("length_factor", g.factors().length());
            s.put("width_factor", g.factors().width());
            if (g.heelSize().isPresent()) {
                s.put("heel_size", g.heelSize().getAsDouble());
            }
            s.put("elements", g.output().get(0).size());
            if (g.maxDeviationMm().isPresent()) {
                s.put("max_deviation_mm", g.maxDeviationMm().getAsDouble());
                worst = Math.max(worst, g.maxDeviationMm().getAsDouble());
            }
            sizes.add(s);
        }
        m.put("sizes", sizes);
        if (plan.coordination().isEmpty()) {
            m.put("max_deviation_mm", worst);
        }
        return m;
    }
}
