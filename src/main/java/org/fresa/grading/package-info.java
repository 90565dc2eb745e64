/**
 * Shoe-size grading of sole outlines (the 1986 thesis's pantograph). Dependencies: {@code geom},
 * {@code model}.
 *
 * <p>{@link org.fresa.grading.GradingRule} holds the thesis's equations (ALFA, BETA, shrinkage);
 * {@link org.fresa.grading.SizeSystem} the size systems and their steps, {@link org.fresa.grading.SizeTable}
 * the thesis's table 3.2. {@link org.fresa.grading.Grader} finds the frame
 * ({@link org.fresa.grading.OutlineFrames}: length axis, heel end, heel-circle origin), measures CP and
 * LP and maps each size with a {@link org.fresa.grading.PantographMap}. The exact image of an
 * outline is a {@link org.fresa.grading.GradedOutline} of lines and
 * {@link org.fresa.grading.EllipticArc}s; {@link org.fresa.grading.Biarcs} turns ellipses into
 * tangent-continuous circular arcs within a tolerance (0.005 mm by default) for NC and DXF.
 * {@link org.fresa.grading.EscomPattern} is the thesis's own representation (points, lines through
 * 2 points, circles through 3), graded point by point and rebuilt, used for the 3-point option and
 * for heel {@link org.fresa.grading.Coordination}.
 */
package org.fresa.grading;
