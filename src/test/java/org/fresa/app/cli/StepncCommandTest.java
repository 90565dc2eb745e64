package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class StepncCommandTest {

    record Run(int status, String out, String err) {}

    static Run fresa(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = FresaCommand.execute(new PrintWriter(out, true), new PrintWriter(err, true), args);
        return new Run(status, out.toString(), err.toString());
    }

    @Test
    void jsonListsInstancesWorkingstepsAndSkippedAsTheSpecSays() {
        Run r = fresa("stepnc", "samples/stepnc/example2.stp", "--json");
        assertEquals(0, r.status(), r.err());
        String j = r.out();
        assertTrue(
                j.startsWith(
                        "{\"schema\":\"COMBINED_SCHEMA\",\"instances\":732,\"project\":\"3caras\",\"workingsteps\":["),
                j);
        assertTrue(j.contains("\"feature\":{\"type\":\"CLOSED_POCKET\""), j);
        assertTrue(j.contains("\"axis\":[0,-1,0]"), j);
        assertTrue(j.contains("\"strategy\":\"CONTOUR_PARALLEL\""), j);
        assertTrue(j.contains("\"tool\":{\"type\":\"FACEMILL\",\"id\":\"SF20\",\"diameter\":16"), j);
        assertTrue(j.contains("\"skipped\":[{\"id\":\"Plane Base Hole_RGH\",\"instance\":48,\"reason\":"), j);
        assertEquals("", r.err());
    }

    @Test
    void proseDescribesTheWorkplansWithoutJson() {
        Run r = fresa("stepnc", "samples/stepnc/iso14649-11-example1.stp");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("workplan 'MAIN WORKPLAN'"), r.out());
        assertTrue(r.out().contains("5. #14 'WS FINISH POCKET1': BOTTOM_AND_SIDE_FINISH_MILLING"), r.out());
    }

    @Test
    void aDamagedFileExitsWith2AndALineAndNothingOnStdout(@TempDir Path dir) throws Exception {
        String text = Files.readString(Path.of("samples/stepnc/example2.stp"), StandardCharsets.UTF_8);
        Path bad = dir.resolve("bad.stp");
        Files.writeString(
                bad,
                text.replace(
                        "#35=ROUND_HOLE('Plane Base Hole',#2,(#25,#49,#60),",
                        "#35=ROUND_HOLE('Plane Base Hole',#2,((#25,#49,#60),"));
        Run r = fresa("stepnc", bad.toString(), "--json");
        assertEquals(2, r.status());
        assertEquals("", r.out());
        assertTrue(r.err().startsWith("fresa: bad.stp: line "), r.err());
        assertFalse(r.err().contains("Exception"), r.err());
        assertFalse(r.err().contains("\tat "), r.err());
    }

    @Test
    void everyWorkingstepThePlannerLeavesOutIsListedWithItsReason(@TempDir Path dir) throws Exception {
        String text = Files.readString(Path.of("src/test/resources/stepnc/slots-profiles.stp"), StandardCharsets.UTF_8);
        Path file = dir.resolve("woodruff.stp");
        Files.writeString(file, text.replace("#37= FLAT_SLOT_END_TYPE(6.000,4.000);", "#37= LOOP_SLOT_END_TYPE();"));
        Run prose = fresa("stepnc", file.toString());
        assertEquals(0, prose.status(), prose.err());
        assertTrue(
                prose.out()
                        .contains("1 workingstep not planned:\n  #15 'WS SQUARE U ENDS': loop slot ends are"
                                + " machined along a closed course of travel only"),
                prose.out());
        Run json = fresa("stepnc", file.toString(), "--json");
        assertTrue(
                json.out()
                        .contains("\"not_planned\":[{\"id\":\"WS SQUARE U ENDS\",\"instance\":15,\"reason\":"
                                + "\"loop slot ends are machined along a closed course of travel only"),
                json.out());
        assertFalse(fresa("stepnc", "src/test/resources/stepnc/slots-profiles.stp")
                .out()
                .contains("not planned"));
    }
}
