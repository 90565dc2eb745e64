package org.fresa.sole;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;

/**
 * One continuous groove cut at full depth: the tool travels at clearance height through the
 * {@code via} points, goes over {@code start}, plunges, follows the curves (tool centre, mm) and
 * retracts at the end. A stroke with no curves is a plunge that a later continuous figure carries
 * on (the thesis's PRIM and NOVO).
 *
 * @param via rapid points at clearance height before the plunge (NOVO's first point), maybe empty
 * @param start the plunge point (mm)
 * @param curves the cuts in order, each starting where the previous ends, the first at start
 */
public record Stroke(List<Vec2> via, Vec2 start, List<Curve2> curves) {

    public Stroke {
        via = List.copyOf(via);
        Objects.requireNonNull(start, "start");
        curves = List.copyOf(curves);
    }

    public static Stroke of(Vec2 start, List<? extends Curve2> curves) {
        return new Stroke(List.of(), start, List.copyOf(curves));
    }

    /** Where the tool is at the end of the stroke. */
    public Vec2 end() {
        return curves.isEmpty() ? start : curves.get(curves.size() - 1).end();
    }

    /** This stroke with more cuts appended (they must start at {@link #end()}). */
    public Stroke extended(List<? extends Curve2> more) {
        List<Curve2> all = new ArrayList<>(curves);
        all.addAll(more);
        return new Stroke(via, start, all);
    }

    /**
     * The same groove cut the other way: curves reversed and in reverse order. The via points are
     * dropped, since the plunge point has moved to the old end.
     */
    public Stroke reversed() {
        List<Curve2> rev = new ArrayList<>(curves.size());
        for (int i = curves.size() - 1; i >= 0; i--) {
            rev.add(curves.get(i).reversed());
        }
        return new Stroke(List.of(), end(), rev);
    }

    /** Total cut length in mm. */
    public double length() {
        double l = 0;
        for (Curve2 c : curves) {
            l += c.length();
        }
        return l;
    }

    /** This stroke mapped by a similarity (via points, start and every curve). */
    public Stroke mapped(Similarity2 t) {
        List<Vec2> v = via.stream().map(t::apply).toList();
        return new Stroke(v, t.apply(start), curves.stream().map(t::apply).toList());
    }
}
