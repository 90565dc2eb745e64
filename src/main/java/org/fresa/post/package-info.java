/**
 * Post-processors: NC dialects for machine tools and robot program languages, written through a
 * {@link java.io.Writer} with {@code Locale.ROOT} numbers. Dependencies: {@code model},
 * {@code kin}, {@code geom}, and {@code pocket} as a stated exception for now:
 * {@link org.fresa.post.Sinumerik7MPost} posts the 1988 thesis's pocket passes and is to move
 * beside them.
 */
package org.fresa.post;
