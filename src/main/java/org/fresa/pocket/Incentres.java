package org.fresa.pocket;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Vec2;

/**
 * Points equidistant (in the offset sense t) from three elements: the thesis's incentres (§6.2),
 * all eight line/circle combinations. Lines give linear equations {@code A·x + B·y - k·t = D};
 * differences of two circles are linear too (k² = 1), so at most one circle stays quadratic and
 * the system reduces to one quadratic in one unknown (the thesis's CRR reduction).
 */
public final class Incentres {
    private Incentres() {}

    /**
     * A solution: the offset t and the point.
     *
     * @param t absolute offset (mm)
     * @param point the incentre
     */
    public record Solution(double t, Vec2 point) {}

    /** Every real solution (0, 1 or 2; more only in degenerate cases), in increasing t. */
    public static List<Solution> of(PocketElement e1, PocketElement e2, PocketElement e3) {
        List<PocketElement> es = List.of(e1, e2, e3);
        PocketElement c0 = null;
        for (PocketElement e : es) {
            if (e.arc()) {
                c0 = e;
                break;
            }
        }
        List<double[]> rows = new ArrayList<>();
        for (PocketElement e : es) {
            if (!e.arc()) {
                rows.add(new double[] {e.a(), e.b(), -e.k(), e.d()});
            } else if (e != c0) {
                rows.add(new double[] {
                    -2 * (e.a() - c0.a()),
                    -2 * (e.b() - c0.b()),
                    -2 * (e.d() * e.k() - c0.d() * c0.k()),
                    -(e.a() * e.a() + e.b() * e.b() - c0.a() * c0.a() - c0.b() * c0.b())
                            + e.d() * e.d()
                            - c0.d() * c0.d()
                });
            }
        }
        List<Solution> out = new ArrayList<>();
        if (c0 == null) {
            double[] r1 = rows.get(0), r2 = rows.get(1), r3 = rows.get(2);
            double det = det3(r1[0], r1[1], r1[2], r2[0], r2[1], r2[2], r3[0], r3[1], r3[2]);
            if (Math.abs(det) < 1e-12) {
                return out;
            }
            double x = det3(r1[3], r1[1], r1[2], r2[3], r2[1], r2[2], r3[3], r3[1], r3[2]) / det;
            double y = det3(r1[0], r1[3], r1[2], r2[0], r2[3], r2[2], r3[0], r3[3], r3[2]) / det;
            double t = det3(r1[0], r1[1], r1[3], r2[0], r2[1], r2[3], r3[0], r3[1], r3[3]) / det;
            out.add(new Solution(t, new Vec2(x, y)));
            return out;
        }
        double[] r1 = rows.get(0), r2 = rows.get(1);
        // pick the free unknown whose complementary 2x2 system is best conditioned
        int[][] pairs = {{0, 1, 2}, {0, 2, 1}, {1, 2, 0}};
        int[] best = null;
        double bestDet = 0;
        for (int[] p : pairs) {
            double det = r1[p[0]] * r2[p[1]] - r1[p[1]] * r2[p[0]];
            if (Math.abs(det) > Math.abs(bestDet)) {
                bestDet = det;
                best = p;
            }
        }
        if (best == null || Math.abs(bestDet) < 1e-12) {
            return out;
        }
        int i = best[0], j = best[1], f = best[2];
        // r1[i] vi + r1[j] vj = r1[3] - r1[f] u ; same for r2
        double[] m = new double[3];
        double[] n = new double[3];
        m[f] = 1;
        n[f] = 0;
        m[i] = (-r1[f] * r2[j] + r2[f] * r1[j]) / bestDet;
        n[i] = (r1[3] * r2[j] - r2[3] * r1[j]) / bestDet;
        m[j] = (-r1[i] * r2[f] + r2[i] * r1[f]) / bestDet;
        n[j] = (r1[i] * r2[3] - r2[i] * r1[3]) / bestDet;
        double a0 = c0.a(), b0 = c0.b(), rr = c0.d(), k0 = c0.k();
        double qa = m[0] * m[0] + m[1] * m[1] - m[2] * m[2];
        double qb = 2 * (m[0] * (n[0] - a0) + m[1] * (n[1] - b0) - k0 * m[2] * (rr + k0 * n[2]));
        double qc = (n[0] - a0) * (n[0] - a0) + (n[1] - b0) * (n[1] - b0) - (rr + k0 * n[2]) * (rr + k0 * n[2]);
        List<Double> us = new ArrayList<>();
        double scale = Math.abs(qb) + Math.abs(qc) + 1;
        if (Math.abs(qa) < 1e-12 * scale) {
            if (Math.abs(qb) > 1e-15) {
                us.add(-qc / qb);
            }
        } else {
            double disc = qb * qb - 4 * qa * qc;
            if (disc < 0 && disc > -1e-9 * qb * qb) {
                disc = 0;
            }
            if (disc >= 0) {
                double sq = Math.sqrt(disc);
                // numerically stable pair of roots
                double q = -0.5 * (qb + Math.copySign(sq, qb));
                if (q != 0) {
                    us.add(q / qa);
                    us.add(qc / q);
                } else {
                    us.add(0.0);
                }
            }
        }
        for (double u : us) {
            double x = m[0] * u + n[0], y = m[1] * u + n[1], t = m[2] * u + n[2];
            out.add(new Solution(t, new Vec2(x, y)));
        }
        out.sort((p, q) -> Double.compare(p.t(), q.t()));
        return out;
    }

    private static double det3(
            double a, double b, double c, double d, double e, double f, double g, double h, double i) {
        return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
    }
}
