package org.fresa.sole;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;

/**
 * A composed tread: designs placed on the right sole at the base size, and the margin they keep
 * from the outline. Gives the clipped grooves of any size and foot.
 *
 * <p>Left foot: the mirror image of the right about the job's length axis through the grading
 * origin (x' = 2 ox - x). Every mirrored groove is also reversed, so its sense about the
 * material is unchanged: a climb-milled ring stays climb-milled, as the thesis kept its cavities'
 * sense by cutting the mirrored copy with the opposite macro (MAC5/MAC6). Text items are moved to
 * their mirrored place without being mirrored.
 *
 * @param items the designs in cutting order
 * @param marginMm the least distance of any groove (tool centre) from the outline, >= 0
 */
public record SoleTread(List<TreadItem> items, double marginMm) {

    public SoleTread {
        items = List.copyOf(items);
        if (!(marginMm >= 0) || !Double.isFinite(marginMm)) {
            throw new IllegalArgumentException("margin must be >= 0: " + marginMm);
        }
    }

    /** The grooves of one item for a size and foot, not yet clipped. */
    public static List<Stroke> placed(TreadItem item, SizeScale size, Foot foot, Tolerance tol) {
        List<Stroke> base = item.strokes(tol);
        List<Stroke> sized = switch (item.rule()) {
            case HELD -> map(base, Similarity2.scale(Vec2.ZERO, size.shrinkFactor()));
            case POSITION -> {
                Vec2 a = TreadItem.anchor(base);
                Vec2 to = size.graded(a);
                yield map(base, Similarity2.scale(a, size.shrinkFactor()).then(Similarity2.translation(to.minus(a))));
            }
            case SCALED -> base.stream().map(s -> graded(s, size, tol)).toList();
        };
        if (foot == Foot.RIGHT) {
            return sized;
        }
        double ox = size.origin().x();
        if (item.text()) {
            Vec2 a = TreadItem.anchor(sized);
            return map(sized, Similarity2.translation(2 * (ox - a.x()), 0));
        }
        Similarity2 m = Similarity2.mirrorX(ox);
        return sized.stream().map(s -> s.mapped(m).reversed()).toList();
    }

    /** The outline of the other foot: mirrored about x = originX, run in the same sense as the given one. */
    public static Contour mirrored(Contour outline, double originXMm) {
        Similarity2 m = Similarity2.mirrorX(originXMm);
        List<Curve2> cs = outline.curves().stream().map(m::apply).toList();
        return new Contour(cs).reversed();
    }

    /**
     * Every groove centre line of the tread for the size and foot, clipped to the outline shrunk
     * by the margin, grouped by tool in the items' order.
     *
     * @param rightOutline the graded outline of the right foot at this size (mm)
     */
    public List<ToolGrooves> grooves(SizeScale size, Foot foot, Contour rightOutline, Tolerance tol) {
        return grooves(size, foot, rightOutline, id -> 0.0, tol);
    }

    /**
     * As {@link #grooves(SizeScale, Foot, Contour, Tolerance)}, but each groove's edge keeps the
     * margin: the centre line of a groove cut by a tool of radius r is clipped at margin + r.
     *
     * @param toolRadiusMm the radius of each tool id
     */
    public List<ToolGrooves> grooves(
            SizeScale size,
            Foot foot,
            Contour rightOutline,
            java.util.function.ToDoubleFunction<String> toolRadiusMm,
            Tolerance tol) {
        Contour outline = foot == Foot.RIGHT
                ? rightOutline
                : mirrored(rightOutline, size.origin().x());
        java.util.Map<String, TreadClipper> clippers = new java.util.HashMap<>();
        List<ToolGrooves> out = new ArrayList<>();
        for (TreadItem item : items) {
            TreadClipper clipper = clippers.computeIfAbsent(
                    item.toolId(), id -> TreadClipper.of(outline, marginMm + toolRadiusMm.applyAsDouble(id), tol));
            List<Stroke> kept = clipper.clip(placed(item, size, foot, tol));
            if (!out.isEmpty() && out.get(out.size() - 1).toolId().equals(item.toolId())) {
                List<Stroke> all = new ArrayList<>(out.get(out.size() - 1).strokes());
                all.addAll(kept);
                out.set(out.size() - 1, new ToolGrooves(item.toolId(), all));
            } else {
                out.add(new ToolGrooves(item.toolId(), kept));
            }
        }
        return out;
    }

    /** The grooves one tool cuts. */
    public record ToolGrooves(String toolId, List<Stroke> strokes) {
        public ToolGrooves {
            Objects.requireNonNull(toolId, "toolId");
            strokes = List.copyOf(strokes);
        }
    }

    private static List<Stroke> map(List<Stroke> strokes, Similarity2 t) {
        return strokes.stream().map(s -> s.mapped(t)).toList();
    }

    private static Stroke graded(Stroke s, SizeScale size, Tolerance tol) {
        List<Curve2> cs = new ArrayList<>();
        for (Curve2 c : s.curves()) {
            cs.add(graded(c, size, tol));
        }
        List<Vec2> via = s.via().stream().map(size::graded).toList();
        return new Stroke(via, size.graded(s.start()), cs);
    }

    static Curve2 graded(Curve2 c, SizeScale size, Tolerance tol) {
        if (c instanceof Segment2 seg) {
            return new Segment2(size.graded(seg.start()), size.graded(seg.end()));
        }
        Arc2 a = (Arc2) c;
        if (a.isFullCircle()) {
            Vec2 ctr = size.graded(a.center());
            double r = a.radius() * Math.sqrt(size.widthFactor() * size.lengthFactor());
            Vec2 s = ctr.plus(a.start().minus(a.center()).normalized().times(r));
            return new Arc2(ctr, s, s, a.ccw());
        }
        Vec2 p1 = size.graded(a.start());
        Vec2 p2 = size.graded(a.pointAt(0.5));
        Vec2 p3 = size.graded(a.end());
        Vec2 ctr = circumcentre(p1, p2, p3);
        if (ctr == null) {
            return new Segment2(p1, p3);
        }
        return new Arc2(ctr, p1, p3, a.ccw());
    }

    private static Vec2 circumcentre(Vec2 a, Vec2 b, Vec2 c) {
        double d = 2 * (a.x() * (b.y() - c.y()) + b.x() * (c.y() - a.y()) + c.x() * (a.y() - b.y()));
        if (Math.abs(d) < 1e-12) {
            return null;
        }
        double a2 = a.dot(a);
        double b2 = b.dot(b);
        double c2 = c.dot(c);
        return Vec2.of(
                (a2 * (b.y() - c.y()) + b2 * (c.y() - a.y()) + c2 * (a.y() - b.y())) / d,
                (a2 * (c.x() - b.x()) + b2 * (a.x() - c.x()) + c2 * (b.x() - a.x())) / d);
    }
}
