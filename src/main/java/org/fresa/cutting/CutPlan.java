package org.fresa.cutting;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.NoSuchElementException;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

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
 * @param rapids for each cut, the rapid travel from the previous exit (the origin for the first)
 *     to its pierce: both ends and any detour points around parts already cut free
 * @param notCut each contour of {@code uncut} with its label and why it is not cut
 * @param feedMmPerMin the cutting feed of every feed move
 * @param kerfMm the kerf, the tool diameter of every section
 *
 * <p>The tool-centre path is not held: a sheet of 180 000 parts has some five million moves, more
 * than the plan itself. {@link #sections()} makes it one pierce at a time as the post writes it;
 * {@link #toolpath()} makes it whole, for a drawing of the sheet or a test.
 */
public record CutPlan(
        List<CutPath> cuts,
        List<Contour> outers,
        List<Contour> holes,
        List<List<Curve2>> open,
        List<Vec2> invalidVertices,
        List<String> warnings,
        List<Contour> uncut,
        int duplicates,
        int zeroLength,
        List<List<Vec2>> rapids,
        List<NotCut> notCut,
        double feedMmPerMin,
        double kerfMm) {

    /**
     * A closed contour left uncut.
     *
     * @param label e.g. "part 2 hole 1"
     * @param contour the drawn contour
     * @param reason why, in the planner's words ("is too small for a 2.000 mm kerf")
     */
    public record NotCut(String label, Contour contour, String reason) {}

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

    /** The moves from the machine origin, one section per pierce, all at once. */
    public Toolpath toolpath() {
        List<ToolpathSection> all = new ArrayList<>(cuts.size());
        for (ToolpathSection s : sections()) {
            all.add(s);
        }
        return new Toolpath(all);
    }

    /**
     * The sections of {@link #toolpath()} in order, each made when the iteration reaches it and
     * not kept: the rapids to the pierce, then the lead-in, the cut, the overcut and the lead-out.
     */
    public Iterable<ToolpathSection> sections() {
        return () -> new Iterator<>() {
            private int i;
            private Vec3 at = Vec3.ZERO;

            @Override
            public boolean hasNext() {
                return i < cuts.size();
            }

            @Override
            public ToolpathSection next() {
                if (!hasNext()) {
                    throw new NoSuchElementException();
                }
                ToolpathSection s = section(i++, at);
                at = s.moves().get(s.moves().size() - 1).end();
                return s;
            }
        };
    }

    private ToolpathSection section(int i, Vec3 at) {
        CutPath c = cuts.get(i);
        List<Move> moves = new ArrayList<>();
        List<Vec2> rapid = rapids.get(i);
        for (int k = 1; k < rapid.size(); k++) {
            moves.add(new Move.Rapid(Vec3.of(rapid.get(k), 0)));
        }
        for (Curve2 cv : c.curves()) {
            if (cv instanceof Segment2 s) {
                if (s.length() > 0) {
                    moves.add(new Move.Linear(Vec3.of(s.end(), 0), feedMmPerMin));
                }
            } else {
                Arc2 a = (Arc2) cv;
                moves.add(new Move.Circular(
                        Vec3.of(a.end(), 0), Vec3.of(a.center(), 0), Vec3.UNIT_Z, a.ccw(), 0, feedMmPerMin));
            }
        }
        return new ToolpathSection(c.label(), Vec3.UNIT_Z, Math.max(kerfMm, 1e-3), 1, 0, at, moves);
    }
}
