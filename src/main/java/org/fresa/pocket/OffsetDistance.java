package org.fresa.pocket;

import java.util.List;
import org.fresa.geom.Box2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;

/** Whether a point is closer than a distance to a set of curves, with box rejection. */
final class OffsetDistance {
    private final List<Curve2> curves;
    private final Box2[] boxes;

    OffsetDistance(List<Curve2> curves) {
        this.curves = curves;
        this.boxes = new Box2[curves.size()];
        for (int i = 0; i < boxes.length; i++) {
            boxes[i] = curves.get(i).bounds();
        }
    }

    boolean closerThan(Vec2 p, double d) {
        for (int i = 0; i < boxes.length; i++) {
            Box2 b = boxes[i];
            double dx = Math.max(0, Math.max(b.minX() - p.x(), p.x() - b.maxX()));
            double dy = Math.max(0, Math.max(b.minY() - p.y(), p.y() - b.maxY()));
            if (dx >= d || dy >= d || dx * dx + dy * dy >= d * d) {
                continue;
            }
            if (curves.get(i).distanceTo(p) < d) {
                return true;
            }
        }
        return false;
    }

    double distance(Vec2 p) {
        double best = Double.POSITIVE_INFINITY;
        for (Curve2 c : curves) {
            best = Math.min(best, c.distanceTo(p));
        }
        return best;
    }
}
