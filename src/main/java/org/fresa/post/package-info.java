/**
 * Post-processors: NC dialects for machine tools and robot program languages, written through a
 * {@link java.io.Writer} with {@code Locale.ROOT} numbers. Dependencies: {@code model},
 * {@code kin}, {@code geom}.
 */
package org.fresa.post;
