/**
 * Post-processors: NC dialects for machine tools and robot program languages, written through a
 * {@link java.io.Writer} with {@code Locale.ROOT} numbers; {@link org.fresa.post.Dialect} gives each
 * control's words to the milling and sheet-cutting posts alike. The thesis's 7M post, which posts
 * the pocket module's passes rather than a toolpath, lives beside the thesis's arithmetic in
 * {@code pocket.compat}, so that no post needs the pocket module.
 * Dependencies: {@code model}, {@code geom}.
 */
package org.fresa.post;
