package org.fresa.post;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.fresa.model.Toolpath;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

public class NcPostsTest {

    private static final Path GOLDEN = Path.of("src/test/resources/org/fresa/post");

    static String program(String post, Toolpath path) throws IOException {
        StringWriter w = new StringWriter();
        NcPosts.byName(post).orElseThrow().write(path, "mixed sample", w);
        return w.toString();
    }

    /** The 840D program in RS274/NGC words, so LinuxCNC can check its motions. */
    public static String siemensAsNgc(String program) {
        StringBuilder sb = new StringBuilder();
        for (String line : program.split("\n")) {
            if (line.startsWith("%_N_") || line.startsWith(";$PATH")) {
                continue;
            }
            String l = line.replace("G71 ", "G21 ")
                    .replace(" G60", " G61")
                    .replaceAll(" D1$", "")
                    .replaceAll("^(N\\d+ )?G4 F", "$1G4 P");
            java.util.regex.Matcher m =
                    java.util.regex.Pattern.compile("TURN=(\\d+)").matcher(l);
            if (m.find()) {
                l = m.replaceFirst("P" + (Integer.parseInt(m.group(1)) + 1));
            }
            sb.append(l).append('\n');
        }
        return sb.toString();
    }

    @ParameterizedTest
    @ValueSource(strings = {"linuxcnc", "iso", "fanuc", "840d"})
    void eachPostWritesTheMixedSampleAsItsGoldenFile(String post) throws IOException {
        String text = program(post, SampleToolpaths.mixed());
        Path golden = GOLDEN.resolve("mixed." + post + ".nc");
        if (Boolean.getBoolean("fresa.updateGolden")) {
            Files.writeString(golden, text, StandardCharsets.UTF_8);
        }
        assertEquals(Files.readString(golden, StandardCharsets.UTF_8), text);
    }

    @ParameterizedTest
    @ValueSource(strings = {"linuxcnc", "iso", "fanuc", "840d"})
    @InterpreterCheck
    void linuxCncsInterpreterMakesExactlyTheToolpathsMotions(String post, @TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        Toolpath path = SampleToolpaths.mixed();
        String text = program(post, path);
        // 840D words LinuxCNC lacks (G71, D1, TURN=) are mapped to their RS274 twins; the rest is read as is
        if (post.equals("840d")) {
            text = siemensAsNgc(text);
        }
        Path file = dir.resolve("p.ngc");
        Files.writeString(file, text);
        Rs274.Result r = Rs274.run(file, 10);
        assertEquals(0, r.exitStatus(), r.stderr());
        boolean split = post.equals("iso") || post.equals("fanuc");
        List<Rs274.Canon> expected = ExpectedMotions.of(path, split, NcPosts.CHORD_TOLERANCE_MM);
        assertNull(ExpectedMotions.firstDifference(expected, r.motions(), 0.0011));
    }

    @ParameterizedTest
    @ValueSource(strings = {"linuxcnc", "iso", "fanuc", "840d"})
    void eachPostWritesTheDrillingSampleWithDwellsAndSpindleEventsAsItsGoldenFile(String post) throws IOException {
        String text = program(post, SampleToolpaths.drilling());
        Path golden = GOLDEN.resolve("drilling." + post + ".nc");
        if (Boolean.getBoolean("fresa.updateGolden")) {
            Files.writeString(golden, text, StandardCharsets.UTF_8);
        }
        assertEquals(Files.readString(golden, StandardCharsets.UTF_8), text);
    }

    /** The dwell block of each dialect, as documented on the posts. */
    @Test
    void eachPostWritesADwellInItsOwnWordsInSeconds() throws IOException {
        assertTrue(program("linuxcnc", SampleToolpaths.drilling()).contains("\nG4 P1.250\n"));
        assertTrue(program("iso", SampleToolpaths.drilling()).matches("(?s).*\nN\\d+ G04 X1\\.250\n.*"));
        assertTrue(program("fanuc", SampleToolpaths.drilling()).matches("(?s).*\nN\\d+ G04 X1\\.250\n.*"));
        assertTrue(program("840d", SampleToolpaths.drilling()).matches("(?s).*\nN\\d+ G4 F1\\.250\n.*"));
    }

    @Test
    void aSpindleStoppedOrReversedInASectionIsStartedAgainByTheNext() throws IOException {
        List<String> lines =
                program("linuxcnc", SampleToolpaths.drilling()).lines().toList();
        int bore = lines.indexOf("(WS2 bore tool 4 D12.000)");
        int reversed = lines.indexOf("(WS3 reversed tool 4 D12.000)");
        int ws4 = lines.indexOf("(WS4 tool 4 D12.000)");
        assertEquals(
                List.of("G4 P2.000", "M5", "G1 X50.000 Y20.000 Z5.000", "S800 M3", "G0 X50.000 Y20.000 Z30.000"),
                lines.subList(lines.indexOf("G1 X50.000 Y20.000 Z-15.000 F80.0") + 1, reversed));
        // same tool and speed, spindle running clockwise: no new start for WS3's own speed, then M4
        assertEquals(
                List.of("(WS3 reversed tool 4 D12.000)", "G0 X50.000 Y20.000 Z30.000", "S800 M4"),
                lines.subList(reversed, reversed + 3));
        assertEquals(List.of("(WS4 tool 4 D12.000)", "S800 M3"), lines.subList(ws4, ws4 + 2));
        assertTrue(bore > 0);
    }

    /**
     * LinuxCNC reads every post's drilling sample (dwell words mapped to G4 P where the dialect's
     * differ) with exactly the toolpath's motions and dwells, and stops and starts the spindle
     * where the toolpath says.
     */
    @ParameterizedTest
    @ValueSource(strings = {"linuxcnc", "iso", "fanuc", "840d"})
    @InterpreterCheck
    void linuxCncsInterpreterDwellsWhereTheToolpathDoes(String post, @TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        Toolpath path = SampleToolpaths.drilling();
        String text = program(post, path);
        text = post.equals("840d") ? siemensAsNgc(text) : text.replaceAll("(?m)^(N\\d+ )?G04 X", "$1G04 P");
        Path file = dir.resolve("d.ngc");
        Files.writeString(file, text);
        Rs274.Result r = Rs274.run(file, 10);
        assertEquals(0, r.exitStatus(), Rs274.log(r));
        List<Rs274.Canon> expected = ExpectedMotions.of(path, false, NcPosts.CHORD_TOLERANCE_MM);
        assertEquals(
                2 + 1, expected.stream().filter(c -> c.kind().equals("dwell")).count());
        assertNull(ExpectedMotions.firstDifference(expected, r.motions(), 0.0011));
        // in the boring: dwell, stop, out at feed, start at 800 rpm, the rapid up; WS3's start, then M4
        List<String> calls = r.stdout()
                .lines()
                .map(l -> l.replaceFirst("^\\s*\\d+\\s+N\\S+\\s+", ""))
                .filter(l -> l.matches("(DWELL|STOP_SPINDLE|START_SPINDLE|SET_SPINDLE_SPEED|STRAIGHT_).*"))
                .toList();
        int at = calls.indexOf("DWELL(2.0000)");
        assertEquals(
                List.of(
                        "DWELL(2.0000)",
                        "STOP_SPINDLE_TURNING(0)",
                        "STRAIGHT_FEED(50.0000, 20.0000, 5.0000, 0.0000, 0.0000, 0.0000)",
                        "SET_SPINDLE_SPEED(0, 800.0000)",
                        "START_SPINDLE_CLOCKWISE(0)",
                        "STRAIGHT_TRAVERSE(50.0000, 20.0000, 30.0000, 0.0000, 0.0000, 0.0000)",
                        "STRAIGHT_TRAVERSE(50.0000, 20.0000, 30.0000, 0.0000, 0.0000, 0.0000)",
                        "SET_SPINDLE_SPEED(0, 800.0000)",
                        "START_SPINDLE_COUNTERCLOCKWISE(0)"),
                calls.subList(at, Math.min(calls.size(), at + 9)),
                String.join("\n", calls));
    }

    @Test
    void numbersUseAPointWhateverTheDefaultLocale() throws IOException {
        Locale saved = Locale.getDefault();
        try {
            Locale.setDefault(Locale.GERMANY);
            String text = program("linuxcnc", SampleToolpaths.mixed());
            assertTrue(text.contains("X10.000 Y10.000 Z-1.000 F300.0"), text);
            assertFalse(text.matches("(?s).*\\d,\\d.*"));
        } finally {
            Locale.setDefault(saved);
        }
    }

    @Test
    void postsAreFoundByNameIgnoringCaseAndUnknownNamesAreEmpty() {
        assertEquals("840d", NcPosts.byName("840D").orElseThrow().name());
        assertEquals("linuxcnc", NcPosts.byName(" LinuxCNC ").orElseThrow().name());
        assertTrue(NcPosts.byName("heidenhain").isEmpty());
        assertEquals(List.of("linuxcnc", "iso", "fanuc", "840d", "apt"), NcPosts.names());
        assertEquals("linuxcnc", NcPosts.defaultPost().name());
    }

    @Test
    void aTiltedArcIsReplacedByChordsWithinTheTolerance() throws IOException {
        String text = program("linuxcnc", SampleToolpaths.mixed());
        // the tilted half circle of radius 5 at 0.001 mm needs
        // ceil(pi / (2 acos(1 - 0.001 / 5))) = ceil(78.5) = 79 chords
        long g1InWs2 = text.lines()
                .dropWhile(l -> !l.startsWith("(WS2"))
                .takeWhile(l -> !l.startsWith("(WS3"))
                .filter(l -> l.startsWith("G1 "))
                .count();
        assertEquals(1 + 79, g1InWs2);
    }
}
