/**
 * Sole moulds: tread figures, cavity, sizes and both feet. Dependencies: {@code pocket}
 * (the cavity's passes), {@code model}, {@code geom}; graded outlines arrive as contours.
 */
package org.fresa.sole;
