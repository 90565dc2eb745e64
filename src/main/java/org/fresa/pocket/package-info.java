/**
 * Pocket milling of line/arc contours from the inside out (the 1988 thesis): exact offsets,
 * the recognition tree, passes. Dependencies: {@code geom}, {@code model}.
 */
package org.fresa.pocket;
