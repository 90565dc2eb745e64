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
public record TreadItem(
        String name,
        List<TreadFigure> lead,
        List<TreadFigure> figures,
        TreadPattern pattern,
        SizeRule rule,
        boolean text,
        String toolId) {

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
     * The grooves of the design at the base size (no shrinkage), in cutting order.
     *
     * <p>As EXAPT's {@code COPY} does, the block is computed once (after the lead calls) and each
     * copy is its image. A continuous figure carries on the groove in progress when its copy
     * starts where the tool is, so contiguous copies of SUB7B make one zig-zag; when it starts
     * elsewhere (a new row), the tool is lifted and plunged there, which is what the thesis had
     * to write NOVO for (the processor would otherwise have cut straight across).
     *
     * @throws IllegalArgumentException when a figure has no path
     */
    public List<Stroke> strokes(Tolerance tol) {
        List<Stroke> lead = new ArrayList<>();
        Vec2 at = Vec2.ZERO;
        boolean down = false;
        for (TreadFigure f : this.lead) {
            FigurePath p = f.path(at, tol);
            down = add(lead, p, down, tol);
            at = p.end();
        }
        List<FigurePath> block = new ArrayList<>();
        Vec2 b = at;
        for (TreadFigure f : figures) {
            FigurePath p = f.path(b, tol);
            block.add(p);
            b = p.end();
        }
        List<Stroke> blockStrokes = new ArrayList<>();
        for (FigurePath p : block) {
            blockStrokes.addAll(p.strokes());
        }
        List<Stroke> strokes = new ArrayList<>(lead);
        for (Similarity2 t : pattern.copies(anchor(blockStrokes), tol)) {
            for (FigurePath p : block) {
                down = add(strokes, p.mapped(t), down, tol);
            }
        }
        List<Stroke> out = new ArrayList<>();
        for (Stroke s : strokes) {
            if (!s.curves().isEmpty()) {
                out.add(s);
            }
        }
        return out;
    }

    private static boolean add(List<Stroke> strokes, FigurePath p, boolean down, Tolerance tol) {
        List<Stroke> s = new ArrayList<>(p.strokes());
        if (p.joinsPrevious()) {
            Stroke first = s.remove(0);
            Stroke last = strokes.isEmpty() ? null : strokes.get(strokes.size() - 1);
            if (down && last != null && last.end().eq(first.start(), tol)) {
                strokes.set(strokes.size() - 1, last.extended(first.curves()));
            } else {
                strokes.add(new Stroke(List.of(), first.start(), first.curves()));
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
