package org.fresa.bench;

import java.util.concurrent.TimeUnit;
import org.fresa.cutting.Chainer;
import org.fresa.dxf.DxfDrawing;
import org.fresa.dxf.DxfReadOptions;
import org.fresa.dxf.DxfReader;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;

/**
 * {@code dxf_mb_per_s}: the 10 052-line corpus drawing read and chained from memory. MB/s =
 * 1.80959 MB divided by the seconds per operation reported.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class DxfBench extends FileInputBench {

    public DxfBench() {
        super("src/test/resources/corpus/dxf/ezdxf/examples_edgeminer_3_us_main.dxf");
    }

    @Benchmark
    public Chainer.Chains readAndChainCorpusDrawing() throws Exception {
        DxfDrawing d = DxfReader.read(input, "bench.dxf", DxfReadOptions.DEFAULT);
        return Chainer.chain(d.curves(), 0.001);
    }
}
