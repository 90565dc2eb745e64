/**
 * Plane and space geometry as immutable value types: vectors, lines, exact circular arcs, closed
 * contours and rigid transforms.
 *
 * <p>Units: lengths in millimetres, angles in radians unless a name says otherwise
 * ({@code angleDeg}). Sign conventions: counter-clockwise is positive, the left normal of a
 * direction (x, y) is (-y, x), a contour whose signed area is positive runs counter-clockwise.
 *
 * <p>Equality: record {@code equals} is exact; approximate comparison goes through
 * {@code eq(other, Tolerance)} with a {@link org.fresa.geom.Tolerance} passed in by the caller.
 *
 * <p>Dependencies: the JDK only. No I/O, no AWT or Swing.
 */
package org.fresa.geom;
