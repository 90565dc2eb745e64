/**
 * The shared domain model: tools, toolpath moves and sections, placements, the geometry of an arc
 * move and its points at a chord tolerance, the cycle-time estimate, and the one checked exception
 * family for bad user input.
 *
 * <p>Units: mm, degrees where a name ends in {@code Deg}, mm/min for feeds, rpm for spindles.
 * Dependencies: {@code geom} and the JDK. No I/O beyond what a caller hands in, no Swing.
 */
package org.fresa.model;
