package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.MillingDirection;
import org.fresa.pocket.PocketStrategy;
import org.fresa.setting.SettingRanges;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * No degenerate block in a pocket program of the G-code posts, read back from the text written:
 * no block repeated word for word after the one before it, no straight move shorter than a
 * micrometre, and every rapid down into the pocket ends just above the material of the layer it
 * enters (the stock's top at the first layer, 0.2 mm above the floor already cut from the
 * second), so that no entry feeds through air. On the thesis's eight contours and the project's
 * pocket samples, with and without islands.
 */
class PocketBlocksTest {

    static final List<String> THESIS =
            List.of("examplepart", "cavity01", "cavity02", "cavity03", "cavity04", "cavity05", "cavity06", "cavity07");
    static final List<String> SAMPLES = List.of("clover", "rooms", "rooms-islands", "slot-ccw");

    private static final Pattern WORD = Pattern.compile("([A-Z])\\s*(-?[0-9.]+)");

    /** The settings of a thesis contour (jobs.csv) or of a sample contour (a 6 mm cutter, two layers). */
    static PocketSettings settings(String name, String post) throws Exception {
        if (THESIS.contains(name)) {
            return PocketServiceTest.settings(name, post);
        }
        return new PocketSettings(
                Path.of("samples/pocket", name + ".contour"),
                6,
                0.6,
                0.15,
                0,
                -6,
                3,
                3000,
                300,
                100,
                SettingRanges.Pocket.POST.require(post),
                MillingDirection.CLIMB,
                EntryRule.Kind.AUTO,
                EntryRule.DEFAULT_ANGLE_DEG,
                false,
                Optional.empty(),
                PocketStrategy.DEFAULT);
    }

    /** What is wrong with the program's blocks, empty when nothing. */
    static List<String> degenerate(String program, double zTopMm, double depthStepMm) {
        List<String> out = new ArrayList<>();
        String prev = null;
        double[] at = null;
        int mode = -1;
        // the rapid down to an entry (its end height and line) and the lowest feed after it
        double entryZ = Double.NaN;
        int entryLine = 0;
        double deepest = Double.POSITIVE_INFINITY;
        int n = 0;
        for (String raw : program.split("\n")) {
            n++;
            String b = raw.strip().replaceFirst("^N\\d+\\s*", "");
            if (b.isEmpty() || b.startsWith("(") || b.startsWith("%") || b.startsWith(";")) {
                continue;
            }
            Matcher g = Pattern.compile("G0*([0-3])(?![0-9.])").matcher(b);
            while (g.find()) {
                mode = Integer.parseInt(g.group(1));
            }
            double[] to = at == null ? new double[3] : at.clone();
            boolean moves = false;
            Matcher w = WORD.matcher(b);
            while (w.find()) {
                int axis = "XYZ".indexOf(w.group(1));
                if (axis >= 0) {
                    to[axis] = Double.parseDouble(w.group(2));
                    moves = true;
                }
            }
            if (b.equals(prev)) {
                out.add("line " + n + " repeats the block before: " + b);
            }
            prev = b;
            if (!moves || mode < 0) {
                continue;
            }
            if (at != null && mode <= 1) {
                double d =
                        Math.sqrt(Math.pow(to[0] - at[0], 2) + Math.pow(to[1] - at[1], 2) + Math.pow(to[2] - at[2], 2));
                if (d < 1e-3) {
                    out.add(String.format(Locale.ROOT, "line %d moves %.4f mm: %s", n, d, b));
                }
            }
            if (mode == 0) {
                air(out, entryZ, entryLine, deepest, zTopMm, depthStepMm);
                entryZ = at != null && to[2] < at[2] ? to[2] : Double.NaN;
                entryLine = n;
                deepest = Double.POSITIVE_INFINITY;
            } else {
                deepest = Math.min(deepest, to[2]);
            }
            at = to;
        }
        air(out, entryZ, entryLine, deepest, zTopMm, depthStepMm);
        return out;
    }

    /** An entry from entryZ whose feeds reach down to deepest: it starts just above that layer's material. */
    private static void air(
            List<String> out, double entryZ, int line, double deepest, double zTopMm, double depthStepMm) {
        if (Double.isNaN(entryZ) || deepest == Double.POSITIVE_INFINITY) {
            return;
        }
        double material = Math.min(zTopMm, deepest + depthStepMm);
        double allowed = material + (material >= zTopMm - 1e-6 ? 1 : 0.2);
        if (entryZ > allowed + 1e-6) {
            out.add(String.format(
                    Locale.ROOT,
                    "line %d: the entry starts %.3f mm above the material at Z%.3f",
                    line,
                    entryZ - material,
                    material));
        }
    }

    @ParameterizedTest
    @ValueSource(
            strings = {
                "examplepart",
                "cavity01",
                "cavity02",
                "cavity03",
                "cavity04",
                "cavity05",
                "cavity06",
                "cavity07",
                "clover",
                "rooms",
                "rooms-islands",
                "slot-ccw"
            })
    void noRepeatedBlockNoMicroMoveNoEntryThroughAir(String name, @TempDir Path dir) throws Exception {
        for (String post : List.of("linuxcnc", "iso", "fanuc", "840d")) {
            PocketSettings s = settings(name, post);
            Path out = dir.resolve(name + "." + post + ".nc");
            TaskOutcome o = PocketService.run(s, out, ProgressMonitor.NONE);
            assertEquals(0, o.exitStatus(), o.problems().toString());
            double step = PocketService.technology(s).depthStepMm();
            List<String> bad = degenerate(Files.readString(out), s.zTopMm(), step);
            assertTrue(bad.isEmpty(), name + " " + post + ": " + bad.size() + " degenerate blocks: " + bad);
        }
    }

    @org.junit.jupiter.api.Test
    void theCheckFindsWhatItLooksFor() {
        // a repeated rapid (also a move of nothing), a 0.4 um feed, and an entry into the
        // second layer 1 mm above its material
        String program = String.join(
                "\n",
                "G0 X1 Y1 Z5",
                "G0 X1 Y1 Z5",
                "G0 X1 Y1 Z1",
                "G1 X1 Y1 Z-1 F100",
                "G1 X1.0004 Y1 Z-1",
                "G1 X5 Y1 Z-1",
                "G0 X5 Y1 Z5",
                "G0 X1 Y1 Z0",
                "G1 X1 Y1 Z-2",
                "G1 X5 Y1 Z-2",
                "G0 X5 Y1 Z5");
        List<String> bad = degenerate(program, 0, 1);
        assertEquals(4, bad.size(), bad.toString());
    }
}
