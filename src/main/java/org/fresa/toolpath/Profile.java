package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;

/**
 * A closed pocket or boss outline in its feature plane (mm), and its exact inward offsets as
 * tool-centre {@link Ring}s. Every ring runs counter-clockwise and starts at its lowest point on
 * the vertical through the centre ("bottom middle"), so nested rings are joined by short straight
 * links along that vertical.
 *
 * <p>Offsets of the parametric profiles are computed in closed form: a rounded rectangle inset
 * by d is a rounded rectangle with sides 2d shorter and corner radius max(r - d, 0); a circle
 * keeps its centre; a regular polygon keeps its angles and loses d of apothem. A general contour
 * is offset by a {@link ContourOffsetter}.
 */
public sealed interface Profile
        permits Profile.RoundedRectangle, Profile.Circle, Profile.RegularPolygon, Profile.General {

    /** The outline itself, counter-clockwise. */
    Contour contour(Tolerance tol);

    /**
     * The loop of tool-centre positions at distance d inside the outline; empty when the profile
     * is narrower than 2d (beyond the tolerance). A profile exactly 2d wide gives a collapsed ring.
     */
    Optional<Ring> inset(double dMm, Tolerance tol);

    /**
     * The smallest interior angle of a sharp corner of the rings inset by dMm up to their
     * collapse, in radians; pi when they have none (circles, stadiums).
     */
    double sharpCornerAngleRad(double dMm);

    /** The centre used as the plunge point of center milling and the origin of the rings. */
    Vec2 center();

    /** Every loop of the inset (a non-convex outline may split into several), largest first. */
    default List<Ring> insetAll(double dMm, Tolerance tol) {
        return inset(dMm, tol).map(List::of).orElse(List.of());
    }

    /** Whether straight links between points inside a ring stay inside it (true for the parametric profiles). */
    default boolean convex() {
        return true;
    }

    /**
     * The largest inset that still leaves a ring (the half-width where the rings collapse to a
     * segment or a point), mm; NaN when unknown (general contours).
     */
    double maxInsetMm();

    /**
     * A rectangle with sides along the feature's x and y axes and rounded corners.
     *
     * @param xLengthMm side along x, > 0
     * @param yLengthMm side along y, > 0
     * @param cornerRadiusMm 0 for sharp corners, at most half the shorter side
     */
    record RoundedRectangle(Vec2 center, double xLengthMm, double yLengthMm, double cornerRadiusMm) implements Profile {
        public RoundedRectangle {
            if (!(xLengthMm > 0)
                    || !(yLengthMm > 0)
                    || cornerRadiusMm < 0
                    || cornerRadiusMm > Math.min(xLengthMm, yLengthMm) / 2 + 1e-9) {
                throw new IllegalArgumentException(
                        "bad rectangle: " + xLengthMm + " x " + yLengthMm + " r " + cornerRadiusMm);
            }
        }

        @Override
        public Contour contour(Tolerance tol) {
            Ring r = ring(xLengthMm, yLengthMm, cornerRadiusMm);
            return new Contour(r.curves());
        }

        @Override
        public Optional<Ring> inset(double d, Tolerance tol) {
            double w = xLengthMm - 2 * d;
            double h = yLengthMm - 2 * d;
            if (w < -tol.linear() || h < -tol.linear()) {
                return Optional.empty();
            }
            return Optional.of(ring(Math.max(w, 0), Math.max(h, 0), Math.max(cornerRadiusMm - d, 0)));
        }

        private Ring ring(double w, double h, double r) {
            r = Math.min(r, Math.min(w, h) / 2);
            double x0 = center.x() - w / 2;
            double x1 = center.x() + w / 2;
            double y0 = center.y() - h / 2;
            double y1 = center.y() + h / 2;
            Vec2 s = new Vec2(center.x(), y0);
            List<Curve2> c = new ArrayList<>();
            Vec2[] corners = {new Vec2(x1, y0), new Vec2(x1, y1), new Vec2(x0, y1), new Vec2(x0, y0)};
            Vec2[] dirs = {Vec2.UNIT_X, Vec2.UNIT_Y, Vec2.UNIT_X.negated(), Vec2.UNIT_Y.negated()};
            Vec2 at = s;
            for (int k = 0; k < 4; k++) {
                Vec2 corner = corners[k];
                Vec2 in = dirs[k];
                Vec2 out = dirs[(k + 1) % 4];
                Vec2 a = corner.minus(in.times(r));
                at = line(c, at, a);
                if (r > 0) {
                    Vec2 b = corner.plus(out.times(r));
                    c.add(new Arc2(a.plus(out.times(r)), a, b, true));
                    at = b;
                }
            }
            line(c, at, s);
            return new Ring(s, c);
        }

        @Override
        public double sharpCornerAngleRad(double dMm) {
            // loops inset beyond the corner radius have sharp corners, and loops run to the collapse
            return cornerRadiusMm >= maxInsetMm() ? Math.PI : Math.PI / 2;
        }

        @Override
        public double maxInsetMm() {
            return Math.min(xLengthMm, yLengthMm) / 2;
        }
    }

    /** A circle; its rings are full circles (true arcs). */
    record Circle(Vec2 center, double radiusMm) implements Profile {
        public Circle {
            if (!(radiusMm > 0)) {
                throw new IllegalArgumentException("circle radius must be > 0: " + radiusMm);
            }
        }

        @Override
        public Contour contour(Tolerance tol) {
            return new Contour(inset(0, tol).orElseThrow().curves());
        }

        @Override
        public Optional<Ring> inset(double d, Tolerance tol) {
            double r = radiusMm - d;
            if (r < -tol.linear()) {
                return Optional.empty();
            }
            Vec2 s = center.plus(new Vec2(0, -Math.max(r, 0)));
            if (r <= tol.linear()) {
                return Optional.of(new Ring(center, List.of()));
            }
            Vec2 top = center.plus(new Vec2(0, r));
            // two half turns rather than one full-turn arc: each has a well-defined chord for links and spirals
            return Optional.of(new Ring(s, List.of(new Arc2(center, s, top, true), new Arc2(center, top, s, true))));
        }

        @Override
        public double sharpCornerAngleRad(double dMm) {
            return Math.PI;
        }

        @Override
        public double maxInsetMm() {
            return radiusMm;
        }
    }

    /**
     * A regular polygon in the ISO orientation: one side parallel to x, crossing the -y axis.
     *
     * @param sides number of sides, >= 3
     * @param diameterMm the diameter of the reference circle
     * @param circumscribed true when the polygon surrounds the circle (the circle is inscribed,
     *     diameter across flats; ISO {@code circumscribed_or_across_flats}); false when the
     *     vertices lie on the circle. The thesis's eq. 22 gives the vertex radius
     *     R = sqrt(r^2 + (r tan(pi/n))^2) = r / cos(pi/n) in the first case.
     */
    record RegularPolygon(Vec2 center, int sides, double diameterMm, boolean circumscribed) implements Profile {
        public RegularPolygon {
            if (sides < 3 || !(diameterMm > 0)) {
                throw new IllegalArgumentException("bad polygon: " + sides + " sides, diameter " + diameterMm);
            }
        }

        /** Distance from the centre to a side (mm). */
        public double apothemMm() {
            double r = diameterMm / 2;
            return circumscribed ? r : r * Math.cos(Math.PI / sides);
        }

        /** Distance from the centre to a vertex (mm): eq. 22 when circumscribed. */
        public double vertexRadiusMm() {
            double r = diameterMm / 2;
            return circumscribed ? Math.sqrt(r * r + Math.pow(r * Math.tan(Math.PI / sides), 2)) : r;
        }

        @Override
        public Contour contour(Tolerance tol) {
            return new Contour(inset(0, tol).orElseThrow().curves());
        }

        @Override
        public Optional<Ring> inset(double d, Tolerance tol) {
            double a = apothemMm() - d;
            if (a < -tol.linear()) {
                return Optional.empty();
            }
            if (a <= tol.linear()) {
                return Optional.of(new Ring(center, List.of()));
            }
            double rv = a / Math.cos(Math.PI / sides);
            Vec2 s = center.plus(new Vec2(0, -a));
            List<Curve2> c = new ArrayList<>();
            Vec2 at = s;
            for (int k = 0; k < sides; k++) {
                double ang = -Math.PI / 2 + Math.PI / sides + 2 * Math.PI * k / sides;
                Vec2 v = center.plus(Vec2.ofAngle(ang).times(rv));
                c.add(new Segment2(at, v));
                at = v;
            }
            c.add(new Segment2(at, s));
            return Optional.of(new Ring(s, c));
        }

        @Override
        public double sharpCornerAngleRad(double dMm) {
            return Math.PI - 2 * Math.PI / sides;
        }

        @Override
        public double maxInsetMm() {
            return apothemMm();
        }
    }

    /** Any closed contour of lines and arcs, offset by the given engine. */
    record General(Contour outline, ContourOffsetter offsetter) implements Profile {
        @Override
        public Contour contour(Tolerance tol) {
            return outline.ccw();
        }

        @Override
        public Optional<Ring> inset(double d, Tolerance tol) {
            List<Contour> off = offsetter.inward(outline.ccw(), d, tol);
            if (off.isEmpty()) {
                return Optional.empty();
            }
            Contour c = off.get(0);
            return Optional.of(new Ring(c.get(0).start(), c.curves()));
        }

        @Override
        public List<Ring> insetAll(double d, Tolerance tol) {
            List<Ring> out = new ArrayList<>();
            for (Contour c : offsetter.inward(outline.ccw(), d, tol)) {
                out.add(new Ring(c.get(0).start(), c.curves()));
            }
            return out;
        }

        @Override
        public double sharpCornerAngleRad(double dMm) {
            double min = Math.PI;
            List<Curve2> cs = outline.ccw().curves();
            for (int i = 0; i < cs.size(); i++) {
                Vec2 t1 = cs.get(i).endTangent();
                Vec2 t2 = cs.get((i + 1) % cs.size()).startTangent();
                double turn = Math.atan2(t1.cross(t2), t1.dot(t2));
                if (turn > 1e-9) {
                    min = Math.min(min, Math.PI - turn);
                }
            }
            return min;
        }

        @Override
        public Vec2 center() {
            return outline.bounds().center();
        }

        @Override
        public double maxInsetMm() {
            return Double.NaN;
        }

        /** Convex when it turns left at every joint and has no clockwise arc (run counter-clockwise). */
        @Override
        public boolean convex() {
            List<Curve2> cs = outline.ccw().curves();
            for (int i = 0; i < cs.size(); i++) {
                if (cs.get(i) instanceof Arc2 a && !a.ccw()) {
                    return false;
                }
                Vec2 t1 = cs.get(i).endTangent();
                Vec2 t2 = cs.get((i + 1) % cs.size()).startTangent();
                if (t1.cross(t2) < -1e-12) {
                    return false;
                }
            }
            return true;
        }
    }

    private static Vec2 line(List<Curve2> c, Vec2 from, Vec2 to) {
        if (from.distance(to) > 0) {
            c.add(new Segment2(from, to));
        }
        return to;
    }
}
