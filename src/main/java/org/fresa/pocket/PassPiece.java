package org.fresa.pocket;

import org.fresa.geom.Vec2;

/**
 * One element of a pass: a straight move, or an arc about the element's centre (clockwise for
 * convex arcs, counter-clockwise for concave ones), from start to end.
 *
 * @param element the contour element this piece offsets
 * @param offsetMm the pass offset t (mm)
 * @param start start point (mm)
 * @param end end point (mm)
 * @param reversed traversed against the clockwise contour (climb milling)
 */
public record PassPiece(PocketElement element, double offsetMm, Vec2 start, Vec2 end, boolean reversed) {

    public boolean isArc() {
        return element.arc();
    }

    /** Counter-clockwise (G03) for concave arcs. */
    public boolean ccw() {
        return (element.k() == 1) != reversed;
    }

    /** The arc's radius at this offset (mm); the snapped junctions of near-tangent input may lie off it. */
    public double radiusMm() {
        return Math.abs(element.at(offsetMm));
    }

    public Vec2 center() {
        return element.center();
    }

    /** Length in mm (arcs along the arc at the radius of the start point). */
    public double lengthMm() {
        if (!isArc()) {
            return start.distance(end);
        }
        double r = start.distance(center());
        double sweep = reversed ? LoopState.sweep(element, end, start) : LoopState.sweep(element, start, end);
        if (sweep > 2 * Math.PI - 1e-9 && start.distance(end) < 1e-9) {
            sweep = 0;
        }
        return r * sweep;
    }
}
