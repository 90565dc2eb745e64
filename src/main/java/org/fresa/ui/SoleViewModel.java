package org.fresa.ui;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fresa.chart.PlotScene;
import org.fresa.geom.Curve2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.grading.GradedSize;
import org.fresa.job.Job;
import org.fresa.job.SoleService;
import org.fresa.model.CamInputException;
import org.fresa.model.ExactDecimal;
import org.fresa.model.Toolpath;
import org.fresa.sole.FigurePath;
import org.fresa.sole.Foot;
import org.fresa.sole.SoleTread;
import org.fresa.sole.Stroke;
import org.fresa.sole.TreadFigure;
import org.fresa.sole.TreadFigures;

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
        return sb.toString();
    }

    /** The selected macro's tool-centre path for its thesis call (continuous ones from PRIM's point). */
    public PlotScene preview() {
        try {
            TreadFigure f = TreadFigures.of(macro, TreadFigures.parseParams(TreadFigures.thesisExample(macro), macro),
                    macro);
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
        if (job.sole().isEmpty()) {
            problem = "The job has no sole settings (open a sole job, e.g. samples/jobs/sole-men40.xml).";
            return;
        }
        try {
            SoleService.SolePlan p = SoleService.plan(job.sole().get(), job.name());
            plan = Optional.of(p);
            sizes = p.grader().plan().sizes().stream().map(ExactDecimal::of).toList();
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
        GradedSize g = p.grader().grade(Double.parseDouble(size));
        Toolpath tp = SoleService.treadProgram(p, g, foot);
        var outline = foot == Foot.RIGHT ? g.output().get(0)
                : SoleTread.mirrored(g.output().get(0), p.grader().origin().x());
        return PlotScene.empty("Sole " + g.name() + ", " + foot.id() + " foot")
                .withContour("outline", PlotScene.Style.OUTLINE, outline).withToolpath(tp);
    }
}
