/**
 * Sheet cutting: chaining, parts and holes, cut order, kerf, leads. The planner takes contours;
 * {@link org.fresa.cutting.DrawingContours} chains a drawing's curves into the closed outlines
 * that the modules taking one outline from a drawing (pocket, grading, sole) start from.
 * Dependencies: {@code pocket} (offsets), {@code dxf} (the drawings chained), {@code model},
 * {@code geom}.
 */
package org.fresa.cutting;
