package org.fresa.grading;

import java.util.Optional;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;

/**
 * The thesis's way of rebuilding arcs after grading (eq. 4.3): a circle through three graded
 * points (APT {@code CIRCLE/P1,P2,P3}), or through two points with a fixed radius and a choice of
 * centre ({@code CIRCLE/P1,P2,XLARGE,RADIUS,R}).
 */
public final class ThreePointArcs {

    /** Which of the two centres of a circle through two points with a given radius. */
    public enum CenterChoice {
        /** the centre with the larger x */
        XLARGE,
        /** the centre with the smaller x */
        XSMALL,
        /** the centre with the larger y */
        YLARGE,
        /** the centre with the smaller y */
        YSMALL
    }

    private ThreePointArcs() {}

    /** The centre of the circle through three points; empty when they are collinear. */
    public static Optional<Vec2> circumcenter(Vec2 a, Vec2 b, Vec2 c) {
        Vec2 ab = b.minus(a);
        Vec2 ac = c.minus(a);
        double d = 2 * ab.cross(ac);
        double scale = Math.max(ab.dot(ab), ac.dot(ac));
        if (Math.abs(d) <= 1e-14 * scale) {
            return Optional.empty();
        }
        double ab2 = ab.dot(ab);
        double ac2 = ac.dot(ac);
        double ux = (ac.y() * ab2 - ab.y() * ac2) / d;
        double uy = (ab.x() * ac2 - ac.x() * ab2) / d;
        return Optional.of(a.plus(new Vec2(ux, uy)));
    }

    /**
     * The arc from a through m to b (counter-clockwise when a, m, b turn left), or the segment a-b
     * when the three points are collinear.
     */
    public static Curve2 arc(Vec2 a, Vec2 m, Vec2 b) {
        Optional<Vec2> c = circumcenter(a, m, b);
        if (c.isEmpty()) {
            return new Segment2(a, b);
        }
        boolean ccw = m.minus(a).cross(b.minus(m)) > 0;
        return new Arc2(c.get(), a, b, ccw);
    }

    /**
     * The two centres of circles of the given radius through a and b.
     *
     * @throws IllegalArgumentException when the points are further apart than the diameter
     */
    public static Vec2[] centers(Vec2 a, Vec2 b, double radiusMm) {
        double chord = a.distance(b);
        if (!(chord > 0) || chord > 2 * radiusMm) {
            throw new IllegalArgumentException(
                    "no circle of radius " + radiusMm + " through points " + chord + " mm apart");
        }
        Vec2 mid = a.interpolate(b, 0.5);
        double h = Math.sqrt(radiusMm * radiusMm - chord * chord / 4);
        Vec2 n = b.minus(a).normalized().leftNormal().times(h);
        return new Vec2[] {mid.plus(n), mid.minus(n)};
    }

    /** The centre picked by the thesis's modifier. */
    public static Vec2 center(Vec2 a, Vec2 b, double radiusMm, CenterChoice choice) {
        Vec2[] c = centers(a, b, radiusMm);
        boolean first = switch (choice) {
            case XLARGE -> c[0].x() >= c[1].x();
            case XSMALL -> c[0].x() <= c[1].x();
            case YLARGE -> c[0].y() >= c[1].y();
            case YSMALL -> c[0].y() <= c[1].y();
        };
        return first ? c[0] : c[1];
    }

    /** The shorter arc from a to b about the chosen centre of the given radius. */
    public static Arc2 arc(Vec2 a, Vec2 b, double radiusMm, CenterChoice choice) {
        Vec2 c = center(a, b, radiusMm, choice);
        boolean ccw = a.minus(c).cross(b.minus(c)) > 0;
        return new Arc2(c, a, b, ccw);
    }
}
