package org.fresa.grading;

import java.util.ArrayList;
import java.util.List;
import java.util.OptionalDouble;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Vec2;
import org.fresa.model.CamInputException;
import org.fresa.model.ExactDecimal;

/**
 * Grades a base outline over sizes with the thesis's pantograph: finds the frame, measures the
 * pattern's length CP and width LP in it (exact extents along and across the length axis, the
 * industry's tangent-line width), and maps every size.
 *
 * <p>The first contour is the sole outline; further contours (holes, marks) are graded with the
 * same map but do not enter CP, LP or the frame.
 */
public final class Grader {

    /** Largest outline accepted (mm across): a sole is far smaller; larger is usually a unit mistake. */
    static final double MAX_OUTLINE_MM = 5000;
    /** Most elements an outline may have; the frame detection compares sample points pairwise. */
    static final int MAX_ELEMENTS = 20_000;

    private final List<Contour> outlines;
    private final GradingPlan plan;
    private final GradingFrame frame;
    private final GradingRule rule;

    private Grader(List<Contour> outlines, GradingPlan plan, GradingFrame frame, GradingRule rule) {
        this.outlines = outlines;
        this.plan = plan;
        this.frame = frame;
        this.rule = rule;
    }

    /**
     * Prepares the grading of the outlines.
     *
     * @param source the outline's name for messages
     * @throws CamInputException when there is no outline, no heel arc for the origin, or a size so
     *     small that a factor is not positive
     */
    public static Grader of(List<Contour> outlines, GradingPlan plan, String source) throws CamInputException {
        if (outlines.isEmpty()) {
            throw new CamInputException(source, "no outline to grade");
        }
        Contour outer = outlines.get(0);
        if (outer.size() > MAX_ELEMENTS) {
            throw new CamInputException(
                    source,
                    "the outline has " + outer.size() + " elements; grading takes at most " + MAX_ELEMENTS
                            + " (simplify the drawing)");
        }
        Box2 box = outer.bounds();
        if (Math.max(box.width(), box.height()) > MAX_OUTLINE_MM) {
            throw new CamInputException(
                    source,
                    "the outline is " + ExactDecimal.of(Math.max(box.width(), box.height()))
                            + " mm across; a sole outline is at most " + ExactDecimal.of(MAX_OUTLINE_MM)
                            + " mm (wrong units?)");
        }
        if (plan.coordination().isPresent()) {
            java.util.Optional<String> misfit = plan.coordination().get().misfit(EscomPattern.ofContour(outer));
            if (misfit.isPresent()) {
                throw new CamInputException(source, "coordination: " + misfit.get());
            }
        }
        GradingFrame frame = OutlineFrames.detect(outer, plan.origin(), plan.lengthAxisDeg(), source);
        double cp = Extents.sizeAlong(outer, frame.lengthAxis());
        double lp = Extents.sizeAlong(outer, frame.widthAxis());
        GradingRule rule;
        try {
            rule = new GradingRule(
                    plan.system(),
                    plan.baseSize(),
                    plan.lengthStepMm(),
                    plan.widthStepMm(),
                    cp,
                    lp,
                    plan.shrinkage(),
                    plan.shrinkageMode());
            for (double s : plan.sizes()) {
                rule.factors(s);
            }
        } catch (IllegalArgumentException e) {
            throw new CamInputException(source, e.getMessage());
        }
        return new Grader(List.copyOf(outlines), plan, frame, rule);
    }

    public GradingFrame frame() {
        return frame;
    }

    public GradingRule rule() {
        return rule;
    }

    public GradingPlan plan() {
        return plan;
    }

    /** Every size of the plan, in order. */
    public GradingResult gradeAll() {
        List<GradedSize> out = new ArrayList<>();
        for (double s : plan.sizes()) {
            out.add(grade(s));
        }
        return new GradingResult(frame, rule, out);
    }

    /** One size. */
    public GradedSize grade(double size) {
        ScaleFactors f = rule.factors(size);
        PantographMap map = PantographMap.of(frame, f);
        List<GradedOutline> exact = new ArrayList<>();
        for (Contour c : outlines) {
            exact.add(GradedOutline.of(c, map));
        }
        List<Contour> output = new ArrayList<>();
        OptionalDouble heel = OptionalDouble.empty();
        if (plan.coordination().isPresent()) {
            Coordination co = plan.coordination().get();
            double nbc = co.heelSize(size, plan.baseSize(), plan.system());
            heel = OptionalDouble.of(nbc);
            PantographMap heelMap = PantographMap.of(frame, rule.factors(nbc));
            for (int k = 0; k < outlines.size(); k++) {
                EscomPattern p = EscomPattern.ofContour(outlines.get(k));
                // designated elements are the outer outline's; an inner contour then grades with the size
                boolean byLine = k == 0 || !co.byElements();
                output.add(p.graded(n -> byLine
                                        && co.isHeelPoint(
                                                p, n, frame.toLocal(p.point(n)).y())
                                ? heelMap
                                : map)
                        .toContour());
            }
        } else if (plan.arcMode() == ArcMode.THREE_POINT) {
            for (Contour c : outlines) {
                output.add(EscomPattern.ofContour(c).graded(map).toContour());
            }
        } else {
            for (GradedOutline g : exact) {
                output.add(g.toArcs(plan.arcToleranceMm()));
            }
        }
        double length;
        double width;
        OptionalDouble deviation = OptionalDouble.empty();
        if (heel.isPresent()) {
            length = Extents.sizeAlong(output.get(0), frame.lengthAxis());
            width = Extents.sizeAlong(output.get(0), frame.widthAxis());
        } else {
            length = exact.get(0).sizeAlong(frame.lengthAxis());
            width = exact.get(0).sizeAlong(frame.widthAxis());
            double worst = 0;
            for (int i = 0; i < exact.size(); i++) {
                worst = Math.max(worst, exact.get(i).deviationFrom(output.get(i), 1.0));
            }
            deviation = OptionalDouble.of(worst);
        }
        return new GradedSize(f, heel, exact, output, length, width, deviation);
    }

    /** The point of the base drawing that stays fixed. */
    public Vec2 origin() {
        return frame.origin();
    }
}
