/**
 * Sole moulds: tread figures, cavity, sizes and both feet. Dependencies: {@code grading},
 * {@code pocket}, {@code model}, {@code geom}.
 */
package org.fresa.sole;
