/**
 * Sheet cutting: chaining, parts and holes, cut order, kerf, leads. Dependencies: {@code pocket}
 * (offsets), {@code model}, {@code geom}. Drawings arrive as contours: the job layer reads them.
 */
package org.fresa.cutting;
