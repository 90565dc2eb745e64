package org.fresa.post;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

/** Toolpaths that exercise every kind of move a post must write. */
final class SampleToolpaths {

    private SampleToolpaths() {}

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

    /**
     * Four sections, two tools, with the moves that do not travel: a peck drilling with a dwell
     * at the step and another at the bottom; a boring with a dwell, the spindle stopped at the
     * bottom, out at feed and started again; the same tool reversed (M4) in a section of its own;
     * then the same tool and speed clockwise again, which must start the spindle again.
     */
    static Toolpath drilling() {
        List<Move> a = new ArrayList<>();
        a.add(new Move.Rapid(v(20, 20, 5)));
        a.add(new Move.Linear(v(20, 20, -6), 150));
        a.add(new Move.Dwell(v(20, 20, -6), 0.5));
        a.add(new Move.Rapid(v(20, 20, 5)));
        a.add(new Move.Rapid(v(20, 20, -5)));
        a.add(new Move.Linear(v(20, 20, -12), 150));
        a.add(new Move.Dwell(v(20, 20, -12), 1.25));
        a.add(new Move.Rapid(v(20, 20, 5)));
        a.add(new Move.Rapid(v(20, 20, 30)));
        ToolpathSection s1 = new ToolpathSection("WS1 peck", Vec3.UNIT_Z, 8, 3, 1200, v(20, 20, 30), a);

        List<Move> b = new ArrayList<>();
        b.add(new Move.Rapid(v(50, 20, 5)));
        b.add(new Move.Linear(v(50, 20, -15), 80));
        b.add(new Move.Dwell(v(50, 20, -15), 2));
        b.add(new Move.SpindleStop(v(50, 20, -15)));
        b.add(new Move.Linear(v(50, 20, 5), 80));
        b.add(new Move.SpindleStart(v(50, 20, 5), 800, true));
        b.add(new Move.Rapid(v(50, 20, 30)));
        ToolpathSection s2 = new ToolpathSection("WS2 bore", Vec3.UNIT_Z, 12, 4, 800, v(50, 20, 30), b);

        List<Move> c = new ArrayList<>();
        c.add(new Move.SpindleStart(v(50, 20, 30), 800, false));
        c.add(new Move.Rapid(v(60, 20, 5)));
        c.add(new Move.Linear(v(60, 20, 0), 80));
        c.add(new Move.Rapid(v(60, 20, 30)));
        ToolpathSection s3 = new ToolpathSection("WS3 reversed", Vec3.UNIT_Z, 12, 4, 800, v(50, 20, 30), c);

        List<Move> d = new ArrayList<>();
        d.add(new Move.Rapid(v(70, 20, 5)));
        d.add(new Move.Linear(v(70, 20, 0), 80));
        d.add(new Move.Rapid(v(70, 20, 30)));
        ToolpathSection s4 = new ToolpathSection("WS4", Vec3.UNIT_Z, 12, 4, 800, v(60, 20, 30), d);
        return new Toolpath(List.of(s1, s2, s3, s4));
    }
}
