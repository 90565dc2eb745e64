package org.fresa.pocket;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;

/** Splitting a line or arc at points that lie on it, for {@link LineArcOffsetter}. */
final class OffsetSplit {
    private OffsetSplit() {}

    /** The fraction (0 at start, 1 at end) of the point of c nearest p. */
    static double param(Curve2 c, Vec2 p) {
        if (c instanceof Segment2 s) {
            Vec2 d = s.direction();
            return p.minus(s.start()).dot(d) / d.dot(d);
        }
        Arc2 a = (Arc2) c;
        double sweep = a.sweepRad();
        double ang = Math.atan2(p.minus(a.center()).y(), p.minus(a.center()).x()) - a.startAngleRad();
        double twoPi = 2 * Math.PI;
        if (sweep > 0) {
            ang = ((ang % twoPi) + twoPi) % twoPi;
            if (ang > sweep + 0.5 * (twoPi - sweep)) {
                ang -= twoPi;
            }
            return ang / sweep;
        }
        ang = ((-ang % twoPi) + twoPi) % twoPi;
        if (ang > -sweep + 0.5 * (twoPi + sweep)) {
            ang -= twoPi;
        }
        return ang / -sweep;
    }

    static void splitAt(Curve2 c, List<Vec2> points, double eps, List<Curve2> out) {
        if (points.isEmpty()) {
            out.add(c);
            return;
        }
        double len = c.length();
        List<double[]> ts = new ArrayList<>();
        for (Vec2 p : points) {
            double t = param(c, p);
            if (t * len > eps && (1 - t) * len > eps) {
                ts.add(new double[] {t, p.x(), p.y()});
            }
        }
        ts.sort((x, y) -> Double.compare(x[0], y[0]));
        Vec2 prev = c.start();
        double prevT = 0;
        for (double[] t : ts) {
            if ((t[0] - prevT) * len <= eps) {
                continue;
            }
            Vec2 p = new Vec2(t[1], t[2]);
            out.add(piece(c, prev, p));
            prev = p;
            prevT = t[0];
        }
        out.add(piece(c, prev, c.end()));
    }

    private static Curve2 piece(Curve2 c, Vec2 a, Vec2 b) {
        if (c instanceof Segment2) {
            return new Segment2(a, b);
        }
        Arc2 arc = (Arc2) c;
        return new Arc2(arc.center(), a, b, arc.ccw());
    }
}
