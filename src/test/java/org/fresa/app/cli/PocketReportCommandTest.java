package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.fresa.app.cli.CutCommandTest.Run;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code fresa pocket --report FILE} (the thesis's technology printout) and {@code --thesis-name
 * NAME} (its output name N01NAME.DAD), on the example part with Table 7.2's technology.
 */
class PocketReportCommandTest {

    @TempDir
    Path dir;

    private Run pocket(String... extra) {
        return pocketFrom("6", extra);
    }

    private Run pocketFrom(String zBottom, String... extra) {
        List<String> args = new ArrayList<>(List.of(
                "pocket",
                "samples/pocket/examplepart.dad",
                "--out",
                dir.resolve("examplepart.nc").toString(),
                "--tool-diameter",
                "4",
                "--cut",
                "0.62",
                "--finish",
                "0.18",
                "--z-top",
                "8",
                "--z-bottom",
                zBottom,
                "--max-depth",
                "2",
                "--rpm",
                "3250",
                "--feed",
                "278",
                "--finish-feed",
                "115",
                "--post",
                "7m-compat",
                "--json"));
        args.addAll(Arrays.asList(extra));
        return CutCommandTest.fresa(args.toArray(String[]::new));
    }

    @Test
    void theReportIsTheListingsLprintBlockWithTable72sValues() throws Exception {
        Path report = dir.resolve("examplepart.txt");
        Run r = pocket("--report", report.toString());
        assertEquals(0, r.status(), r.err());
        // Table 7.2 of the thesis: 4, 62 %, 18 %, 8, 6, 2, 1, 2, 3250, 278, 115
        assertEquals("""
                DIAMETRO DA FRESA =          4\s
                 % DE CORTE      =           62 %
                 % DE ACABAMENTO   =         18 %


                 PLANO (Z) DA SUPERFICIE =   8\s
                 PLANO (Z) DA BASE      =    6\s
                 PASSE DE PROFUNDIDADE  =    2\s
                 N DE PASSE DE PROFUND. =    1\s
                 INCREMENTO NA PROFUNDID.=   2\s
                 ROTACAO DA FRESA       =    3250\s
                 AVANCO DA FRESA        =    278\s
                 AVANCO NO ACABAMENTO   =    115\s
                """, Files.readString(report));
        assertTrue(
                r.out().contains("\"report\": \"" + report.toString().replace("\\", "\\\\") + "\"")
                        || r.out().contains("\"report\":\"" + report.toString().replace("\\", "\\\\") + "\""),
                r.out());
        assertTrue(Files.exists(dir.resolve("examplepart.nc")));
    }

    @Test
    void depthPassesAndTheirIncrementAreTheThesisProgramsArithmetic() throws Exception {
        Path report = dir.resolve("r.txt");
        Run r = pocketFrom("5", "--report", report.toString());
        assertEquals(0, r.status(), r.err());
        String text = Files.readString(report);
        // 3 mm at most 2 mm a pass: INT(1.5 + .9999999) = 2 passes of 1.5 mm
        assertTrue(text.contains(" N DE PASSE DE PROFUND. =    2 \n"), text);
        assertTrue(text.contains(" INCREMENTO NA PROFUNDID.=   1.5 \n"), text);
    }

    @Test
    void theThesisNameNamesTheProgramN01NameDad() throws Exception {
        Run r = pocket("--thesis-name", "pg3");
        assertEquals(0, r.status(), r.err());
        Path written = dir.resolve("N01PG3.DAD");
        assertTrue(Files.exists(written), r.out());
        assertFalse(Files.exists(dir.resolve("examplepart.nc")));
        assertTrue(r.out().contains("N01PG3.DAD"), r.out());
        assertTrue(r.out().contains("\"thesis_name\""), r.out());
        assertTrue(Files.readString(written).contains("G01"), "the 7M program");
    }

    @Test
    void aThesisNameTheDiskCouldNotHoldIsBadUsage() {
        for (String bad : List.of("CAVITY", "", "a.b", "c/d")) {
            Run r = pocket("--thesis-name", bad);
            assertEquals(2, r.status(), bad + ": " + r.out());
            assertTrue(r.err().contains("--thesis-name") && r.err().contains("1 to 5 letters or digits"), r.err());
        }
        assertFalse(Files.exists(dir.resolve("examplepart.nc")));
    }

    @Test
    void theReportMayNotReplaceTheProgram() {
        Run r = pocket("--report", dir.resolve("examplepart.nc").toString());
        assertEquals(2, r.status(), r.out());
        assertTrue(r.err().contains("--report"), r.err());
    }
}
