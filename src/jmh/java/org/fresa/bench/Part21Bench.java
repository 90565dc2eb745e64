package org.fresa.bench;

import java.io.ByteArrayInputStream;
import java.util.concurrent.TimeUnit;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.StepNcReader;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;

/**
 * {@code part21_mb_per_s}: example 2 read and bound from memory. MB/s = 0.038927 MB times the
 * operations per second reported.
 */
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
public class Part21Bench extends FileInputBench {

    public Part21Bench() {
        super("samples/stepnc/example2.stp");
    }

    @Benchmark
    public StepNcProgram readAndBindExample2() throws Exception {
        return StepNcReader.read(new ByteArrayInputStream(input), "example2.stp");
    }
}
