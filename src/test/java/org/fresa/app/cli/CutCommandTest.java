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

    record Run(int status, String out, String err) {
    }

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
                + String.format(line, "A2", "10", "0", "10", "10") + String.format(line, "A3", "10", "10", thirdEndX, "10")
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
        assertAll(() -> assertEquals(2, r.status()),
                () -> assertEquals("fresa: d.dxf: " + message + "\n", r.err()),
                () -> assertFalse(Files.exists(dir.resolve("d.ngc"))));
    }

    @Test
    void aMissingCoordinateRefusesTheDrawingWithTheEntitysLine() throws IOException {
        Run r = cut(square("0").replace("11\n0\n21\n10\n", "11\n0\n"));
        assertAll(() -> assertEquals(2, r.status()),
                () -> assertEquals("fresa: d.dxf: line 34: LINE A3: group 21 (a y coordinate) is missing\n", r.err()));
    }

    @Test
    void aDrawingCutShortBeforeItsEofIsRefused() throws IOException {
        String whole = square("0");
        Run r = cut(whole.substring(0, whole.indexOf("0\nLINE\n5\nA4")));
        assertAll(() -> assertEquals(2, r.status()),
                () -> assertTrue(r.err().contains("d.dxf: line 46: the drawing ends without its closing group 0 EOF"
                        + " (the file is truncated)"), r.err()),
                () -> assertFalse(Files.exists(dir.resolve("d.ngc"))));
    }
}
