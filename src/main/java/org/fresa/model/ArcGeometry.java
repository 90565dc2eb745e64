package org.fresa.model;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Vec3;

/**
 * The geometry of a {@link Move.Circular} seen from its start point: radius, signed sweep about
 * the normal (extra turns included) and rise along the normal, and its points at a chord
 * tolerance. Shared by the posts (arcs in planes other than XY/XZ/YZ), the CSV writer and the
 * robot trajectory, so that toolpath.csv and trajectory.csv sample an arc at the same points.
 *
 * <p>Conventions: the sweep is positive counter-clockwise about the normal; an arc whose end
 * projects onto its start (within 1e-9 of the radius) is a full turn, so its sweep is 2 pi (plus
 * the extra turns). The rise is the component of end minus start along the normal (a helix when
 * non-zero). A zero radius gives a sweep of 0 and the end point only.
 *
 * @param start start point (mm)
 * @param move the arc
 * @param radiusMm distance from the axis to the start point
 * @param sweepRad signed total sweep, |sweep| in (0, 2 pi (turns + 1)]
 * @param riseMm end minus start along the normal
 */
public record ArcGeometry(Vec3 start, Move.Circular move, double radiusMm, double sweepRad, double riseMm) {

    /** The geometry of the arc that starts at {@code start}. */
    public static ArcGeometry of(Vec3 start, Move.Circular c) {
        Vec3 n = c.normal();
        Vec3 u = inPlane(start.minus(c.center()), n);
        Vec3 e = inPlane(c.end().minus(c.center()), n);
        double r = u.norm();
        double rise = c.end().minus(start).dot(n);
        if (r == 0) {
            return new ArcGeometry(start, c, 0, 0, rise);
        }
        double angle = Math.atan2(u.cross(e).dot(n), u.dot(e));
        boolean fullTurn = u.distance(e) <= 1e-9 * Math.max(1, r);
        double sweep;
        if (c.ccw()) {
            sweep = fullTurn ? 2 * Math.PI : (angle <= 0 ? angle + 2 * Math.PI : angle);
        } else {
            sweep = fullTurn ? -2 * Math.PI : (angle >= 0 ? angle - 2 * Math.PI : angle);
        }
        sweep += Math.signum(sweep) * 2 * Math.PI * c.turns();
        return new ArcGeometry(start, c, r, sweep, rise);
    }

    private static Vec3 inPlane(Vec3 v, Vec3 n) {
        return v.minus(n.times(v.dot(n)));
    }

    /** The path length in mm (a helix counts its rise). */
    public double lengthMm() {
        return Math.hypot(radiusMm * sweepRad, riseMm);
    }

    /** The point at the given fraction of the sweep (0 start, 1 end, which is exact). */
    public Vec3 pointAt(double fraction) {
        if (fraction == 1) {
            return move.end();
        }
        Vec3 n = move.normal();
        Vec3 u = inPlane(start.minus(move.center()), n);
        Vec3 v = n.cross(u);
        double a = sweepRad * fraction;
        Vec3 axisPoint = move.center().plus(n.times(start.minus(move.center()).dot(n) + riseMm * fraction));
        return axisPoint.plus(u.times(Math.cos(a))).plus(v.times(Math.sin(a)));
    }

    /**
     * The points that replace the arc by chords deviating at most {@code chordToleranceMm} from
     * it: the start excluded, the exact end included, at equal angle steps (at least one).
     */
    public List<Vec3> points(double chordToleranceMm) {
        if (!(chordToleranceMm > 0)) {
            throw new IllegalArgumentException("chord tolerance must be > 0: " + chordToleranceMm);
        }
        int steps = 1;
        if (radiusMm > chordToleranceMm) {
            double maxStep = 2 * Math.acos(1 - chordToleranceMm / radiusMm);
            steps = Math.max(1, (int) Math.ceil(Math.abs(sweepRad) / maxStep - 1e-12));
        }
        if (Math.abs(sweepRad) >= Math.PI) {
            steps = Math.max(steps, 3);
        }
        List<Vec3> pts = new ArrayList<>(steps);
        for (int k = 1; k <= steps; k++) {
            pts.add(pointAt((double) k / steps));
        }
        return pts;
    }
}
