package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;

class RobotsCommandTest {

    @Test
    void theBuiltInRobotsAreListedWithTheirTables() {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = FresaCommand.execute(new PrintWriter(out), new PrintWriter(err), "robots");
        assertEquals(0, status, err::toString);
        String text = out.toString();
        assertTrue(text.contains("irb140:") && text.contains("adept-one:") && text.contains("tricept806:"), text);
        assertTrue(text.contains("theta q - 90"), text);
        assertTrue(text.contains("r_b 500 mm, r_p 200 mm, d_eff 400 mm, e_ffl 250 mm"), text);
    }

    @Test
    void withJsonTheyArePrintedAsOneObject() {
        StringWriter out = new StringWriter();
        int status =
                FresaCommand.execute(new PrintWriter(out), new PrintWriter(new StringWriter()), "robots", "--json");
        assertEquals(0, status);
        String json = out.toString().trim();
        assertTrue(json.startsWith("{\"robots\":[") && json.endsWith("}"), json);
        assertTrue(json.contains("\"d_mm\":352"), json);
    }
}
