package org.fresa.toolpath;

import java.util.List;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;

/**
 * One continuous cut at a layer's depth, in the feature plane.
 *
 * @param start where the cut begins (mm)
 * @param curves the cut, chained from start; empty for a single plunge point
 * @param joinAtDepth true when the tool may feed straight from the previous pass's end to this
 *     start without leaving the cleared region; false to lift, traverse and approach again
 */
public record Pass(Vec2 start, List<Curve2> curves, boolean joinAtDepth) {

    public Pass {
        curves = List.copyOf(curves);
    }

    public Vec2 end() {
        return curves.isEmpty() ? start : curves.get(curves.size() - 1).end();
    }
}
