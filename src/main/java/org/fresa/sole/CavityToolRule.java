package org.fresa.sole;

import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;

/**
 * The sole thesis's rule for the cavity cutter (Ahrens 1986, figure 6.16): its diameter must be
 * smaller than the smallest diameter among the outline's arcs, because the tool centre follows
 * each element at the tool radius and an arc tighter than the tool has no offset to follow: the
 * path breaks and the wall there is left uncut or gouged.
 *
 * <p>Only arcs bending towards the cavity's inside (their centre on the material side of the
 * tool) constrain the cutter; an arc bending away is offset to a larger one. The thesis states the
 * rule for every arc; for the sole it machined the two readings agree (its smallest arcs, the toe
 * C7 and the heel C1, both bend inwards).
 */
public final class CavityToolRule {

    private CavityToolRule() {}

    /**
     * The tightest inward arc that the tool cannot follow.
     *
     * @param elementIndex the arc's position in the outline, from 1 in the outline's order
     */
    public record Violation(int elementIndex, Arc2 arc, double toolDiameterMm) {
        public Violation {
            Objects.requireNonNull(arc, "arc");
        }

        /** The refusal in the planner's words. */
        public String sentence() {
            return String.format(
                    Locale.ROOT,
                    "the %.3f mm cavity tool is not smaller than the outline's arc %d (centre %.3f, %.3f; diameter %.3f mm):"
                            + " its centre cannot follow that arc; choose a tool below %.3f mm",
                    toolDiameterMm,
                    elementIndex,
                    arc.center().x(),
                    arc.center().y(),
                    2 * arc.radius(),
                    toolDiameterMm,
                    2 * arc.radius());
        }
    }

    /** The tightest inward arc whose diameter is not larger than the tool's, or empty. */
    public static Optional<Violation> check(Contour outline, double toolDiameterMm) {
        if (!(toolDiameterMm > 0) || Double.isInfinite(toolDiameterMm)) {
            throw new IllegalArgumentException("tool diameter must be finite and > 0: " + toolDiameterMm);
        }
        boolean ccw = outline.isCcw();
        Arc2 tightest = null;
        int index = 0;
        for (int i = 0; i < outline.size(); i++) {
            Curve2 c = outline.get(i);
            if (c instanceof Arc2 a && a.ccw() == ccw && (tightest == null || a.radius() < tightest.radius())) {
                tightest = a;
                index = i + 1;
            }
        }
        if (tightest != null && toolDiameterMm >= 2 * tightest.radius()) {
            return Optional.of(new Violation(index, tightest, toolDiameterMm));
        }
        return Optional.empty();
    }
}
