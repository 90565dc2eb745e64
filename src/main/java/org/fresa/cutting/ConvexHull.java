package org.fresa.cutting;

import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;

/**
 * A counter-clockwise convex polygon held as coordinate arrays, with the length of each edge
 * worked out once: the rapid router's obstacles. Fenced fast path: the router makes two hulls for
 * every part cut free and tests every rapid against them, and with a point record per vertex and
 * a comparator sort the hulls alone took 30 s of the 150 s CPU of the 181 750-part sheet
 * ({@code job.SquareSheet}) and a fifth of its garbage; as arrays sorted in place they take
 * under 3 s. The arithmetic is that of the {@link Vec2} operations it replaces, term for term, so
 * every hull, and every route, is the same to the last bit.
 */
final class ConvexHull {
    private static final double EPS = 1e-7;

    private final double[] xs;
    private final double[] ys;
    /** Length of the edge from vertex i to vertex i + 1 (mm). */
    private final double[] edgeMm;

    private ConvexHull(double[] xs, double[] ys, int n) {
        this.xs = java.util.Arrays.copyOf(xs, n);
        this.ys = java.util.Arrays.copyOf(ys, n);
        this.edgeMm = new double[n];
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            edgeMm[i] = Math.hypot(xs[j] - xs[i], ys[j] - ys[i]);
        }
    }

    int size() {
        return xs.length;
    }

    double x(int i) {
        return xs[i];
    }

    double y(int i) {
        return ys[i];
    }

    Vec2 vertex(int i) {
        return new Vec2(xs[i], ys[i]);
    }

    Vec2[] vertices() {
        Vec2[] v = new Vec2[xs.length];
        for (int i = 0; i < v.length; i++) {
            v[i] = vertex(i);
        }
        return v;
    }

    Box2 box() {
        double x0 = Double.POSITIVE_INFINITY;
        double y0 = Double.POSITIVE_INFINITY;
        double x1 = Double.NEGATIVE_INFINITY;
        double y1 = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < xs.length; i++) {
            x0 = Math.min(x0, xs[i]);
            y0 = Math.min(y0, ys[i]);
            x1 = Math.max(x1, xs[i]);
            y1 = Math.max(y1, ys[i]);
        }
        return new Box2(x0, y0, x1, y1);
    }

    /** The hull of a cut path, its arcs by circumscribed polygons of 10 degree steps. */
    static ConvexHull ofPath(Contour path) {
        Points p = new Points(4 * path.size() + 8);
        for (Curve2 c : path.curves()) {
            p.add(c.start());
            if (c instanceof Arc2 a && a.radius() > 0) {
                double sweep = a.sweepRad();
                int n = Math.max(1, (int) Math.ceil(Math.abs(sweep) / Math.toRadians(10)));
                double grow = 1 / Math.cos(Math.abs(sweep) / n / 2); // circumscribed: the hull holds the arc
                double r = a.radius() * grow;
                double cx = a.center().x();
                double cy = a.center().y();
                for (int k = 0; k < n; k++) {
                    double ang = a.startAngleRad() + sweep * (k + 0.5) / n;
                    p.add(cx + Math.cos(ang) * r, cy + Math.sin(ang) * r);
                }
            }
            p.add(c.end());
        }
        return p.hull();
    }

    /** The hull of the points around each vertex at the given offsets: the hull grown by the clearance. */
    ConvexHull grown(double[] dx, double[] dy) {
        Points p = new Points(dx.length * xs.length);
        for (int i = 0; i < xs.length; i++) {
            for (int k = 0; k < dx.length; k++) {
                p.add(xs[i] + dx[k], ys[i] + dy[k]);
            }
        }
        return p.hull();
    }

    /** The hull of points (Andrew's monotone chain: counter-clockwise, without collinear points). */
    static ConvexHull of(Iterable<Vec2> points) {
        Points p = new Points(16);
        for (Vec2 v : points) {
            p.add(v);
        }
        return p.hull();
    }

    /** True when the segment a-b passes through the open interior of the polygon. */
    boolean crosses(Vec2 a, Vec2 b) {
        return crosses(a.x(), a.y(), b.x(), b.y());
    }

    boolean crosses(double ax, double ay, double bx, double by) {
        double t0 = 0;
        double t1 = 1;
        double abx = bx - ax;
        double aby = by - ay;
        int n = xs.length;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double ex = xs[j] - xs[i];
            double ey = ys[j] - ys[i];
            double len = edgeMm[i];
            double f0 = (ex * (ay - ys[i]) - ey * (ax - xs[i])) / len - EPS; // > 0 inside
            double df = (ex * aby - ey * abx) / len;
            if (df == 0) {
                if (f0 <= 0) {
                    return false;
                }
            } else {
                double t = -f0 / df;
                if (df > 0) {
                    t0 = Math.max(t0, t);
                } else {
                    t1 = Math.min(t1, t);
                }
                if (t1 - t0 <= 1e-12) {
                    return false;
                }
            }
        }
        return (t1 - t0) * Math.hypot(abx, aby) > EPS;
    }

    /** True when p lies inside the polygon, more than the tolerance from every edge. */
    boolean inside(Vec2 p) {
        int n = xs.length;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double ex = xs[j] - xs[i];
            double ey = ys[j] - ys[i];
            if ((ex * (p.y() - ys[i]) - ey * (p.x() - xs[i])) / edgeMm[i] <= EPS) {
                return false;
            }
        }
        return true;
    }

    /** A growing list of points as two coordinate arrays. */
    private static final class Points {
        private double[] x;
        private double[] y;
        private int n;

        Points(int capacity) {
            x = new double[Math.max(4, capacity)];
            y = new double[x.length];
        }

        void add(Vec2 p) {
            add(p.x(), p.y());
        }

        void add(double px, double py) {
            if (n == x.length) {
                x = java.util.Arrays.copyOf(x, 2 * n);
                y = java.util.Arrays.copyOf(y, 2 * n);
            }
            x[n] = px;
            y[n] = py;
            n++;
        }

        ConvexHull hull() {
            int[] order = new int[n];
            for (int i = 0; i < n; i++) {
                order[i] = i;
            }
            // by x, then y, as Double.compare orders them; equal points are equal values, so the
            // order among them does not matter
            sort(order, new int[n], 0, n);
            if (n < 3) {
                double[] hx = new double[n];
                double[] hy = new double[n];
                for (int i = 0; i < n; i++) {
                    hx[i] = x[order[i]];
                    hy[i] = y[order[i]];
                }
                return new ConvexHull(hx, hy, n);
            }
            double[] hx = new double[2 * n];
            double[] hy = new double[2 * n];
            int k = 0;
            for (int i = 0; i < n; i++) {
                double px = x[order[i]];
                double py = y[order[i]];
                while (k >= 2 && turn(hx, hy, k, px, py) <= 0) {
                    k--;
                }
                hx[k] = px;
                hy[k++] = py;
            }
            for (int i = n - 2, lower = k + 1; i >= 0; i--) {
                double px = x[order[i]];
                double py = y[order[i]];
                while (k >= lower && turn(hx, hy, k, px, py) <= 0) {
                    k--;
                }
                hx[k] = px;
                hy[k++] = py;
            }
            return new ConvexHull(hx, hy, k - 1);
        }

        /** (h[k-1] - h[k-2]) x (p - h[k-2]), as Vec2 works it out. */
        private static double turn(double[] hx, double[] hy, int k, double px, double py) {
            double ux = hx[k - 1] - hx[k - 2];
            double uy = hy[k - 1] - hy[k - 2];
            double vx = px - hx[k - 2];
            double vy = py - hy[k - 2];
            return ux * vy - uy * vx;
        }

        private int compare(int i, int j) {
            int c = Double.compare(x[i], x[j]);
            return c != 0 ? c : Double.compare(y[i], y[j]);
        }

        /** Merge sort of order[from, to) by point. */
        private void sort(int[] order, int[] tmp, int from, int to) {
            if (to - from <= 12) {
                for (int i = from + 1; i < to; i++) {
                    int v = order[i];
                    int j = i - 1;
                    while (j >= from && compare(order[j], v) > 0) {
                        order[j + 1] = order[j];
                        j--;
                    }
                    order[j + 1] = v;
                }
                return;
            }
            int mid = (from + to) >>> 1;
            sort(order, tmp, from, mid);
            sort(order, tmp, mid, to);
            if (compare(order[mid - 1], order[mid]) <= 0) {
                return;
            }
            System.arraycopy(order, from, tmp, from, to - from);
            int i = from;
            int j = mid;
            for (int k = from; k < to; k++) {
                if (j >= to || i < mid && compare(tmp[i], tmp[j]) <= 0) {
                    order[k] = tmp[i++];
                } else {
                    order[k] = tmp[j++];
                }
            }
        }
    }
}
