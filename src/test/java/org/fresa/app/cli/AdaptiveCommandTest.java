package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.ui.PocketViewModel;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code fresa pocket --strategy adaptive} writes its program and says what it slowed; the Pocket tab offers it. */
class AdaptiveCommandTest {

    @Test
    void theCommandLineAndThePocketTabOfferIt(@TempDir Path dir) {
        Path out = dir.resolve("a.ngc");
        FresaCommandTest.Run r = FresaCommandTest.fresa(
                "pocket",
                "samples/pocket/rooms-islands.contour",
                "--tool-diameter",
                "6",
                "--cut",
                "0.4",
                "--strategy",
                "adaptive",
                "--json",
                "--out",
                out.toString());
        assertEquals(0, r.status(), r.out() + r.err());
        assertTrue(
                r.out().contains("\"strategy\":\"adaptive\"") || r.out().contains("\"strategy\": \"adaptive\""),
                r.out());
        assertTrue(r.out().contains("slowed_cuts"), r.out());
        assertTrue(Files.exists(out));
        assertTrue(PocketViewModel.STRATEGIES.contains("adaptive"), PocketViewModel.STRATEGIES.toString());
    }
}
