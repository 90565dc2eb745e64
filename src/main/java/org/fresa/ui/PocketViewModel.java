package org.fresa.ui;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.fresa.chart.PlotScene;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.job.PocketService;
import org.fresa.model.CamInputException;
import org.fresa.pocket.LoopState;
import org.fresa.pocket.PocketElement;
import org.fresa.pocket.PocketPlan;
import org.fresa.pocket.PocketToolpath;
import org.fresa.pocket.RecognitionNode;
import org.fresa.pocket.RegionPocket;
import org.fresa.pocket.ToolTooLargeException;

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
            return new Result(scene, report, nc, org.fresa.check.ProgramCheck.of(nc,
                    org.fresa.job.ProgramChecks.dialect(settings.post()), org.fresa.job.ProgramChecks.pocket(settings))
                    .failure());
        }
    }

    private PocketSettings settings = new PocketSettings(Path.of("samples/pocket/cavity01.dad"), 6, 0.62, 0.13, 30, 27, 3,
            3200, 290, 100, "7m-compat");
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

    /** Recomputes from the settings; on bad input keeps the message and clears the result. */
    /** The outcome of one computation: a result or the reason there is none. */
    public record Outcome(Optional<Result> result, Optional<String> error) {
    }

    /** Computes with the current settings (the tab does it in the background with {@link #outcome}). */
    public void compute() {
        show(outcome(settings));
    }

    /** Takes an outcome computed for the current settings. */
    public void show(Outcome o) {
        result = o.result();
        error = o.error();
    }

    /** Plans the pocket of these settings: touches no view-model state, so any thread may call it. */
    public static Outcome outcome(PocketSettings settings) {
        try {
            String name = settings.contour().getFileName().toString();
            if (!name.toLowerCase(Locale.ROOT).endsWith(".dad")) {
                List<Contour> contours = PocketService.readContours(settings.contour());
                if (contours.size() > 1) {
                    RegionPocket.Plan rp = PocketService.regionPlan(settings, contours);
                    return new Outcome(Optional.of(Result.checked(regionScene(contours, rp), regionReport(contours, rp),
                            PocketService.regionProgram(rp, settings.post(), name), settings)), Optional.empty());
                }
            }
            PocketPlan plan = PocketService.plan(settings);
            String nc = PocketService.program(plan, settings.post(), settings.contour().getFileName().toString(),
                    settings.climb(), settings.entryRule());
            return new Outcome(Optional.of(Result.checked(scene(plan, settings), report(plan), nc, settings)),
                    Optional.empty());
        } catch (CamInputException | IOException | ToolTooLargeException | IllegalArgumentException e) {
            return new Outcome(Optional.empty(), Optional.of(String.valueOf(e.getMessage())));
        }
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
        sb.append(String.format(Locale.ROOT, "%d island(s): Fresa's region engine (the thesis's tree has none)%n",
                contours.size() - 1));
        for (RegionPocket.Level l : plan.levels()) {
            long faces = l.loops().stream().filter(Contour::isCcw).count();
            sb.append(String.format(Locale.ROOT, "offset %8.3f  %d sub-area(s), %d loop(s)%n", l.offsetMm(), faces,
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
        PlotScene scene = PlotScene.empty("pocket")
                .with(new PlotScene.Layer("contour", PlotScene.Style.OUTLINE, curves(ref, 0)));
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
            sb.append(indent).append("SC").append(n.id()).append(' ')
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
}
