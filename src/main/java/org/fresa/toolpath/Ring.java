package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;

/**
 * A closed tool-centre loop in the feature plane: its curves in order from {@link #start()} back
 * to it. A collapsed loop (an offset that shrank to a segment or a point) is allowed: a segment
 * is run there and back, a point has no curves.
 *
 * @param start the first and last point (mm)
 * @param curves the loop, each curve ending where the next begins; empty for a point
 */
public record Ring(Vec2 start, List<Curve2> curves) {

    public Ring {
        curves = List.copyOf(curves);
    }

    /** The same loop run the other way from the same start. */
    public Ring reversed() {
        List<Curve2> list = new ArrayList<>(curves.size());
        for (int i = curves.size() - 1; i >= 0; i--) {
            list.add(curves.get(i).reversed());
        }
        return new Ring(start, list);
    }

    public double length() {
        double l = 0;
        for (Curve2 c : curves) {
            l += c.length();
        }
        return l;
    }

    public boolean isPoint() {
        return curves.isEmpty();
    }
}
