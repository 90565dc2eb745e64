package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.ui.PocketViewModel;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code fresa pocket --strategy adaptive} is refused, with why, until the walks hold their
 * engagement along the walls too: bad input (exit 2), nothing written, whatever the post; the
 * Pocket tab does not offer it.
 */
class AdaptiveRefusedTest {

    @TempDir
    Path dir;

    @ParameterizedTest
    @ValueSource(strings = {"linuxcnc", "iso", "7m", "7m-compat"})
    void adaptiveIsRefusedPlainlyAndWritesNothing(String post) {
        Path out = dir.resolve("a.nc");
        FresaCommandTest.Run r = FresaCommandTest.fresa(
                "pocket",
                "samples/pocket/cavity01.dad",
                "--tool-diameter",
                "6",
                "--post",
                post,
                "--strategy",
                "adaptive",
                "--out",
                out.toString());
        assertEquals(2, r.status(), r.out() + r.err());
        assertTrue(r.err().contains("adaptive clearing is not available yet"), r.err());
        assertTrue(r.err().contains("--strategy"), r.err());
        assertFalse(Files.exists(out));
        assertFalse(PocketViewModel.STRATEGIES.contains("adaptive"), PocketViewModel.STRATEGIES.toString());
    }
}
