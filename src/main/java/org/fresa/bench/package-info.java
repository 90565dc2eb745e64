/**
 * The short benchmarks of {@code fresa bench} (docs/performance.md), beside the JMH suite of the
 * same package ({@code src/jmh/java}, the long versions); their inputs are resources of the jar
 * under {@code /org/fresa/bench/} or generated (the square sheet of the cutting figure).
 *
 * <p>Dependencies: {@code job} (each figure runs a module's service as {@code fresa run} does),
 * {@code stepnc}, {@code dxf}, {@code pocket}, {@code cutting}, {@code post}, {@code kin},
 * {@code model}; never {@code ui} or {@code app}.
 */
package org.fresa.bench;
