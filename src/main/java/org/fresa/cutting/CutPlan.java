package org.fresa.cutting;

import java.util.List;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;
import org.fresa.model.Toolpath;

/**
 * A sheet's cutting plan: the cuts in order, what was found in the drawing, what could not be
 * cut and why, and the tool-centre path.
 *
 * @param cuts pierces in cutting order
 * @param outers the drawn outer contours of parts
 * @param holes the drawn holes
 * @param open open chains (drawn, never cut)
 * @param invalidVertices corners the paper's rules reject (paper mode) or a kerf cannot reach
 * @param warnings one sentence each
 * @param uncut closed contours that are not cut (a hole smaller than the kerf)
 * @param duplicates elements removed as repeats
 * @param zeroLength elements removed for zero length
 * @param toolpath the moves from the machine origin, one section per pierce
 * @param rapids for each cut, the rapid travel from the previous exit (the origin for the first)
 *     to its pierce: both ends and any detour points around parts already cut free
 * @param notCut each contour of {@code uncut} with its label and why it is not cut
 */
public record CutPlan(List<CutPath> cuts, List<Contour> outers, List<Contour> holes, List<List<Curve2>> open,
        List<Vec2> invalidVertices, List<String> warnings, List<Contour> uncut, int duplicates, int zeroLength,
        Toolpath toolpath, List<List<Vec2>> rapids, List<NotCut> notCut) {

    /**
     * A closed contour left uncut.
     *
     * @param label e.g. "part 2 hole 1"
     * @param contour the drawn contour
     * @param reason why, in the planner's words ("is too small for a 2.000 mm kerf")
     */
    public record NotCut(String label, Contour contour, String reason) {
    }

    public CutPlan {
        cuts = List.copyOf(cuts);
        outers = List.copyOf(outers);
        holes = List.copyOf(holes);
        open = open.stream().map(List::copyOf).toList();
        invalidVertices = List.copyOf(invalidVertices);
        warnings = List.copyOf(warnings);
        uncut = List.copyOf(uncut);
        rapids = rapids.stream().map(List::copyOf).toList();
        notCut = List.copyOf(notCut);
        if (rapids.size() != cuts.size()) {
            throw new IllegalArgumentException(rapids.size() + " rapids for " + cuts.size() + " cuts");
        }
    }

    public double cutLengthMm() {
        double l = 0;
        for (CutPath c : cuts) {
            l += c.cutLengthMm();
        }
        return l;
    }

    /** Total rapid travel from the origin through every pierce, detours included. */
    public double rapidLengthMm() {
        double l = 0;
        for (List<Vec2> r : rapids) {
            for (int k = 0; k + 1 < r.size(); k++) {
                l += r.get(k).distance(r.get(k + 1));
            }
        }
        return l;
    }
}
