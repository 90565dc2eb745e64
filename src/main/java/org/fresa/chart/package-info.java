/**
 * Plots as JFreeChart charts, shared by the tabs and by the files written headless (PNG, SVG):
 * toolpaths with arcs drawn as arcs, joint trajectories, errors, nested outlines.
 * {@code java.awt} is allowed here (charts are AWT drawings); Swing is not. Dependencies:
 * {@code model}, {@code geom}; never {@code job}, {@code ui} or {@code app}.
 */
package org.fresa.chart;
