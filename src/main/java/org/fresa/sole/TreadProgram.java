package org.fresa.sole;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.fresa.geom.Arc2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

/**
 * The grooves of a tread as a program: z = 0 is the insert's top face, grooves are cut at
 * z = -depth in one pass (the thesis: 2 mm at once), the tool travels at z = clearance between
 * grooves. One section per tool. Arcs are circular moves (G02/G03); a full ring is one circular
 * move back to its start.
 */
public final class TreadProgram {
    private TreadProgram() {}

    /**
     * @param grooves the tread's grooves for one size and foot, by tool
     * @param tools the tools by id
     * @param depthMm groove depth below the top face, > 0
     * @param clearanceMm height of rapid travel above the top face, > 0
     * @throws IllegalArgumentException when a groove names an unknown tool
     */
    public static Toolpath toolpath(
            List<SoleTread.ToolGrooves> grooves, Map<String, TreadTool> tools, double depthMm, double clearanceMm) {
        if (!(depthMm > 0) || !(clearanceMm > 0)) {
            throw new IllegalArgumentException("depth and clearance must be > 0");
        }
        List<ToolpathSection> sections = new ArrayList<>();
        Vec3 home = Vec3.of(0, 0, clearanceMm);
        for (SoleTread.ToolGrooves g : grooves) {
            if (g.strokes().isEmpty()) {
                continue;
            }
            TreadTool t = tools.get(g.toolId());
            if (t == null) {
                throw new IllegalArgumentException("unknown tool " + g.toolId());
            }
            List<Move> moves = new ArrayList<>();
            for (Stroke s : g.strokes()) {
                for (Vec2 v : s.via()) {
                    moves.add(new Move.Rapid(Vec3.of(v.x(), v.y(), clearanceMm)));
                }
                moves.add(new Move.Rapid(Vec3.of(s.start().x(), s.start().y(), clearanceMm)));
                moves.add(new Move.Linear(Vec3.of(s.start().x(), s.start().y(), -depthMm), t.plungeFeedMmPerMin()));
                for (Curve2 c : s.curves()) {
                    moves.add(cut(c, -depthMm, t.feedMmPerMin()));
                }
                Vec2 e = s.end();
                moves.add(new Move.Rapid(Vec3.of(e.x(), e.y(), clearanceMm)));
            }
            sections.add(new ToolpathSection(
                    "tread " + t.id(), Vec3.of(0, 0, 1), t.diameterMm(), t.number(), t.spindleRpm(), home, moves));
        }
        return new Toolpath(sections);
    }

    private static Move cut(Curve2 c, double z, double feed) {
        Vec3 end = Vec3.of(c.end().x(), c.end().y(), z);
        if (c instanceof Segment2) {
            return new Move.Linear(end, feed);
        }
        Arc2 a = (Arc2) c;
        return new Move.Circular(end, Vec3.of(a.center().x(), a.center().y(), z), Vec3.of(0, 0, 1), a.ccw(), 0, feed);
    }
}
