package org.fresa.post;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

/** Toolpaths that exercise every kind of move a post must write. */
final class SampleToolpaths {

    private SampleToolpaths() {
    }

    static Vec3 v(double x, double y, double z) {
        return new Vec3(x, y, z);
    }

    /**
     * Three sections, two tools: lines, XY arcs both ways, a three-turn helix, an arc about -Z,
     * arcs in XZ and YZ, an arc in a tilted plane (to be linearised), a section without tool
     * change.
     */
    static Toolpath mixed() {
        List<Move> a = new ArrayList<>();
        a.add(new Move.Rapid(v(10, 10, 5)));
        a.add(new Move.Linear(v(10, 10, -1), 300));
        a.add(new Move.Linear(v(40, 10, -1), 1200));
        a.add(new Move.Circular(v(50, 20, -1), v(40, 20, -1), Vec3.UNIT_Z, true, 0, 1200));
        a.add(new Move.Circular(v(40, 30, -1), v(40, 20, -1), Vec3.UNIT_Z, false, 0, 1200));
        a.add(new Move.Circular(v(40, 30, -4), v(40, 20, -1), Vec3.UNIT_Z, true, 2, 600));
        a.add(new Move.Circular(v(30, 20, -4), v(40, 20, -4), Vec3.UNIT_Z.negated(), true, 0, 600));
        a.add(new Move.Rapid(v(30, 20, 10)));
        ToolpathSection s1 = new ToolpathSection("WS1 face", Vec3.UNIT_Z, 18, 1, 720, v(0, 0, 50), a);

        List<Move> b = new ArrayList<>();
        b.add(new Move.Rapid(v(0, -5, 10)));
        b.add(new Move.Linear(v(0, -5, 0), 200));
        b.add(new Move.Circular(v(20, -5, 0), v(10, -5, 0), Vec3.UNIT_Y, true, 0, 400));
        b.add(new Move.Circular(v(20, 5, 0), v(20, 0, 0), Vec3.UNIT_X, false, 0, 400));
        Vec3 tilted = v(0, -Math.sqrt(0.5), Math.sqrt(0.5));
        b.add(new Move.Circular(v(30, 5, 0), v(25, 5, 0), tilted, true, 0, 400));
        b.add(new Move.Rapid(v(30, 5, 20)));
        ToolpathSection s2 = new ToolpathSection("WS2 (side)", Vec3.UNIT_Z, 10, 2, 1500, v(30, 20, 10), b);

        List<Move> c = new ArrayList<>();
        c.add(new Move.Linear(v(30, 5, 10), 100));
        c.add(new Move.Rapid(v(30, 5, 20)));
        ToolpathSection s3 = new ToolpathSection("WS3", Vec3.UNIT_Z, 10, 2, 1500, v(30, 5, 20), c);
        return new Toolpath(List.of(s1, s2, s3));
    }
}
