package org.fresa.bench;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * A generated sheet drawing of small square parts, as a nesting program writes one for a large
 * order: ASCII DXF, four LINEs per square, squares of {@value #SIDE_MM} mm on a
 * {@value #PITCH_MM} mm pitch in rows of {@value #PER_ROW}. 181 750 squares (727 000 LINEs) make
 * a 50 MB file; it measures how cutting scales (the benchmark's {@code cut_parts_per_s}, the
 * low-memory test).
 */
public final class SquareSheet {

    /** Side of a square part (mm): room for the default 3 mm lead-in beside a 2 mm kerf. */
    public static final double SIDE_MM = 10;
    /** Distance between square corners (mm). */
    public static final double PITCH_MM = 20;
    /** Squares in a row. */
    public static final int PER_ROW = 430;
    /** The squares of the 50 MB drawing. */
    public static final int FIFTY_MB_SQUARES = 181_750;

    private SquareSheet() {}

    /** Writes {@code squares} squares to {@code out} (overwritten). */
    public static void write(Path out, int squares) throws IOException {
        try (BufferedWriter w = Files.newBufferedWriter(out, StandardCharsets.US_ASCII)) {
            w.write("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n");
            StringBuilder sb = new StringBuilder(512);
            for (int n = 0; n < squares; n++) {
                double x = (n % PER_ROW) * PITCH_MM;
                double y = (n / PER_ROW) * PITCH_MM;
                double[][] c = {{x, y}, {x + SIDE_MM, y}, {x + SIDE_MM, y + SIDE_MM}, {x, y + SIDE_MM}};
                sb.setLength(0);
                for (int k = 0; k < 4; k++) {
                    double[] a = c[k];
                    double[] b = c[(k + 1) % 4];
                    sb.append(String.format(
                            Locale.ROOT,
                            "0\nLINE\n8\n0\n10\n%.3f\n20\n%.3f\n30\n0.0\n11\n%.3f\n21\n%.3f\n31\n0.0\n",
                            a[0],
                            a[1],
                            b[0],
                            b[1]));
                }
                w.write(sb.toString());
            }
            w.write("0\nENDSEC\n0\nEOF\n");
        }
    }
}
