package org.fresa.bench;

import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * The shared set-up of the benches that read one input file from memory: the suite's warm-up,
 * measurement and forks, and the file's bytes loaded once per trial. Subclasses add their mode
 * and time unit.
 */
@State(Scope.Thread)
@Warmup(iterations = 5, time = 1)
@Measurement(iterations = 10, time = 1)
@Fork(2)
public abstract class FileInputBench {

    private final String relative;

    /** The input's bytes, after {@link #load}. */
    protected byte[] input;

    /** @param relative the input file, relative to the project checkout ({@link Inputs#root}) */
    protected FileInputBench(String relative) {
        this.relative = relative;
    }

    @Setup
    public void load() {
        input = Inputs.bytes(relative);
    }
}
