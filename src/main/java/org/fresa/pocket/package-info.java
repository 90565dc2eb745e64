/**
 * Pocket milling of line/arc contours from the inside out (the 1988 thesis): exact offsets,
 * the recognition tree, passes. Dependencies: {@code geom}, {@code model}.
 *
 * <p>Two engines share the offset kernel ({@link org.fresa.pocket.LineArcOffsetter} for one
 * loop, {@link org.fresa.pocket.RegionOffsetter} for an outer loop with islands):
 * {@link org.fresa.pocket.Recognition} + {@link org.fresa.pocket.PassPlanner} follow the thesis
 * (the 7M posts, its tree and reported sizes); {@link org.fresa.pocket.RegionPocket} offsets the
 * whole region and so handles islands and any number of sub-areas (used for pockets with islands
 * and for the sole cavity). Units mm; contours counter-clockwise bound material-free regions,
 * clockwise loops bound islands; climb milling runs faces counter-clockwise, islands clockwise.
 *
 * <p>Robustness: offsets are exact lines and arcs; pieces are kept by their distance to the
 * input (within 1e-10 of the drawing's size), chained within 1e-5 mm; the thesis's COMPAR
 * (1e-4 x mean radius or line distance) is used by the recognition only.
 */
package org.fresa.pocket;
