package org.fresa.grading;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;

/**
 * A closed outline graded exactly: the pantograph's affine image of a contour of lines and arcs,
 * as lines and elliptic arcs in the base's order of travel.
 *
 * @param curves the graded elements, each ending where the next starts
 */
public record GradedOutline(List<GradedCurve> curves) {

    public GradedOutline {
        curves = List.copyOf(curves);
        if (curves.isEmpty()) {
            throw new IllegalArgumentException("an outline needs at least one element");
        }
    }

    /** The exact image of a contour under the map. */
    public static GradedOutline of(Contour base, PantographMap map) {
        List<GradedCurve> out = new ArrayList<>(base.size());
        for (Curve2 c : base.curves()) {
            if (c instanceof Segment2 s) {
                out.add(new GradedLine(map.apply(s.start()), map.apply(s.end())));
            } else {
                out.add(EllipticArc.of((Arc2) c, map));
            }
        }
        return new GradedOutline(out);
    }

    /** The image of this outline under another map (grading a graded outline again). */
    public GradedOutline mapped(PantographMap map) {
        return new GradedOutline(curves.stream().map(c -> c.mapped(map)).toList());
    }

    /** Smallest and largest p . dir over the outline (exact). */
    public double[] extentAlong(Vec2 dir) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (GradedCurve c : curves) {
            double[] e = c.extentAlong(dir);
            lo = Math.min(lo, e[0]);
            hi = Math.max(hi, e[1]);
        }
        return new double[] {lo, hi};
    }

    /** The outline's size along the direction (mm). */
    public double sizeAlong(Vec2 dir) {
        double[] e = extentAlong(dir);
        return e[1] - e[0];
    }

    /**
     * Points on the exact outline in order of travel, starting at the first element's start, the
     * closing point not repeated: every line's start and points along each ellipse such that the
     * polygon deviates from the outline by at most chordMm.
     */
    public List<Vec2> points(double chordMm) {
        List<Vec2> out = new ArrayList<>();
        for (GradedCurve c : curves) {
            out.addAll(c.sample(chordMm));
        }
        return out;
    }

    /**
     * The outline as lines and circular arcs for NC and DXF: lines stay lines, each elliptic arc
     * becomes biarcs within toleranceMm. The contour is closed exactly (shared end points).
     */
    public Contour toArcs(double toleranceMm) {
        List<Curve2> out = new ArrayList<>();
        for (GradedCurve c : curves) {
            if (c instanceof GradedLine l) {
                out.add(new Segment2(l.start(), l.end()));
            } else {
                EllipticArc e = (EllipticArc) c;
                if (isCircle(e)) {
                    out.add(new Arc2(e.center(), e.start(), e.end(), e.ccw()));
                } else {
                    out.addAll(Biarcs.of(e, toleranceMm));
                }
            }
        }
        return new Contour(out);
    }

    /** True when a graded arc is still a circle (equal factors), so it stays one arc. */
    private static boolean isCircle(EllipticArc e) {
        return Math.abs(e.u().norm() - e.v().norm()) <= 1e-12 * e.u().norm()
                && Math.abs(e.u().dot(e.v())) <= 1e-12 * e.u().dot(e.u())
                && Math.abs(e.sweepRad()) < 2 * Math.PI;
    }

    /**
     * The largest distance from densely sampled points of this exact outline to the contour, and
     * from the contour's sampled points back to this outline's polygon: a two-sided check of how
     * closely the contour follows the exact outline.
     *
     * @param stepMm the spacing of the contour's samples; the exact outline is sampled so that its
     *     polygon is within 1e-5 mm of it, which bounds the error of the check
     */
    public double deviationFrom(Contour c, double stepMm) {
        List<Vec2> exact = points(1e-5);
        double worst = 0;
        for (Vec2 p : exact) {
            worst = Math.max(worst, c.distanceTo(p));
        }
        Contour poly = Contour.polygon(exact);
        for (Curve2 k : c.curves()) {
            int n = Math.max(2, (int) Math.ceil(k.length() / stepMm));
            for (int i = 0; i < n; i++) {
                worst = Math.max(worst, poly.distanceTo(k.pointAt((double) i / n)));
            }
        }
        return worst;
    }
}
