package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Intersections;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.stepnc.Feature.SlotEnd;
import org.fresa.stepnc.Feature.SlotEnd.EndType;

/**
 * The outline a slot along a GENERAL_PATH sweeps at one half width (ISO 14649-10 general_path:
 * its swept_path a polyline or a composite curve of lines and arcs): the path offset by the half
 * width to either side, the walls staying lines and arcs, joined by arcs about the path's corners
 * on the outer side and cut where they meet on the inner side; the ends as their end types say.
 * A closed path (a loop) sweeps a band: the outer offset and the inner one as an island.
 *
 * <p>Lengths in mm, in the slot frame (the feature frame, z the feature axis); "left" is left of
 * the path's direction seen from +z.
 */
final class SlotBands {

    private SlotBands() {}

    /** The walls on one side of an open or closed path at a signed offset (positive left). */
    static List<Curve2> wall(List<Curve2> path, double offset, boolean closed, Tolerance tol) {
        List<Curve2> parts = new ArrayList<>();
        for (Curve2 c : path) {
            parts.add(offsetCurve(c, offset));
        }
        int n = parts.size();
        List<Curve2> out = new ArrayList<>();
        // the joints: after curve i, the next one (the first again when closed)
        Curve2[] trimmed = parts.toArray(new Curve2[0]);
        List<List<Curve2>> after = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            after.add(new ArrayList<>());
        }
        int joints = closed ? n : n - 1;
        for (int i = 0; i < joints; i++) {
            int j = (i + 1) % n;
            Vec2 corner = path.get(i).end();
            Curve2 a = trimmed[i];
            Curve2 b = trimmed[j];
            if (a.end().distance(b.start()) <= tol.linear()) {
                continue;
            }
            double turn = path.get(i).endTangent().cross(path.get(j).startTangent());
            boolean outer = offset > 0 ? turn < 0 : turn > 0;
            if (outer) {
                // the wall goes round the path's corner at the half width
                after.get(i).add(new Arc2(corner, a.end(), b.start(), turn > 0));
                continue;
            }
            Vec2 meet = null;
            for (Vec2 p : Intersections.of(a, b, tol)) {
                if (meet == null || p.distance(corner) < meet.distance(corner)) {
                    meet = p;
                }
            }
            if (meet == null) {
                throw new UnsupportedOperationException("the slot's path turns too tightly for its width: the walls"
                        + " beside its corner at (" + ToolpathPlanner.mm(corner.x()) + ", "
                        + ToolpathPlanner.mm(corner.y()) + ") do not meet");
            }
            trimmed[i] = withEnd(a, meet);
            trimmed[j] = withStart(b, meet);
        }
        for (int i = 0; i < n; i++) {
            if (trimmed[i].length() > tol.linear()) {
                out.add(trimmed[i]);
            }
            out.addAll(after.get(i));
        }
        return out;
    }

    /**
     * The outline of a slot along an open path: the right wall forward, the far end, the left
     * wall back and the near end, counter-clockwise.
     */
    static Contour openOutline(List<Curve2> path, double halfWidth, List<SlotEnd> ends, Tolerance tol) {
        SlotEnd first = ends.isEmpty() ? null : ends.get(0);
        SlotEnd last = ends.size() < 2 ? first : ends.get(1);
        List<Curve2> right = wall(path, -halfWidth, false, tol);
        List<Curve2> left = wall(path, halfWidth, false, tol);
        List<Curve2> cs = new ArrayList<>(right);
        Curve2 end = path.get(path.size() - 1);
        Curve2 start = path.get(0);
        cs.add(cap(
                end.end(),
                end.endTangent(),
                halfWidth,
                last,
                cs.get(cs.size() - 1).end(),
                left.get(left.size() - 1).end()));
        for (int i = left.size() - 1; i >= 0; i--) {
            cs.add(left.get(i).reversed());
        }
        cs.add(cap(
                start.start(),
                start.startTangent().times(-1),
                halfWidth,
                first,
                left.get(0).start(),
                right.get(0).start()));
        return Contour.of(cs, Tolerance.DRAWING);
    }

    /** An end from the right wall's end to the left wall's: a half circle about the path's end, or square. */
    private static Curve2 cap(Vec2 at, Vec2 outward, double halfWidth, SlotEnd e, Vec2 from, Vec2 to) {
        if (e != null
                && e.type() == EndType.FLAT
                && (e.firstRadiusMm().orElse(0) > 0 || e.secondRadiusMm().orElse(0) > 0)) {
            throw new UnsupportedOperationException(
                    "flat slot ends with corner radii are machined on a LINEAR_PATH only; along a GENERAL_PATH a flat"
                            + " end is square");
        }
        if (e != null && e.type() == EndType.RADIUSED) {
            return new Arc2(at, from, to, true);
        }
        return new Segment2(from, to);
    }

    /** The band a closed path sweeps: its outer wall, counter-clockwise. */
    static Contour closedOuter(List<Curve2> ccwPath, double halfWidth, Tolerance tol) {
        return Contour.of(wall(ccwPath, -halfWidth, true, tol), Tolerance.DRAWING);
    }

    /** The band a closed path sweeps: its inner wall, the island left standing. */
    static Contour closedInner(List<Curve2> ccwPath, double halfWidth, Tolerance tol) {
        List<Curve2> in = wall(ccwPath, halfWidth, true, tol);
        Contour c = Contour.of(in, Tolerance.DRAWING);
        if (!(c.signedArea() > tol.linear() * tol.linear())) {
            throw new UnsupportedOperationException(
                    "the loop slot is as wide as its closed path: no island is left inside it");
        }
        return c.ccw();
    }

    /** A line or arc moved to its left by the offset (an arc's radius less it when counter-clockwise). */
    static Curve2 offsetCurve(Curve2 c, double offset) {
        if (c instanceof Segment2 s) {
            Vec2 n = s.direction().normalized().leftNormal().times(offset);
            return new Segment2(s.start().plus(n), s.end().plus(n));
        }
        Arc2 a = (Arc2) c;
        double r = a.radius();
        double r2 = a.ccw() ? r - offset : r + offset;
        if (!(r2 > 1e-6)) {
            throw new UnsupportedOperationException("the slot's path turns on a " + ToolpathPlanner.mm(r)
                    + " mm radius, tighter than the half width " + ToolpathPlanner.mm(Math.abs(offset))
                    + " mm it is offset by");
        }
        Vec2 s0 = a.center().plus(a.start().minus(a.center()).times(r2 / r));
        Vec2 e0 =
                a.center().plus(a.end().minus(a.center()).times(r2 / a.center().distance(a.end())));
        return new Arc2(a.center(), s0, e0, a.ccw());
    }

    private static Curve2 withEnd(Curve2 c, Vec2 p) {
        return c instanceof Arc2 a ? new Arc2(a.center(), a.start(), p, a.ccw()) : new Segment2(c.start(), p);
    }

    private static Curve2 withStart(Curve2 c, Vec2 p) {
        return c instanceof Arc2 a ? new Arc2(a.center(), p, a.end(), a.ccw()) : new Segment2(p, c.end());
    }
}
