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

    /**
     * The slowed moves listed for review are the program's own: every row's feed is an F word of
     * the program below --feed, its fraction is that feed over --feed, and the rows cover the
     * length the summary gives for each of the 2 layers.
     */
    @Test
    void theSlowedMovesAreListedAsTheProgramCutsThem(@TempDir Path dir) throws Exception {
        Path out = dir.resolve("a.ngc");
        Path csv = dir.resolve("slowed.csv");
        FresaCommandTest.Run r = FresaCommandTest.fresa(
                "pocket",
                "samples/pocket/rooms-islands.contour",
                "--tool-diameter",
                "6",
                "--cut",
                "0.4",
                "--z-bottom",
                "-4",
                "--max-depth",
                "2",
                "--feed",
                "300",
                "--strategy",
                "adaptive",
                "--slowed",
                csv.toString(),
                "--json",
                "--out",
                out.toString());
        assertEquals(0, r.status(), r.out() + r.err());
        assertTrue(r.out().contains("slowed_csv"), r.out());
        java.util.List<String> rows = Files.readAllLines(csv);
        assertEquals(
                "layer_z_mm,move,x_start_mm,y_start_mm,x_end_mm,y_end_mm,length_mm,feed_mm_per_min,feed_factor",
                rows.get(0));
        assertTrue(rows.size() > 1, "rooms-islands at cut 0.4 has slowed stretches");
        String nc = Files.readString(out);
        double length = 0;
        java.util.Set<String> layers = new java.util.TreeSet<>();
        for (String row : rows.subList(1, rows.size())) {
            String[] f = row.split(",");
            assertEquals(9, f.length, row);
            double feed = Double.parseDouble(f[7]);
            assertTrue(feed < 300 && feed >= 15, row);
            String word = String.format(java.util.Locale.ROOT, "F%.1f", feed);
            assertTrue(nc.contains(word + "\n") || nc.contains(word + " "), word + " in the program");
            assertEquals(feed / 300, Double.parseDouble(f[8]), 0.0006, row);
            assertTrue(java.util.Set.of("line", "arc_ccw", "arc_cw").contains(f[1]), row);
            length += Double.parseDouble(f[6]);
            layers.add(f[0]);
        }
        assertEquals(java.util.Set.of("-2.000", "-4.000"), layers);
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("\"slowed_length_mm\"\\s*:\\s*([0-9.]+)")
                .matcher(r.out());
        assertTrue(m.find(), r.out());
        // the summary's length is a layer's slowed cuts; the rows add the links into them, every layer
        assertTrue(length >= 2 * Double.parseDouble(m.group(1)) - 0.01, length + " against " + m.group(1));
    }

    @Test
    void aListOfSlowedMovesIsRefusedForAStrategyThatSlowsNone(@TempDir Path dir) {
        Path out = dir.resolve("o.ngc");
        FresaCommandTest.Run r = FresaCommandTest.fresa(
                "pocket",
                "samples/pocket/rooms-islands.contour",
                "--tool-diameter",
                "6",
                "--slowed",
                dir.resolve("s.csv").toString(),
                "--out",
                out.toString());
        assertEquals(2, r.status(), r.out() + r.err());
        assertTrue(r.err().contains("--slowed: only adaptive clearing slows its feed"), r.err());
        assertTrue(Files.notExists(out));
        assertTrue(Files.notExists(dir.resolve("s.csv")));
    }
}
