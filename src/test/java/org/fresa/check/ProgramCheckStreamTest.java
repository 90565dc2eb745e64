package org.fresa.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * A program file is checked as it is read, block by block: the verdict (the failing block, its
 * line, the count of blocks) is the one the text check gives, whatever the line ends and however
 * the reader hands the text over (a character at a time puts a CR LF across two reads).
 */
class ProgramCheckStreamTest {

    private static final Limits PLASMA = Limits.sheetCutting("plasma", "M3 S1", "M5");

    private static List<String> programs() {
        String good = ProgramCheckTest.GOOD;
        String cut =
                "(sheet)\nG21 G90 G17 G40 G94\n(part 1)\nG0 X1 Y1\nM3 S1\nG1 X5 Y1 F2000\nG3 X5 Y3 I0 J1\nM5\nM2\n";
        List<String> base = List.of(
                good,
                good.replace("S3000 M3\n", ""),
                good.replace("G1 X57.272", "G1 XNaN X57.272"),
                good.replace("F300.0", "F0.0"),
                cut,
                cut.replace("M3 S1\n", ""),
                cut.replace("X5 Y3", "X5 YQ"),
                "",
                "\n",
                "\r",
                "\r\n",
                "M2",
                cut.substring(0, cut.length() - 1));
        List<String> all = new ArrayList<>();
        for (String p : base) {
            all.add(p);
            all.add(p.replace("\n", "\r\n"));
            all.add(p.replace("\n", "\r"));
            all.add(p.replace("\n", "\r\r\n\n"));
        }
        return all;
    }

    /** A reader that gives one character per read, as a slow pipe might. */
    private static Reader trickle(String s) {
        return new Reader() {
            private int i;

            @Override
            public int read(char[] cbuf, int off, int len) {
                if (i == s.length()) {
                    return -1;
                }
                if (len == 0) {
                    return 0;
                }
                cbuf[off] = s.charAt(i++);
                return 1;
            }

            @Override
            public void close() {}
        };
    }

    private static String verdict(ProgramCheck.Verdict v) {
        Optional<Failure> f = v.failure();
        return v.blocks() + " blocks, "
                + f.map(x -> "line " + x.line() + " " + x.rule().name() + ": " + x.message())
                        .orElse("passes");
    }

    @Test
    void aReadProgramHasTheVerdictOfItsText() throws IOException {
        int failing = 0;
        for (String p : programs()) {
            for (NcDialect d : List.of(NcDialect.LINUXCNC, NcDialect.ISO)) {
                for (Limits l : List.of(ProgramCheckTest.MILL, PLASMA)) {
                    String text = verdict(ProgramCheck.of(p, d, l));
                    failing += text.endsWith("passes") ? 0 : 1;
                    String shown = p.replace("\r", "<CR>").replace("\n", "<LF>");
                    assertEquals(text, verdict(ProgramCheck.of(new StringReader(p), d, l)), shown);
                    assertEquals(text, verdict(ProgramCheck.of(trickle(p), d, l)), shown);
                }
            }
        }
        // the cases include refusals, not only programs that pass
        assertEquals(true, failing > 50, failing + " refusals");
    }
}
