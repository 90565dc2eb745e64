package org.fresa.geom;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * A closed chain of lines and arcs: each curve ends where the next starts, and the last ends
 * where the first starts. The curves are the truth: area, orientation and containment are exact
 * for arcs (no polygonal approximation).
 *
 * @param curves the elements in order of travel, at least one
 */
public record Contour(List<Curve2> curves) {

    public Contour {
        curves = List.copyOf(Objects.requireNonNull(curves, "curves"));
        if (curves.isEmpty()) {
            throw new IllegalArgumentException("a contour needs at least one curve");
        }
    }

    /**
     * A contour from curves that must join within tol.linear() (each end to the next start, the
     * last end to the first start).
     *
     * @throws IllegalArgumentException naming the first gap larger than the tolerance
     */
    public static Contour of(List<? extends Curve2> curves, Tolerance tol) {
        List<Curve2> list = List.copyOf(curves);
        for (int i = 0; i < list.size(); i++) {
            Curve2 a = list.get(i);
            Curve2 b = list.get((i + 1) % list.size());
            double gap = a.end().distance(b.start());
            if (gap > tol.linear()) {
                throw new IllegalArgumentException("contour is open between element " + (i + 1) + " and "
                        + ((i + 1) % list.size() + 1) + ": gap " + gap + " mm");
            }
        }
        return new Contour(list);
    }

    /** A closed polygon through the given points. */
    public static Contour polygon(List<Vec2> points) {
        if (points.size() < 3) {
            throw new IllegalArgumentException("a polygon needs at least 3 points: " + points.size());
        }
        List<Curve2> list = new ArrayList<>();
        for (int i = 0; i < points.size(); i++) {
            list.add(new Segment2(points.get(i), points.get((i + 1) % points.size())));
        }
        return new Contour(list);
    }

    public int size() {
        return curves.size();
    }

    public Curve2 get(int index) {
        return curves.get(index);
    }

    /** The enclosed area in mm^2, positive for a counter-clockwise contour. */
    public double signedArea() {
        double a = 0;
        for (Curve2 c : curves) {
            a += c.areaContribution();
        }
        return a;
    }

    public double area() {
        return Math.abs(signedArea());
    }

    public boolean isCcw() {
        return signedArea() > 0;
    }

    /** The same contour run the other way, starting at the old last curve's end. */
    public Contour reversed() {
        List<Curve2> list = new ArrayList<>(curves.size());
        for (int i = curves.size() - 1; i >= 0; i--) {
            list.add(curves.get(i).reversed());
        }
        return new Contour(list);
    }

    /** This contour oriented counter-clockwise (itself when it already is). */
    public Contour ccw() {
        return isCcw() ? this : reversed();
    }

    public double length() {
        double l = 0;
        for (Curve2 c : curves) {
            l += c.length();
        }
        return l;
    }

    public Box2 bounds() {
        Box2 b = curves.get(0).bounds();
        for (Curve2 c : curves) {
            b = b.union(c.bounds());
        }
        return b;
    }

    /** The distance in mm from p to the nearest point of the contour. */
    public double distanceTo(Vec2 p) {
        double d = Double.POSITIVE_INFINITY;
        for (Curve2 c : curves) {
            d = Math.min(d, c.distanceTo(p));
        }
        return d;
    }

    /**
     * Whether p lies strictly inside, by the winding number with exact arcs. Points within
     * tol.linear() of the contour count as on it, which is reported as not inside.
     */
    public boolean contains(Vec2 p, Tolerance tol) {
        if (distanceTo(p) <= tol.linear()) {
            return false;
        }
        return windingNumber(p) != 0;
    }

    /** The winding number of the contour about p (p must not lie on the contour). */
    public int windingNumber(Vec2 p) {
        double total = 0;
        for (Curve2 c : curves) {
            total += sweepSeenFrom(c, p);
        }
        return (int) Math.round(total / (2 * Math.PI));
    }

    private static double sweepSeenFrom(Curve2 c, Vec2 p) {
        if (c instanceof Segment2 s) {
            return angleBetween(s.start().minus(p), s.end().minus(p));
        }
        Arc2 a = (Arc2) c;
        // split the arc in pieces of less than a half turn so each chord angle is unambiguous
        int n = Math.max(2, (int) Math.ceil(Math.abs(a.sweepRad()) / (Math.PI / 4)));
        double sum = 0;
        Vec2 prev = a.start();
        for (int k = 1; k <= n; k++) {
            Vec2 next = k == n ? a.end() : a.pointAt((double) k / n);
            sum += angleBetween(prev.minus(p), next.minus(p));
            prev = next;
        }
        return sum;
    }

    private static double angleBetween(Vec2 u, Vec2 v) {
        return Math.atan2(u.cross(v), u.dot(v));
    }

    /** The contour moved by the vector. */
    public Contour translated(Vec2 by) {
        List<Curve2> list = new ArrayList<>(curves.size());
        for (Curve2 c : curves) {
            list.add(c.translated(by));
        }
        return new Contour(list);
    }
}
