package org.fresa.robustness;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedWriter;
import java.io.PrintWriter;
import java.io.RandomAccessFile;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.fresa.app.cli.FresaCommand;
import org.fresa.dxf.DxfDrawing;
import org.fresa.dxf.DxfReader;
import org.fresa.model.FileChecks;
import org.fresa.stepnc.Part21Reader;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Inputs larger than memory in a 512 MB heap (the {@code low-memory} surefire
 * execution): a file beyond its reader's stated limit is refused with exit 2 before a byte is
 * read, never an OutOfMemoryError; a drawing just below the DXF limit is read whole. The large
 * files are sparse (their size without their bytes), so the test costs no disk.
 */
class InputSizeLowMemoryTest {

    private static final long MIB = 1024 * 1024;

    @TempDir
    Path dir;

    @BeforeEach
    void needsTheLowMemoryExecution() {
        long maxHeap = Runtime.getRuntime().maxMemory();
        assumeTrue(
                maxHeap <= 520 * MIB,
                "needs -Xmx512m (the low-memory surefire execution), has " + maxHeap / MIB + " MiB");
    }

    private Path sparse(String name, long bytes) throws Exception {
        Path p = dir.resolve(name);
        try (RandomAccessFile f = new RandomAccessFile(p.toFile(), "rw")) {
            f.setLength(bytes);
        }
        return p;
    }

    @ParameterizedTest(name = "{0} of 4 GB")
    @CsvSource(textBlock = """
            cut,      big.dxf,      a DXF drawing may have at most
            stepnc,   big.stp,      a Part 21 file may have at most
            pocket,   big.contour,  a contour file may have at most 16 MB
            pocket,   big.dad,      a pocket contour (.dad records) may have at most 16 MB
            grade,    big.contour,  a sole outline (.dxf or .contour) may have at most 16 MB
            run,      big.xml,      a job file may have at most 16 MB
            """)
    void aFileLargerThanItsReadersLimitIsRefusedBeforeItIsRead(String command, String name, String words)
            throws Exception {
        Path big = sparse(name, 4096 * MIB);
        Path out = dir.resolve("out");
        List<String> args = switch (command) {
            case "cut" ->
                List.of("cut", big.toString(), "--out", out.resolve("c.ngc").toString());
            case "stepnc" -> List.of("stepnc", big.toString());
            case "pocket" ->
                List.of("pocket", big.toString(), "--out", out.resolve("p.ngc").toString(), "--tool-diameter", "6");
            case "grade" ->
                List.of(
                        "grade",
                        big.toString(),
                        "--out",
                        out.toString(),
                        "--base-size",
                        "40",
                        "--sizes",
                        "40",
                        "--system",
                        "br");
            default -> List.of("run", big.toString(), "--out", out.toString());
        };
        StringWriter err = new StringWriter();
        int status = FresaCommand.execute(
                new PrintWriter(new StringWriter(), true), new PrintWriter(err, true), args.toArray(String[]::new));
        assertAll(
                err.toString(),
                () -> assertEquals(2, status),
                () -> assertTrue(err.toString().contains("is 4096 MB; " + words), "says " + words),
                () -> assertFalse(err.toString().contains("OutOfMemoryError")),
                () -> assertFalse(Files.exists(out), "nothing written"));
    }

    @org.junit.jupiter.api.Test
    void theStatedLimitsAreShareOfTheHeapThatFit() {
        long heap = Runtime.getRuntime().maxMemory();
        assertAll(
                () -> assertEquals(heap / 8, DxfReader.maxFileBytes()),
                () -> assertEquals(heap / 4, Part21Reader.maxFileBytes()),
                () -> assertTrue(
                        Part21Reader.maxFileBytes() >= 100 * MIB,
                        "the 100 MB Part 21 file of the performance goals fits"),
                () -> assertEquals(16 * MIB, FileChecks.MAX_TEXT_FILE_BYTES));
    }

    @org.junit.jupiter.api.Test
    void aDrawingJustBelowTheLimitIsReadWhole() throws Exception {
        Path big = dir.resolve("squares.dxf");
        int squares = writeSquares(big, DxfReader.maxFileBytes() * 9 / 10);
        DxfDrawing d = DxfReader.read(big);
        assertEquals(4L * squares, d.curves().size());
    }

    /** Unit squares on a grid, four LINEs each, until the file passes minBytes. */
    private static int writeSquares(Path out, long minBytes) throws Exception {
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
                            "0\nLINE\n8\n0\n10\n%.3f\n20\n%.3f\n30\n0.0\n11\n%.3f\n" + "21\n%.3f\n31\n0.0\n",
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
