package org.fresa.cutting;

import java.util.List;
import java.util.Objects;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;

/**
 * One pierce: the lead-in, the closed cut (tool-centre path, starting and ending at the
 * pierce-side junction), the overcut and the lead-out, in order of travel.
 *
 * @param label e.g. "part 2 hole 1"
 * @param outer true for the outside of a part, false for a hole
 * @param part the drawn contour this cut frees (its original geometry)
 * @param path the closed path of the tool centre, starting at the end of the lead-in
 * @param leadIn from the pierce point to the path's start (empty: pierce on the path)
 * @param tail overcut then lead-out, after the path is closed
 * @param compensation 0 none (path already offset), 41 controller keeps the tool left, 42 right
 */
public record CutPath(
        String label,
        boolean outer,
        Contour part,
        Contour path,
        List<Curve2> leadIn,
        List<Curve2> tail,
        int compensation) {

    public CutPath {
        Objects.requireNonNull(label, "label");
        leadIn = List.copyOf(leadIn);
        tail = List.copyOf(tail);
    }

    /** Where the jet pierces the sheet. */
    public Vec2 pierce() {
        return leadIn.isEmpty() ? path.get(0).start() : leadIn.get(0).start();
    }

    /** Where the jet is switched off. */
    public Vec2 exit() {
        return tail.isEmpty()
                ? path.get(path.size() - 1).end()
                : tail.get(tail.size() - 1).end();
    }

    /** Every feed curve in order. */
    public List<Curve2> curves() {
        List<Curve2> all = new java.util.ArrayList<>(leadIn);
        all.addAll(path.curves());
        all.addAll(tail);
        return all;
    }

    public double cutLengthMm() {
        double l = 0;
        for (Curve2 c : curves()) {
            l += c.length();
        }
        return l;
    }
}
