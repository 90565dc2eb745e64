package org.fresa.sole;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.fresa.geom.Box2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;

/**
 * One design of a tread: macro calls (an {@code INDEX} block) repeated by a pattern, with its
 * size rule, its tool and whether it is text (never mirrored).
 *
 * @param name shown to the planner
 * @param lead calls made once before the copies, not repeated (PRIM or NOVO to start a
 *     continuous groove)
 * @param figures the block that the pattern repeats
 * @param pattern the copies
 * @param rule how the design follows the sizes
 * @param text true for text, logos and size marks: on the left foot the design moves to the
 *     mirrored place but is not mirrored itself
 * @param toolId the tool that cuts it (an id of the tread's tools)
 */
public record TreadItem(String name, List<TreadFigure> lead, List<TreadFigure> figures, TreadPattern pattern,
        SizeRule rule, boolean text, String toolId) {

    public TreadItem {
        Objects.requireNonNull(name, "name");
        lead = List.copyOf(lead);
        figures = List.copyOf(figures);
        Objects.requireNonNull(pattern, "pattern");
        Objects.requireNonNull(rule, "rule");
        Objects.requireNonNull(toolId, "toolId");
        if (figures.isEmpty()) {
            throw new IllegalArgumentException(name + ": a tread item needs at least one figure");
        }
    }

    /**
     * The grooves of the design at the base size (no shrinkage), in cutting order. Continuous
     * figures chain onto the groove in progress, also across copies, as EXAPT's copies of a
     * "B" macro do; a continuous figure with no groove in progress plunges where the tool is.
     *
     * @throws IllegalArgumentException when a figure has no path
     */
    public List<Stroke> strokes(Tolerance tol) {
        List<Stroke> block = evaluate(List.of(), List.of(Similarity2.IDENTITY), tol);
        Vec2 anchor = anchor(block);
        List<Stroke> out = new ArrayList<>();
        for (Stroke s : evaluate(lead, pattern.copies(anchor, tol), tol)) {
            if (!s.curves().isEmpty()) {
                out.add(s);
            }
        }
        return out;
    }

    private List<Stroke> evaluate(List<TreadFigure> before, List<Similarity2> copies, Tolerance tol) {
        List<Stroke> strokes = new ArrayList<>();
        Vec2 at = Vec2.ZERO;
        boolean down = false;
        for (TreadFigure f : before) {
            FigurePath p = f.path(at, tol);
            down = add(strokes, p, at, down);
            at = p.end();
        }
        for (Similarity2 t : copies) {
            Similarity2 inv = t.inverse();
            for (TreadFigure f : figures) {
                FigurePath p = f.path(inv.apply(at), tol).mapped(t);
                down = add(strokes, p, at, down);
                at = p.end();
            }
        }
        return strokes;
    }

    private static boolean add(List<Stroke> strokes, FigurePath p, Vec2 at, boolean down) {
        List<Stroke> s = new ArrayList<>(p.strokes());
        if (p.joinsPrevious()) {
            Stroke first = s.remove(0);
            if (down && !strokes.isEmpty()) {
                strokes.set(strokes.size() - 1, strokes.get(strokes.size() - 1).extended(first.curves()));
            } else {
                strokes.add(new Stroke(List.of(), at, first.curves()));
            }
        }
        strokes.addAll(s);
        return p.staysDown();
    }

    /** The centre of the bounding box of the strokes (ZERO when there are none). */
    static Vec2 anchor(List<Stroke> strokes) {
        Box2 b = null;
        for (Stroke s : strokes) {
            for (Curve2 c : s.curves()) {
                b = b == null ? c.bounds() : b.union(c.bounds());
            }
        }
        return b == null ? Vec2.ZERO : b.center();
    }
}
