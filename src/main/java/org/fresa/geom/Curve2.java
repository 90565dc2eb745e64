package org.fresa.geom;

/**
 * An element of a plane contour: a straight segment or an exact circular arc.
 *
 * <p>Every curve is directed from {@link #start()} to {@link #end()}; tangents follow that
 * direction.
 */
public sealed interface Curve2 permits Segment2, Arc2 {

    Vec2 start();

    Vec2 end();

    /** Length in mm. */
    double length();

    /** The same curve run the other way. */
    Curve2 reversed();

    /** The point at the given fraction of the length (0 start, 1 end). */
    Vec2 pointAt(double fraction);

    /** Unit tangent at the start, in the direction of travel. */
    Vec2 startTangent();

    /** Unit tangent at the end, in the direction of travel. */
    Vec2 endTangent();

    /**
     * The signed area this curve contributes to a closed contour by the shoelace formula, with
     * the exact circular segment for arcs. Summed over a closed contour it gives the enclosed
     * area, positive when the contour runs counter-clockwise.
     */
    double areaContribution();

    /** The smallest axis-aligned box that holds the curve. */
    Box2 bounds();

    /** The curve moved by the vector. */
    Curve2 translated(Vec2 by);

    /** The distance in mm from p to the nearest point of the curve. */
    double distanceTo(Vec2 p);
}
