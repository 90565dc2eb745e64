package org.fresa.geom;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.function.ToDoubleFunction;

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
        return sumOverCurves(Curve2::areaContribution);
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
        return sumOverCurves(Curve2::length);
    }

    /** A quantity summed over the curves in the order of travel. */
    private double sumOverCurves(ToDoubleFunction<Curve2> quantity) {
        double sum = 0;
        for (Curve2 c : curves) {
            sum += quantity.applyAsDouble(c);
        }
        return sum;
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

    /**
     * The winding number of the contour about p (p must not lie on the contour): the signed
     * count of crossings of the ray from p towards +x, upward crossings positive. Arcs are split
     * where they turn in y, so each piece crosses the ray at most once.
     */
    public int windingNumber(Vec2 p) {
        int w = 0;
        for (Curve2 c : curves) {
            if (c instanceof Segment2 s) {
                w += crossing(s.start(), s.end(), p, null, false);
            } else {
                w += arcCrossings((Arc2) c, p);
            }
        }
        return w;
    }

    /**
     * +1 for an upward crossing of the ray y = p.y, x > p.x, -1 for downward, 0 for none, for a
     * piece from a to b that is monotone in y: a segment (center null) or an arc piece about
     * center on the half of the circle given by rightHalf. Half-open in y (a.y <= p.y < b.y
     * upward, b.y <= p.y < a.y downward) so that a vertex is counted once.
     */
    private static int crossing(Vec2 a, Vec2 b, Vec2 p, Vec2 center, boolean rightHalf) {
        boolean up = a.y() <= p.y() && p.y() < b.y();
        boolean down = b.y() <= p.y() && p.y() < a.y();
        if (!up && !down) {
            return 0;
        }
        double x;
        if (center == null) {
            x = a.x() + (p.y() - a.y()) / (b.y() - a.y()) * (b.x() - a.x());
        } else {
            double r = center.distance(a);
            double dy = p.y() - center.y();
            double dx = Math.sqrt(Math.max(0, r * r - dy * dy));
            x = rightHalf ? center.x() + dx : center.x() - dx;
        }
        if (x <= p.x()) {
            return 0;
        }
        return up ? 1 : -1;
    }

    private static int arcCrossings(Arc2 a, Vec2 p) {
        double r = a.radius();
        if (r == 0) {
            return 0;
        }
        double start = a.startAngleRad();
        double sweep = a.sweepRad();
        // split points: the angles pi/2 and -pi/2 (top and bottom) inside the sweep
        double[] cuts = new double[8];
        int n = 0;
        for (int m = -4; m <= 4; m++) {
            double t = (Math.PI / 2 + m * Math.PI - start) / sweep;
            if (t > 0 && t < 1 && n < cuts.length && !containsValue(cuts, n, t)) {
                cuts[n++] = t;
            }
        }
        java.util.Arrays.sort(cuts, 0, n);
        int w = 0;
        double t0 = 0;
        Vec2 from = a.start();
        for (int i = 0; i <= n; i++) {
            double t1 = i < n ? cuts[i] : 1;
            Vec2 to = i < n ? a.center().plus(Vec2.ofAngle(start + sweep * t1).times(r)) : a.end();
            double mid = start + sweep * (t0 + t1) / 2;
            boolean right = Math.cos(mid) > 0;
            w += crossing(from, to, p, a.center(), right);
            from = to;
            t0 = t1;
        }
        return w;
    }

    private static boolean containsValue(double[] a, int n, double v) {
        for (int i = 0; i < n; i++) {
            if (Math.abs(a[i] - v) < 1e-15) {
                return true;
            }
        }
        return false;
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
