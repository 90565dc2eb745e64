/**
 * The 1988 thesis's Sinumerik 7M post ({@link org.fresa.pocket.compat.Sinumerik7MPost}, the
 * {@code 7m} and {@code 7m-compat} posts) and its own arithmetic, for {@code 7m-compat}:
 * Microsoft Binary Format single precision as the 8086 BASIC math package computes it ({@link org.fresa.pocket.compat.Mbf}),
 * BASIC's {@code STR$}/{@code VAL} ({@link org.fresa.pocket.compat.BasicNumbers}), the program's
 * intersection routine ({@link org.fresa.pocket.compat.ThesisJunction}) and its pass-to-pass
 * chain of offsets written back as text ({@link org.fresa.pocket.compat.ThesisPasses}). Units mm.
 * Dependencies: {@code pocket}, {@code model}, {@code geom}; nothing outside the 7M post uses the
 * arithmetic, and Fresa's own planning stays in double precision.
 *
 * <p>Robustness: the emulation is exact integer arithmetic on the 24-bit mantissas; where the
 * thesis's program would stop (no junction, parallel lines) the recomputation returns empty and
 * the post keeps the exact junctions.
 */
package org.fresa.pocket.compat;
