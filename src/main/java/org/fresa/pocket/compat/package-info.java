/**
 * The 1988 thesis's own arithmetic, for the {@code 7m-compat} post only: Microsoft Binary Format
 * single precision as the 8086 BASIC math package computes it ({@link org.fresa.pocket.compat.Mbf}),
 * BASIC's {@code STR$}/{@code VAL} ({@link org.fresa.pocket.compat.BasicNumbers}), the program's
 * intersection routine ({@link org.fresa.pocket.compat.ThesisJunction}) and its pass-to-pass
 * chain of offsets written back as text ({@link org.fresa.pocket.compat.ThesisPasses}). Units mm.
 * Dependencies: {@code pocket}, {@code geom}; nothing outside the compat post uses this package,
 * and Fresa's own planning stays in double precision.
 *
 * <p>Robustness: the emulation is exact integer arithmetic on the 24-bit mantissas; where the
 * thesis's program would stop (no junction, parallel lines) the recomputation returns empty and
 * the post keeps the exact junctions.
 */
package org.fresa.pocket.compat;
