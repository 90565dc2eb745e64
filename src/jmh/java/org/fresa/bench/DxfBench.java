package org.fresa.bench;

import java.util.concurrent.TimeUnit;
import org.fresa.cutting.Chainer;
import org.fresa.dxf.DxfDrawing;
import org.fresa.dxf.DxfReadOptions;
import org.fresa.dxf.DxfReader;
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
 * {@code dxf_mb_per_s}: the 10 052-line corpus drawing read and chained from memory. MB/s =
 * 1.80959 MB divided by the seconds per operation reported.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 5, time = 1)
@Measurement(iterations = 10, time = 1)
@Fork(2)
public class DxfBench {

    private byte[] drawing;

    @Setup
    public void load() {
        drawing = Inputs.bytes("../shared/corpus/dxf/ezdxf/examples_edgeminer_3_us_main.dxf");
    }

    @Benchmark
    public Chainer.Chains readAndChainCorpusDrawing() throws Exception {
        DxfDrawing d = DxfReader.read(drawing, "bench.dxf", DxfReadOptions.DEFAULT);
        return Chainer.chain(d.curves(), 0.001);
    }
}
