package org.fresa.pocket;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;

/**
 * A level cut of an adaptive program fed below both programmed feeds: where {@link EngagementFeed}
 * slowed a stretch the walks could not hold at the stepover, or the link into it. Read back from
 * the program's own moves, so that what the planner reviews is what the machine runs.
 *
 * @param zMm the depth layer
 * @param curve the cut in the plane, a line or an arc as programmed
 * @param feedMmPerMin its feed
 */
public record SlowedMove(double zMm, Curve2 curve, double feedMmPerMin) {

    public SlowedMove {
        Objects.requireNonNull(curve, "curve");
    }

    /** The fraction of the programmed feed. */
    public double factor(double feedMmPerMin) {
        return this.feedMmPerMin / feedMmPerMin;
    }

    /** The section's level feed moves at neither of its programmed feeds, in program order. */
    public static List<SlowedMove> of(ToolpathSection s, double feedMmPerMin, double finishFeedMmPerMin) {
        List<SlowedMove> out = new ArrayList<>();
        Vec3 at = s.start();
        for (Move m : s.moves()) {
            double f = m instanceof Move.Linear l
                    ? l.feedMmPerMin()
                    : m instanceof Move.Circular c ? c.feedMmPerMin() : Double.NaN;
            boolean level = Math.abs(m.end().z() - at.z()) < 1e-9;
            if (level && !Double.isNaN(f) && f != feedMmPerMin && f != finishFeedMmPerMin) {
                Vec2 a = at.xy();
                Vec2 b = m.end().xy();
                if (m instanceof Move.Circular c && c.turns() == 0 && c.normal().z() != 0) {
                    out.add(new SlowedMove(
                            at.z(),
                            new Arc2(
                                    c.center().xy(),
                                    a,
                                    b,
                                    c.ccw() == (c.normal().z() > 0)),
                            f));
                } else if (!a.equals(b)) {
                    out.add(new SlowedMove(at.z(), new Segment2(a, b), f));
                }
            }
            at = m.end();
        }
        return out;
    }
}
