package org.fresa.bench;

import java.io.ByteArrayInputStream;
import java.util.concurrent.TimeUnit;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.StepNcReader;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * {@code part21_mb_per_s}: example 2 read and bound from memory. MB/s = 0.038927 MB times the
 * operations per second reported.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 5, time = 1)
@Measurement(iterations = 10, time = 1)
@Fork(2)
public class Part21Bench {

    private byte[] example2;

    @Setup
    public void load() {
        example2 = Inputs.bytes("samples/stepnc/example2.stp");
    }

    @Benchmark
    public StepNcProgram readAndBindExample2() throws Exception {
        return StepNcReader.read(new ByteArrayInputStream(example2), "example2.stp");
    }
}
