package org.fresa.pocket;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;

/**
 * The initial contour of a pocket: elements in clockwise traversal order, element 1 first and the
 * closing element N last (the first pass starts at the junction N -> 1), with the thesis's
 * tolerance {@code compar = 1e-4 × mean(|D| or R)} over the input elements.
 *
 * @param elements the elements, in order; line k values set from the geometry
 * @param compar tolerance in mm (scaled to the contour's size)
 * @param islands closed inner contours (Fresa extension; the thesis has none)
 */
public record PocketProfile(List<PocketElement> elements, double compar, List<Contour> islands) {

    public PocketProfile {
        elements = List.copyOf(elements);
        islands = List.copyOf(islands);
        if (elements.size() < 2) {
            throw new IllegalArgumentException("a pocket contour needs at least 2 elements");
        }
    }

    /** The thesis's tolerance for the given elements. */
    public static double comparOf(List<PocketElement> elements) {
        double sum = 0;
        for (PocketElement e : elements) {
            sum += Math.abs(e.d());
        }
        double mean = sum / elements.size();
        return mean > 0 ? 1e-4 * mean : 1e-6;
    }

    /**
     * The same contour with every line's (A, B) of unit length. An offset moves a line's D by the
     * offset, which is a distance only for a unit normal: the thesis's files do not always write
     * one (cavity 01's element 4, {@code .7 -.75 30}, has |(A, B)| = 1.026, so its finishing pass
     * would stand 2.924 mm from that wall for a 3 mm radius and cut 0.076 mm into it). The
     * thesis's own printed programs keep the raw coefficients; every other program is planned on
     * this one. Normals within {@link #UNIT_NORMAL_SLACK} of unit length (seven printed digits)
     * are kept as written.
     */
    public PocketProfile withUnitNormals() {
        List<PocketElement> out = new ArrayList<>(elements.size());
        boolean changed = false;
        for (PocketElement e : elements) {
            double n = e.normalLength();
            if (e.arc() || !(n > 0) || Math.abs(n - 1) <= UNIT_NORMAL_SLACK) {
                out.add(e);
                continue;
            }
            changed = true;
            out.add(new PocketElement(e.number(), false, e.a() / n, e.b() / n, e.d() / n, e.k(), e.selector()));
        }
        return changed ? new PocketProfile(out, compar, islands) : this;
    }

    /**
     * How far a line's |(A, B)| may be from 1 and be taken as a unit normal: the thesis's files
     * write seven digits, which leaves about 1e-7 (0.3 nm of a 3 mm offset).
     */
    static final double UNIT_NORMAL_SLACK = 1e-6;

    /**
     * The same contour with a line element across every junction the thesis snaps: where two
     * elements that should meet near-tangent miss each other by a gap (cavity 02's circles 5 and
     * 6 by 0.755 mm, line 1 and circle 2 by 0.368 mm), the wall as drawn runs along each element
     * to the point nearest the junction and steps across the gap there, as {@link #outline()}
     * draws it. The step has one reflex end, a corner of material standing into the pocket. The
     * thesis instead joins the two offsets at their snapped junction at every pass, so its pass
     * at t leaves the step's reflex corner closer than t: grown by the tool's radius, the
     * finishing pass cuts the wall beyond that corner by the gap. With the step an element of its
     * own (and the zero-radius arc the reference contour puts at its reflex end) every pass
     * stands t from the wall as drawn. Gaps up to {@link #BRIDGED_GAP_MM} are left snapped.
     */
    public PocketProfile withBridgedJunctions() {
        int n = elements.size();
        List<Vec2> v = vertices();
        int created = elements.stream().mapToInt(PocketElement::number).max().orElse(n);
        List<PocketElement> out = new ArrayList<>(elements.size());
        boolean changed = false;
        for (int i = 0; i < n; i++) {
            PocketElement p = elements.get((i + n - 1) % n);
            PocketElement q = elements.get(i);
            Vec2 from = nearestOnCarrier(p, v.get(i));
            Vec2 to = nearestOnCarrier(q, v.get(i));
            if (from.distance(to) <= BRIDGED_GAP_MM) {
                out.add(q);
                continue;
            }
            changed = true;
            // the step's unit normal on its right, where the pocket is as it is walked from p to q
            Vec2 u = to.minus(from).normalized();
            double a = u.y();
            double b = -u.x();
            int k = 1;
            if (a < 0 || (a == 0 && b < 0)) {
                a = -a;
                b = -b;
                k = -1;
            }
            PocketElement step = new PocketElement(++created, false, a, b, a * from.x() + b * from.y(), k, 'S');
            step = step.withSelector(ElementGeometry.selectorNear(p, step, 0, from, compar));
            out.add(step);
            out.add(q.withSelector(ElementGeometry.selectorNear(step, q, 0, to, compar)));
        }
        return changed ? new PocketProfile(out, compar, islands) : this;
    }

    /**
     * The largest gap (mm) a snapped junction may keep in {@link #withBridgedJunctions()}: the
     * most its passes may stand into the wall there.
     */
    public static final double BRIDGED_GAP_MM = 0.001;

    /**
     * The junctions the thesis snaps across a gap of more than {@link #BRIDGED_GAP_MM} (its pass
     * grown by the tool's radius cuts the wall beyond them by that gap), largest gap first.
     *
     * @return each such junction's point at t = 0 and its gap (mm)
     */
    public List<SnappedJunction> snappedJunctions() {
        int n = elements.size();
        List<Vec2> v = vertices();
        List<SnappedJunction> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            double gap = nearestOnCarrier(elements.get((i + n - 1) % n), v.get(i))
                    .distance(nearestOnCarrier(elements.get(i), v.get(i)));
            if (gap > BRIDGED_GAP_MM) {
                out.add(new SnappedJunction(v.get(i), gap));
            }
        }
        out.sort((x, y) -> Double.compare(y.gapMm(), x.gapMm()));
        return out;
    }

    /**
     * A junction of two elements that miss each other, which the thesis snaps.
     *
     * @param point the snapped junction at t = 0 (mm)
     * @param gapMm how far apart the two elements are there (mm)
     */
    public record SnappedJunction(Vec2 point, double gapMm) {}

    /** The point of e's carrier (its line, or its circle at t = 0) nearest to p. */
    private static Vec2 nearestOnCarrier(PocketElement e, Vec2 p) {
        if (e.arc()) {
            return onCircle(p, e.center(), Math.max(0, e.d()));
        }
        double n = e.normalLength();
        double h = (e.a() * p.x() + e.b() * p.y() - e.d()) / n;
        return new Vec2(p.x() - e.a() / n * h, p.y() - e.b() / n * h);
    }

    /** Junction points at t = 0: index i is the start of element i. */
    public List<Vec2> vertices() {
        List<Vec2> out = new ArrayList<>();
        int n = elements.size();
        for (int i = 0; i < n; i++) {
            PocketElement p = elements.get((i + n - 1) % n);
            out.add(ElementGeometry.junction(p, elements.get(i), 0, compar).orElse(Vec2.ZERO));
        }
        return out;
    }

    /**
     * The wall as lines and arcs, clockwise as the elements run (the pocket on the right), from
     * junction to junction at t = 0; a zero-radius arc is a corner and adds nothing. Arcs are
     * counter-clockwise where concave (k = 1), as the passes cut them. A line whose (A, B) is not
     * of unit length (cavity 01's element 4, 1.026) is drawn where it lies, A x + B y = D.
     */
    public Contour outline() {
        List<Vec2> v = vertices();
        int n = elements.size();
        List<Curve2> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            PocketElement e = elements.get(i);
            Vec2 a = v.get(i);
            Vec2 b = v.get((i + 1) % n);
            if (a.distance(b) <= 1e-9) {
                continue;
            }
            if (!e.arc() || !(e.d() > 0)) {
                out.add(new Segment2(a, b));
                continue;
            }
            // a near-tangent junction the thesis snapped may lie off the circle: the arc runs on
            // its circle and a short line joins each such junction, as the passes are cut
            Vec2 as = onCircle(a, e.center(), e.d());
            Vec2 bs = onCircle(b, e.center(), e.d());
            if (a.distance(as) > 1e-9) {
                out.add(new Segment2(a, as));
            }
            out.add(new Arc2(e.center(), as, bs, e.k() == 1));
            if (bs.distance(b) > 1e-9) {
                out.add(new Segment2(bs, b));
            }
        }
        return new Contour(out);
    }

    private static Vec2 onCircle(Vec2 p, Vec2 c, double r) {
        double d = p.distance(c);
        return d < 1e-12 ? p : c.plus(p.minus(c).times(r / d));
    }

    /**
     * Sets each line's k from its direction of travel between its junctions (pocket on the right),
     * as the thesis's subroutine 8470 does for lines with A >= 0, but for any sign of (A, B).
     *
     * @return empty when a junction does not exist
     */
    static Optional<List<PocketElement>> withLineDirections(List<PocketElement> elements, double compar) {
        int n = elements.size();
        List<Vec2> v = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Optional<Vec2> j = ElementGeometry.junction(elements.get((i + n - 1) % n), elements.get(i), 0, compar);
            if (j.isEmpty()) {
                return Optional.empty();
            }
            v.add(j.get());
        }
        List<PocketElement> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            PocketElement e = elements.get(i);
            if (!e.arc()) {
                Vec2 dir = v.get((i + 1) % n).minus(v.get(i));
                double s = e.a() * dir.y() - e.b() * dir.x();
                e = e.withK(s >= 0 ? 1 : -1);
            }
            out.add(e);
        }
        return Optional.of(out);
    }

    /**
     * Converts a contour of segments and arcs (any orientation) to thesis elements: lines in the
     * canonical unit form with A >= 0, arcs convex when they turn with the clockwise contour.
     */
    /**
     * The contour with consecutive elements on one carrier joined: arcs on the same circle with
     * the same sense, segments on the same line. The recognition tree needs each element to be a
     * different carrier (two pieces of one circle have no incentre); drawings often split a circle
     * where the contour starts. At least two elements are kept.
     */
    static Contour mergeCarriers(Contour c) {
        List<Curve2> list = new ArrayList<>(c.curves());
        boolean changed = true;
        while (changed && list.size() > 2) {
            changed = false;
            for (int i = 0; i < list.size() && list.size() > 2; i++) {
                int j = (i + 1) % list.size();
                Curve2 a = list.get(i);
                Curve2 b = list.get(j);
                Curve2 joined = null;
                if (a instanceof Arc2 x
                        && b instanceof Arc2 y
                        && x.ccw() == y.ccw()
                        && x.center().distance(y.center()) <= 1e-9 * Math.max(1, x.radius())
                        && Math.abs(x.radius() - y.radius()) <= 1e-9 * Math.max(1, x.radius())
                        && Math.abs(x.sweepRad() + y.sweepRad()) < 2 * Math.PI - 1e-9) {
                    joined = new Arc2(x.center(), x.start(), y.end(), x.ccw());
                } else if (a instanceof Segment2 x && b instanceof Segment2 y) {
                    Vec2 u = x.direction();
                    Vec2 v = y.direction();
                    if (u.dot(v) > 0 && Math.abs(u.cross(v)) <= 1e-12 * u.norm() * v.norm()) {
                        joined = new Segment2(x.start(), y.end());
                    }
                }
                if (joined != null) {
                    list.set(i, joined);
                    list.remove(j);
                    if (j < i) {
                        // the joined element wraps past the end: keep the contour's start where it was
                        list.add(0, list.remove(list.size() - 1));
                    }
                    changed = true;
                }
            }
        }
        return list.size() == c.size() ? c : new Contour(list);
    }

    public static PocketProfile fromContours(List<Contour> contours) {
        Contour outer = mergeCarriers(contours.get(0));
        if (outer.isCcw()) {
            outer = outer.reversed();
        }
        List<PocketElement> raw = new ArrayList<>();
        int n = outer.size();
        for (int i = 0; i < n; i++) {
            Curve2 c = outer.get(i);
            int number = i + 1;
            if (c instanceof Segment2 s) {
                double a = s.start().y() - s.end().y();
                double b = s.end().x() - s.start().x();
                double d = s.end().x() * s.start().y() - s.end().y() * s.start().x();
                double len = Math.hypot(a, b);
                a /= len;
                b /= len;
                d /= len;
                if (a < 0 || (a == 0 && b < 0)) {
                    a = -a;
                    b = -b;
                    d = -d;
                }
                raw.add(new PocketElement(number, false, a, b, d, 1, 'S'));
            } else {
                Arc2 arc = (Arc2) c;
                raw.add(new PocketElement(
                        number, true, arc.center().x(), arc.center().y(), arc.radius(), arc.ccw() ? 1 : -1, 'S'));
            }
        }
        List<PocketElement> sel = new ArrayList<>();
        double compar = comparOf(raw);
        for (int i = 0; i < n; i++) {
            PocketElement prev = raw.get((i + n - 1) % n);
            PocketElement e = raw.get(i);
            Vec2 start = outer.get(i).start();
            sel.add(e.withSelector(ElementGeometry.selectorNear(prev, e, 0, start, compar)));
        }
        List<PocketElement> out = withLineDirections(sel, compar).orElse(sel);
        List<Contour> islands = contours.size() > 1 ? contours.subList(1, contours.size()) : List.of();
        return new PocketProfile(out, compar, islands);
    }
}
