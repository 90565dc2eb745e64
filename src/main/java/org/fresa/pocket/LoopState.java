package org.fresa.pocket;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fresa.geom.Vec2;

/**
 * A subcontour of the recognition tree, valid from offset {@code tFrom} until the next event: its
 * elements in clockwise order with their junction selectors, and the start pointer (the element
 * whose end vertex starts every pass on this subcontour).
 *
 * @param tFrom offset (mm) from which this element list holds
 * @param elements the elements in order
 * @param pointer index into elements of the pointer element
 * @param compar tolerance (mm)
 */
public record LoopState(double tFrom, List<PocketElement> elements, int pointer, double compar) {

    public LoopState {
        elements = List.copyOf(elements);
    }

    public int size() {
        return elements.size();
    }

    public PocketElement get(int i) {
        int n = elements.size();
        return elements.get(((i % n) + n) % n);
    }

    /** The junction that starts element i at offset t. */
    public Optional<Vec2> start(int i, double t) {
        return ElementGeometry.junction(get(i - 1), get(i), t, compar);
    }

    /** All junctions at offset t (index i starts element i), empty if one is missing. */
    public Optional<List<Vec2>> vertices(double t) {
        List<Vec2> out = new ArrayList<>();
        for (int i = 0; i < size(); i++) {
            Optional<Vec2> v = start(i, t);
            if (v.isEmpty()) {
                return Optional.empty();
            }
            out.add(v.get());
        }
        return Optional.of(out);
    }

    /** Smallest interior angle (degrees, at most 180) of the subcontour offset by t. */
    public double minAngleDeg(double t) {
        double min = 180;
        for (int i = 0; i < size(); i++) {
            PocketElement p = get(i - 1), q = get(i);
            if ((p.arc() && p.at(t) <= 1e-9) || (q.arc() && q.at(t) <= 1e-9)) {
                continue;
            }
            Optional<Vec2> v = start(i, t);
            if (v.isPresent()) {
                min = Math.min(min, ElementGeometry.interiorAngleDeg(p, q, v.get()));
            }
        }
        return min;
    }

    /**
     * Signed area of the subcontour offset by t (negative for the clockwise pocket), arcs as
     * arcs; empty when a junction is missing or an element runs backwards (the subcontour has
     * vanished).
     */
    public Optional<Double> signedArea(double t) {
        Optional<List<Vec2>> vs = vertices(t);
        if (vs.isEmpty()) {
            return Optional.empty();
        }
        List<Vec2> v = vs.get();
        double area = 0;
        int n = size();
        for (int i = 0; i < n; i++) {
            Vec2 s = v.get(i), e = v.get((i + 1) % n);
            PocketElement el = get(i);
            area += s.cross(e) / 2;
            if (el.arc()) {
                double r = el.at(t);
                if (r < -compar) {
                    return Optional.empty();
                }
                double sweep = sweep(el, s, e);
                if (sweep > 2 * Math.PI - 1e-3 && s.distance(e) < 10 * compar) {
                    return Optional.empty();
                }
                // circular segment between chord and arc: + for ccw, - for cw
                double seg = 0.5 * r * r * (sweep - Math.sin(sweep));
                area += el.k() == 1 ? seg : -seg;
            } else if (e.minus(s).dot(el.tangentAt(s)) < -10 * compar) {
                return Optional.empty();
            }
        }
        return Optional.of(area);
    }

    /** Sweep (radians, in [0, 2π)) of arc element el from s to e in its sense of travel. */
    static double sweep(PocketElement el, Vec2 s, Vec2 e) {
        double a0 = s.minus(el.center()).angleRad();
        double a1 = e.minus(el.center()).angleRad();
        double d = el.k() == 1 ? a1 - a0 : a0 - a1;
        d = d % (2 * Math.PI);
        if (d < 0) {
            d += 2 * Math.PI;
        }
        return d;
    }

    public LoopState with(double t, List<PocketElement> els, int ptr) {
        return new LoopState(t, els, ptr, compar);
    }
}
