package org.fresa.sole;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;

/** The two-circle waves of SUB5A/B/E. */
final class Waves {
    private Waves() {}

    /**
     * Circle 1 (centre PC1 through PTAN) from x = XA5 to PTAN, circle 2 forward; with n copies
     * shifted by afas: circle 2 of pair I-1 runs on to where it meets circle 1 of pair I (to the
     * line x = XB5 + I afas when that is where they meet), and the last circle 2 ends at
     * x = XB5 + n afas.
     */
    static List<Curve2> wave(
            double xc1,
            double yc1,
            double xc2,
            double yc2,
            double xt,
            double yt,
            double xa5,
            double xb5,
            double afas,
            int n,
            boolean ccw,
            Tolerance tol,
            String macro) {
        List<Curve2> out = new ArrayList<>();
        Vec2 pc1 = Vec2.of(xc1, yc1);
        Vec2 pt = Vec2.of(xt, yt);
        double r1 = pc1.distance(pt);
        double endX = xb5 + n * afas;
        Vec2 s = CircleWalk.startAtX(pc1, r1, xa5, endX, ccw, tol, macro);
        Vec2 p = s;
        boolean sense = ccw;
        Vec2 heading = null;
        for (int i = 0; i <= n; i++) {
            Vec2 off = Vec2.of(i * afas, 0);
            Vec2 c1 = pc1.plus(off);
            Vec2 c2 = Vec2.of(xc2, yc2).plus(off);
            Vec2 tan = pt.plus(off);
            if (i > 0) {
                if (Math.abs(c1.distance(p) - r1) > 1e-6) {
                    throw new IllegalArgumentException(macro + ": the wave does not reach circle 1 of copy " + i);
                }
                sense = CircleWalk.nextSense(heading, c1, p, true);
            }
            Arc2 a1 = CircleWalk.arc(c1, p, tan, sense);
            out.add(a1);
            heading = a1.endTangent();
            double r2 = c2.distance(tan);
            boolean s2 = CircleWalk.nextSense(heading, c2, tan, true);
            Arc2 a2;
            if (i < n && afas != 0) {
                Vec2 nextC1 = pc1.plus(Vec2.of((i + 1) * afas, 0));
                a2 = CircleWalk.toCircle(c2, tan, s2, nextC1, r1, tol, macro);
            } else {
                a2 = CircleWalk.toX(c2, r2, tan, s2, xb5 + i * afas, tol, macro);
            }
            out.add(a2);
            heading = a2.endTangent();
            p = a2.end();
        }
        return out;
    }
}
