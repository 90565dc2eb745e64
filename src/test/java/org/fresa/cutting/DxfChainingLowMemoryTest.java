package org.fresa.cutting;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.fresa.dxf.DxfDrawing;
import org.fresa.dxf.DxfReader;
import org.fresa.testing.CorpusCheck;
import org.fresa.testing.TestInputs;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A 10 MB DXF drawing is read and chained within a 512 MB heap, and so is the largest
 * corpus drawing. Runs in the {@code low-memory} surefire execution ({@code -Xmx512m}); skipped
 * in a larger heap, where it would prove nothing.
 */
class DxfChainingLowMemoryTest {

    private static final long MIB = 1024 * 1024;
    private static final Path CORPUS_FILE = TestInputs.DXF_CORPUS.resolve("ezdxf/examples_edgeminer_3_us_main.dxf");

    @TempDir
    Path dir;

    @Test
    void aTenMegabyteDrawingOfSquaresIsReadAndChainedIn512Megabytes() throws Exception {
        assumeLowMemory();
        Path big = dir.resolve("squares.dxf");
        int squares = writeSquares(big, 10 * MIB);
        assertTrue(Files.size(big) >= 10 * MIB);

        DxfDrawing d = DxfReader.read(big);
        Chainer.Chains chains = Chainer.chain(d.curves(), 0.001);

        assertAll(
                () -> assertEquals(4 * squares, d.curves().size()),
                () -> assertEquals(squares, chains.closed().size()),
                () -> assertEquals(0, chains.open().size()));
    }

    @Test
    @CorpusCheck
    void theLargestCorpusDrawingIsReadAndChainedIn512Megabytes() throws Exception {
        assumeLowMemory();
        assumeTrue(Files.isRegularFile(CORPUS_FILE), "corpus absent");

        DxfDrawing d = DxfReader.read(CORPUS_FILE);
        Chainer.Chains chains = Chainer.chain(d.curves(), 0.001);

        assertEquals(10_052, d.curves().size());
        assertTrue(chains.closed().size() + chains.open().size() > 0);
    }

    private static void assumeLowMemory() {
        long maxHeap = Runtime.getRuntime().maxMemory();
        assumeTrue(
                maxHeap <= 520 * MIB,
                "needs -Xmx512m (the low-memory surefire execution), has " + maxHeap / MIB + " MiB");
    }

    /** Unit squares 2 mm apart on a grid, four LINEs each, until the file passes minBytes. */
    private static int writeSquares(Path out, long minBytes) throws IOException {
        int n = 0;
        long written = 0;
        try (BufferedWriter w = Files.newBufferedWriter(out, StandardCharsets.US_ASCII)) {
            w.write("0\nSECTION\n2\nENTITIES\n");
            while (written < minBytes) {
                double x = (n % 1000) * 2.0;
                double y = (n / 1000) * 2.0;
                double[][] c = {{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}};
                for (int k = 0; k < 4; k++) {
                    double[] a = c[k];
                    double[] b = c[(k + 1) % 4];
                    String line = String.format(
                            Locale.ROOT,
                            "0\nLINE\n8\n0\n10\n%.3f\n20\n%.3f\n30\n0.0\n11\n%.3f\n21\n%.3f\n31\n0.0\n",
                            a[0],
                            a[1],
                            b[0],
                            b[1]);
                    w.write(line);
                    written += line.length();
                }
                n++;
            }
            w.write("0\nENDSEC\n0\nEOF\n");
        }
        return n;
    }
}
