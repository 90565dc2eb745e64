/**
 * Shoe-size grading of sole outlines (the 1986 thesis's pantograph). Dependencies: {@code geom},
 * {@code model}.
 */
package org.fresa.grading;
