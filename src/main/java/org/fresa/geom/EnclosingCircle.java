package org.fresa.geom;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;

/**
 * The smallest circle that holds a set of points (Welzl's incremental construction, the points
 * taken in a fixed shuffled order so that the result and its cost do not depend on how the
 * caller ordered them).
 */
public final class EnclosingCircle {

    private static final double SLACK_MM = 1e-9;

    private EnclosingCircle() {}

    /** The radius of the smallest circle holding every point (mm); 0 for none or one point. */
    public static double radiusMm(List<Vec2> points) {
        if (points.size() < 2) {
            return 0;
        }
        List<Vec2> p = new ArrayList<>(points);
        Collections.shuffle(p, new Random(1));
        Vec2 c = p.get(0);
        double r = 0;
        for (int i = 1; i < p.size(); i++) {
            if (c.distance(p.get(i)) <= r + SLACK_MM) {
                continue;
            }
            c = p.get(i);
            r = 0;
            for (int j = 0; j < i; j++) {
                if (c.distance(p.get(j)) <= r + SLACK_MM) {
                    continue;
                }
                c = p.get(i).plus(p.get(j)).times(0.5);
                r = p.get(i).distance(c);
                for (int k = 0; k < j; k++) {
                    if (c.distance(p.get(k)) <= r + SLACK_MM) {
                        continue;
                    }
                    Vec2 o = circumcentre(p.get(i), p.get(j), p.get(k));
                    if (o == null) {
                        // three points on a line: the circle on the two farthest apart
                        Vec2[] t = {p.get(i), p.get(j), p.get(k)};
                        double best = -1;
                        for (int a = 0; a < 3; a++) {
                            for (int b = a + 1; b < 3; b++) {
                                if (t[a].distance(t[b]) > best) {
                                    best = t[a].distance(t[b]);
                                    o = t[a].plus(t[b]).times(0.5);
                                }
                            }
                        }
                    }
                    c = o;
                    r = Math.max(c.distance(p.get(i)), Math.max(c.distance(p.get(j)), c.distance(p.get(k))));
                }
            }
        }
        return r;
    }

    private static Vec2 circumcentre(Vec2 a, Vec2 b, Vec2 c) {
        double bx = b.x() - a.x();
        double by = b.y() - a.y();
        double cx = c.x() - a.x();
        double cy = c.y() - a.y();
        double d = 2 * (bx * cy - by * cx);
        if (Math.abs(d) < 1e-18) {
            return null;
        }
        double b2 = bx * bx + by * by;
        double c2 = cx * cx + cy * cy;
        return new Vec2(a.x() + (cy * b2 - by * c2) / d, a.y() + (bx * c2 - cx * b2) / d);
    }
}
