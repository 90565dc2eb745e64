package org.fresa.grading;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.Function;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;

/**
 * A pattern as the thesis's ESCOM programs describe it (section 4.2): named points, and the
 * outline's elements defined through them (lines through 2 points, circles through 3, circles
 * through 2 with a fixed radius). Grading moves the points only (eq. 4.1); the elements are
 * rebuilt from the moved points (eqs. 4.2, 4.3), so neighbours share their end points at every
 * size, while a graded arc's centre and radius change in a non-trivial way and the tangent
 * continuity of the base is not kept.
 *
 * @param points the named points, in definition order (mm)
 * @param elements the outline's elements in order of travel
 */
public record EscomPattern(Map<String, Vec2> points, List<Element> elements) {

    /** An element of the outline. */
    public sealed interface Element permits Line, Circle3, CircleR {
        String from();

        String to();
    }

    /** {@code LINE/from,to}. */
    public record Line(String from, String to) implements Element {}

    /** {@code CIRCLE/from,via,to}: the arc from, through via, to to. */
    public record Circle3(String from, String via, String to) implements Element {}

    /** {@code CIRCLE/from,to,CHOICE,RADIUS,r}: the shorter arc; the radius is not graded. */
    public record CircleR(String from, String to, double radiusMm, ThreePointArcs.CenterChoice choice)
            implements Element {}

    public EscomPattern {
        points = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(points));
        elements = List.copyOf(elements);
        for (Element e : elements) {
            for (String n : names(e)) {
                if (!points.containsKey(n)) {
                    throw new IllegalArgumentException("element " + e + " uses the undefined point " + n);
                }
            }
        }
    }

    private static List<String> names(Element e) {
        if (e instanceof Circle3 c) {
            return List.of(c.from(), c.via(), c.to());
        }
        return List.of(e.from(), e.to());
    }

    public Vec2 point(String name) {
        return Objects.requireNonNull(points.get(name), name);
    }

    /** Every point moved by its own map (one map for all, or heel and forepart maps). */
    public EscomPattern graded(Function<String, PantographMap> mapOfPoint) {
        Map<String, Vec2> out = new LinkedHashMap<>();
        points.forEach((n, p) -> out.put(n, mapOfPoint.apply(n).apply(p)));
        return new EscomPattern(out, elements);
    }

    /** Every point moved by the same map. */
    public EscomPattern graded(PantographMap map) {
        return graded(n -> map);
    }

    /** The element rebuilt from the current points. */
    public Curve2 curve(Element e) {
        if (e instanceof Line l) {
            return new Segment2(point(l.from()), point(l.to()));
        }
        if (e instanceof Circle3 c) {
            return ThreePointArcs.arc(point(c.from()), point(c.via()), point(c.to()));
        }
        CircleR r = (CircleR) e;
        return ThreePointArcs.arc(point(r.from()), point(r.to()), r.radiusMm(), r.choice());
    }

    /** The outline: elements in order; they join exactly where consecutive elements share a point. */
    public Contour toContour() {
        List<Curve2> out = new ArrayList<>(elements.size());
        for (Element e : elements) {
            out.add(curve(e));
        }
        return new Contour(out);
    }

    /**
     * The pattern of a contour: a point at each element's start ({@code P1, P2, ...}) and one at
     * the middle of each arc ({@code M1, ...}); lines become {@link Line}, arcs {@link Circle3}.
     * A full circle is split into two halves, as 3 points cannot define a full turn.
     */
    public static EscomPattern ofContour(Contour c) {
        Map<String, Vec2> pts = new LinkedHashMap<>();
        List<Element> els = new ArrayList<>();
        List<Curve2> curves = new ArrayList<>();
        for (Curve2 k : c.curves()) {
            if (k instanceof Arc2 a && a.isFullCircle()) {
                Vec2 half = a.pointAt(0.5);
                curves.add(new Arc2(a.center(), a.start(), half, a.ccw()));
                curves.add(new Arc2(a.center(), half, a.end(), a.ccw()));
            } else {
                curves.add(k);
            }
        }
        int n = curves.size();
        for (int i = 0; i < n; i++) {
            pts.put("P" + (i + 1), curves.get(i).start());
        }
        int m = 0;
        for (int i = 0; i < n; i++) {
            String from = "P" + (i + 1);
            String to = "P" + ((i + 1) % n + 1);
            Curve2 k = curves.get(i);
            if (k instanceof Arc2 a) {
                String via = "M" + (++m);
                pts.put(via, a.pointAt(0.5));
                els.add(new Circle3(from, via, to));
            } else {
                els.add(new Line(from, to));
            }
        }
        return new EscomPattern(pts, els);
    }
}
