package org.fresa.grading;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;
import org.fresa.model.CamInputException;

/**
 * Finds the grading frame of a sole outline.
 *
 * <ol>
 *   <li><b>Length axis</b>: the direction of the outline's longer extent, its diameter (the two
 *       points furthest apart, on a 0.5 mm sampling). A sole's heel-to-toe diameter leans a few
 *       degrees from its centre line because the toe is not on that line, so a diameter within
 *       10 degrees of the drawing's x or y axis is snapped to that axis: drawings are made
 *       aligned, and the thesis grades in the drawing's axes. Outlines drawn at another angle are
 *       graded in the frame of their diameter.
 *   <li><b>Heel end</b>: of the two ends of the length axis, the one where the outline is
 *       narrower at a sixth of the length from the end (the heel is narrower than the forepart).
 *       The length axis is turned to point from heel to toe.
 *   <li><b>Origin</b> (unless given): the centre of the heel circle, the arc that reaches furthest
 *       back along the length axis (thesis section 4.2: the origin is the centre of circle C1).
 * </ol>
 */
public final class OutlineFrames {

    private static final double SNAP_DEG = 10;

    private OutlineFrames() {}

    /**
     * The frame of the outline.
     *
     * @param origin a given origin, or empty for the heel circle's centre
     * @param lengthAxisDeg a given direction of the length axis (degrees from +x, towards the
     *     toe), or empty to find it
     * @throws CamInputException when no origin is given and no arc lies at the heel end
     */
    public static GradingFrame detect(
            Contour outline, Optional<Vec2> origin, OptionalDouble lengthAxisDeg, String source)
            throws CamInputException {
        List<Vec2> pts = sample(outline, 0.5);
        Vec2 u;
        if (lengthAxisDeg.isPresent()) {
            u = Vec2.ofAngle(Math.toRadians(lengthAxisDeg.getAsDouble()));
        } else {
            u = snapped(diameterDirection(pts));
            double[] e = Extents.along(outline, u);
            double len = e[1] - e[0];
            double nearLow = widthAt(pts, u, e[0] + len / 6, len / 50);
            double nearHigh = widthAt(pts, u, e[1] - len / 6, len / 50);
            if (nearHigh < nearLow) {
                u = u.negated();
            }
        }
        if (origin.isPresent()) {
            return new GradingFrame(origin.get(), u);
        }
        return new GradingFrame(heelCenter(outline, u, source), u);
    }

    /** The centre of the arc that reaches furthest back (lowest along u). */
    static Vec2 heelCenter(Contour outline, Vec2 u, String source) throws CamInputException {
        double back = Extents.along(outline, u)[0];
        double tol = 1e-6 * Math.max(1, Extents.sizeAlong(outline, u));
        Arc2 best = null;
        for (Curve2 c : outline.curves()) {
            if (c instanceof Arc2 a && a.radius() > 0) {
                double lo = Extents.along(a, u)[0];
                boolean convexBack = a.containsAngle(u.negated().angleRad());
                if (Math.abs(lo - back) <= tol
                        && convexBack
                        && (best == null || Math.abs(a.sweepRad()) > Math.abs(best.sweepRad()))) {
                    best = a;
                }
            }
        }
        if (best == null) {
            throw new CamInputException(
                    source,
                    "no arc at the heel end of the outline to take the grading origin "
                            + "from; give the origin (--origin X,Y)");
        }
        return best.center();
    }

    static List<Vec2> sample(Contour c, double stepMm) {
        List<Vec2> out = new ArrayList<>();
        for (Curve2 k : c.curves()) {
            int n = Math.max(k instanceof Arc2 ? 16 : 1, (int) Math.ceil(k.length() / stepMm));
            for (int i = 0; i < n; i++) {
                out.add(k.pointAt((double) i / n));
            }
        }
        return out;
    }

    static Vec2 diameterDirection(List<Vec2> pts) {
        double best = -1;
        Vec2 dir = Vec2.UNIT_Y;
        for (int i = 0; i < pts.size(); i++) {
            for (int j = i + 1; j < pts.size(); j++) {
                double d = pts.get(i).distance(pts.get(j));
                if (d > best) {
                    best = d;
                    dir = pts.get(j).minus(pts.get(i));
                }
            }
        }
        return best > 0 ? dir.normalized() : Vec2.UNIT_Y;
    }

    static Vec2 snapped(Vec2 d) {
        for (Vec2 axis : new Vec2[] {Vec2.UNIT_X, Vec2.UNIT_Y}) {
            double cos = Math.abs(d.dot(axis));
            if (cos >= Math.cos(Math.toRadians(SNAP_DEG))) {
                return d.dot(axis) >= 0 ? axis : axis.negated();
            }
        }
        return d;
    }

    private static double widthAt(List<Vec2> pts, Vec2 u, double station, double halfBand) {
        Vec2 w = new Vec2(u.y(), -u.x());
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (Vec2 p : pts) {
            if (Math.abs(p.dot(u) - station) <= halfBand) {
                lo = Math.min(lo, p.dot(w));
                hi = Math.max(hi, p.dot(w));
            }
        }
        return hi > lo ? hi - lo : 0;
    }
}
