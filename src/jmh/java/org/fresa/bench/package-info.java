/**
 * JMH benchmarks for the performance figures (the long versions of {@code fresa bench}): built
 * only with the {@code benchmark} Maven profile, run with
 * {@code java -cp target/fresa.jar org.openjdk.jmh.Main}; see docs/performance.md. Inputs are
 * found relative to the system property {@code fresa.root} (default: the working directory).
 */
package org.fresa.bench;
