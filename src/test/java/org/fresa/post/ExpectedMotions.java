package org.fresa.post;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Vec3;
import org.fresa.model.ArcGeometry;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

/**
 * The canonical motions a correct G-code post of a toolpath must make the interpreter print:
 * per section a rapid to its start, then its moves; arcs in principal planes as one ARC_FEED
 * (or one per turn when the dialect has no turn word), other arcs as chords; dwells as DWELL
 * where the tool is. Spindle stops and starts are no motions (the interpreter's spindle calls
 * also come from tool changes and the program end); tests that need them read the log.
 */
public final class ExpectedMotions {

    private ExpectedMotions() {}

    public static List<Rs274.Canon> of(Toolpath path, boolean splitTurns, double chordTolMm) {
        List<Rs274.Canon> list = new ArrayList<>();
        for (ToolpathSection s : path.sections()) {
            list.add(new Rs274.Canon("rapid", s.start(), null, null, 0));
            Vec3 at = s.start();
            for (Move m : s.moves()) {
                if (m instanceof Move.Rapid r) {
                    list.add(new Rs274.Canon("rapid", r.end(), null, null, 0));
                } else if (m instanceof Move.Linear l) {
                    list.add(new Rs274.Canon("feed", l.end(), null, null, 0));
                } else if (m instanceof Move.Circular c) {
                    arc(list, at, c, splitTurns, chordTolMm);
                } else if (m instanceof Move.Dwell d) {
                    list.add(new Rs274.Canon("dwell", at, null, null, 0, d.seconds()));
                }
                at = m.end();
            }
        }
        return list;
    }

    private static void arc(List<Rs274.Canon> list, Vec3 at, Move.Circular c, boolean split, double tol) {
        Vec3 axis = null;
        for (Vec3 a : List.of(Vec3.UNIT_Z, Vec3.UNIT_Y, Vec3.UNIT_X)) {
            if (Math.abs(Math.abs(c.normal().dot(a)) - 1) < 1e-9) {
                axis = a;
            }
        }
        if (axis == null) {
            for (Vec3 p : ArcGeometry.of(at, c).points(tol)) {
                list.add(new Rs274.Canon("feed", p, null, null, 0));
            }
            return;
        }
        int sense = (c.ccw() == c.normal().dot(axis) > 0) ? 1 : -1;
        if (!split || c.turns() == 0) {
            list.add(new Rs274.Canon("arc", c.end(), c.center(), axis, sense * (c.turns() + 1)));
            return;
        }
        ArcGeometry g = ArcGeometry.of(at, c);
        double perTurn = 2 * Math.PI / Math.abs(g.sweepRad());
        for (int k = 1; k <= c.turns(); k++) {
            list.add(new Rs274.Canon(
                    "arc", at.plus(c.normal().times(g.riseMm() * perTurn * k)), c.center(), axis, sense));
        }
        list.add(new Rs274.Canon("arc", c.end(), c.center(), axis, sense));
    }

    /** Null when equal within tolMm (positions and in-plane centres), else the first difference. */
    public static String firstDifference(List<Rs274.Canon> expected, List<Rs274.Canon> actual, double tolMm) {
        for (int i = 0; i < Math.min(expected.size(), actual.size()); i++) {
            Rs274.Canon e = expected.get(i);
            Rs274.Canon a = actual.get(i);
            boolean same = e.kind().equals(a.kind())
                    && e.end().distance(a.end()) <= tolMm
                    && Math.abs(e.seconds() - a.seconds()) <= 5e-4;
            if (same && e.kind().equals("arc")) {
                Vec3 n = e.normal();
                Vec3 ec = e.center().minus(n.times(e.center().dot(n)));
                same = n.equals(a.normal()) && e.rotation() == a.rotation() && ec.distance(a.center()) <= tolMm;
            }
            if (!same) {
                return "motion " + i + ": expected " + e + " but was " + a;
            }
        }
        if (expected.size() != actual.size()) {
            return "expected " + expected.size() + " motions but was " + actual.size();
        }
        return null;
    }
}
