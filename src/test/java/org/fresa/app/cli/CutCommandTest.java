package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** {@code fresa cut}: what a broken drawing does to the exit status, and what the planner is told. */
class CutCommandTest {

    @TempDir
    Path dir;

    record Run(int status, String out, String err) {}

    static Run fresa(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = FresaCommand.execute(new PrintWriter(out, true), new PrintWriter(err, true), args);
        return new Run(status, out.toString(), err.toString());
    }

    /** A 10 x 10 square of LINEs; the third line's end x is the given text. */
    static String square(String thirdEndX) {
        String line = "0\nLINE\n5\n%s\n8\n0\n10\n%s\n20\n%s\n11\n%s\n21\n%s\n";
        return "0\nSECTION\n2\nENTITIES\n" + String.format(line, "A1", "0", "0", "10", "0")
                + String.format(line, "A2", "10", "0", "10", "10")
                + String.format(line, "A3", "10", "10", thirdEndX, "10")
                + String.format(line, "A4", "0", "10", "0", "0") + "0\nENDSEC\n0\nEOF\n";
    }

    Run cut(String drawing) throws IOException {
        Path in = dir.resolve("d.dxf");
        Files.writeString(in, drawing);
        return fresa("cut", in.toString(), "--out", dir.resolve("d.ngc").toString());
    }

    @Test
    void aWholeSquareIsCut() throws IOException {
        Run r = cut(square("0"));
        assertEquals(0, r.status(), r.err());
    }

    @Test
    void aDrawingWithNoClosedContourWritesNoProgram() throws IOException {
        // the square with its third line 5 mm short: one open chain
        Run r = cut(square("5"));
        assertAll(
                () -> assertEquals(1, r.status(), r.err()),
                () -> assertTrue(r.err().contains("nothing to cut: the drawing has no closed contour"), r.err()),
                () -> assertFalse(Files.exists(dir.resolve("d.ngc"))));
    }

    // the third LINE is named on line 34, its group 11 value is on line 44
    @ParameterizedTest(name = "end x ''{0}''")
    @CsvSource(textBlock = """
            abc,      line 44: LINE A3 (from line 34): group 11 is 'abc': expected an x coordinate (a finite number)
            NaN,      line 44: LINE A3 (from line 34): group 11 is 'NaN': expected an x coordinate (a finite number)
            Infinity, line 44: LINE A3 (from line 34): group 11 is 'Infinity': expected an x coordinate (a finite number)
            1e999,    line 44: LINE A3 (from line 34): group 11 is '1e999': expected an x coordinate (a finite number)
            """)
    void aCoordinateThatIsNotANumberRefusesTheDrawingWithItsLine(String x, String message) throws IOException {
        Run r = cut(square(x));
        assertAll(
                () -> assertEquals(2, r.status()),
                () -> assertEquals("fresa: d.dxf: " + message + "\n", r.err()),
                () -> assertFalse(Files.exists(dir.resolve("d.ngc"))));
    }

    @Test
    void aMissingCoordinateRefusesTheDrawingWithTheEntitysLine() throws IOException {
        Run r = cut(square("0").replace("11\n0\n21\n10\n", "11\n0\n"));
        assertAll(
                () -> assertEquals(2, r.status()),
                () -> assertEquals("fresa: d.dxf: line 34: LINE A3: group 21 (a y coordinate) is missing\n", r.err()));
    }

    @Test
    void aDrawingCutShortBeforeItsEofIsRefused() throws IOException {
        String whole = square("0");
        Run r = cut(whole.substring(0, whole.indexOf("0\nLINE\n5\nA4")));
        assertAll(
                () -> assertEquals(2, r.status()),
                () -> assertTrue(
                        r.err()
                                .contains("d.dxf: line 46: the drawing ends without its closing group 0 EOF"
                                        + " (the file is truncated)"),
                        r.err()),
                () -> assertFalse(Files.exists(dir.resolve("d.ngc"))));
    }

    /** A 200 x 200 plate with 30 square holes of 1 mm, too small for the default 2 mm kerf. */
    static String plateWithTinyHoles() {
        StringBuilder sb = new StringBuilder("0\nSECTION\n2\nENTITIES\n");
        sb.append(poly(0, 0, 200));
        for (int k = 0; k < 30; k++) {
            sb.append(poly(10 + 6 * k, 100, 1));
        }
        return sb.append("0\nENDSEC\n0\nEOF\n").toString();
    }

    static String poly(double x, double y, double side) {
        return String.format(
                java.util.Locale.ROOT,
                "0\nLWPOLYLINE\n90\n4\n70\n1\n10\n%s\n20\n%s\n10\n%s\n20\n%s\n10\n%s\n20\n%s\n" + "10\n%s\n20\n%s\n",
                x,
                y,
                x + side,
                y,
                x + side,
                y + side,
                x,
                y + side);
    }

    @Test
    void everyContourNotCutIsNamedAndPlacedOnTheTerminalAndInTheJson() throws IOException {
        Path in = dir.resolve("holes.dxf");
        Files.writeString(in, plateWithTinyHoles());
        Run r = fresa("cut", in.toString(), "--out", dir.resolve("h.ngc").toString());
        Run j = fresa("cut", in.toString(), "--out", dir.resolve("h.ngc").toString(), "--json");
        long named = r.err()
                .lines()
                .filter(l -> l.matches("fresa: part 1 hole \\d+ \\(1\\.000 x 1\\.000 mm at \\d+\\.000,"
                        + " 100\\.000\\) is too small for a 2\\.000 mm kerf: not cut"))
                .count();
        assertAll(
                () -> assertEquals(1, r.status()),
                () -> assertEquals(30, named, r.err()),
                () -> assertFalse(r.err().contains("more warnings"), r.err()),
                () -> assertTrue(
                        r.err()
                                .contains("fresa: part 1 hole 30 (1.000 x 1.000 mm at 184.000, 100.000) is too"
                                        + " small"),
                        r.err()),
                () -> assertTrue(
                        j.out().contains("\"not_cut_contours\":[{\"contour\":\"part 1 hole 1\",\"x_mm\":"), j.out()),
                () -> assertEquals(
                        30, j.out().split("\"reason\":\"is too small for a 2.000 mm kerf\"", -1).length - 1, j.out()));
    }

    @Test
    void thePapersInvalidVerticesAreListedWithTheirPlaces() throws IOException {
        // the paper's rule: the four sharp corners of a square hole are concave for the nozzle
        Path in = dir.resolve("square-hole.dxf");
        Files.writeString(in, "0\nSECTION\n2\nENTITIES\n" + poly(0, 0, 100) + poly(40, 40, 20) + "0\nENDSEC\n0\nEOF\n");
        Run r = fresa("cut", in.toString(), "--out", dir.resolve("s.ngc").toString(), "--paper-mode", "--json");
        assertAll(
                () -> assertTrue(
                        r.out().contains("\"invalid_vertex_points\":[[40,40],[60,40],[60,60],[40,60]]"), r.out()),
                () -> assertEquals(
                        4,
                        r.err()
                                .lines()
                                .filter(l -> l.startsWith("fresa: invalid vertex of part 1 hole 1 at ("))
                                .count(),
                        r.err()),
                () -> assertTrue(r.err().contains("invalid vertex of part 1 hole 1 at (40.000, 40.000)"), r.err()));
    }
}
