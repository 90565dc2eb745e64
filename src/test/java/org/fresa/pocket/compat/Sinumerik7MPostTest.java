package org.fresa.pocket.compat;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fresa.pocket.DadReader;
import org.fresa.pocket.PassPlanner;
import org.fresa.pocket.PocketPlan;
import org.fresa.pocket.PocketTechnology;
import org.fresa.pocket.Recognition;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

class Sinumerik7MPostTest {

    static final Path SAMPLES = Path.of("samples/pocket");

    static PocketPlan plan(String name) throws Exception {
        for (String line : Files.readAllLines(SAMPLES.resolve("jobs.csv"))) {
            String[] f = line.split(",");
            if (f[0].equals(name + ".dad")) {
                PocketTechnology t = new PocketTechnology(
                        d(f[1]), d(f[2]), d(f[3]), d(f[4]), d(f[5]), d(f[6]), d(f[7]), d(f[8]), d(f[9]));
                var profile = DadReader.read(Files.readString(SAMPLES.resolve(f[0])), f[0]);
                return PassPlanner.plan(Recognition.of(profile), t);
            }
        }
        throw new IllegalArgumentException(name);
    }

    private static double d(String s) {
        return Double.parseDouble(s);
    }

    static List<String> lines(String text) {
        return text.lines().map(String::stripTrailing).toList();
    }

    static List<String> printed(String name) throws Exception {
        return lines(Files.readString(SAMPLES.resolve("golden-nc/" + name + ".nc")));
    }

    /**
     * Scanning errors of the digest's copy of a printed program that the sample files keep (their
     * README lists the ones already corrected there): line number, text as in the file, text the
     * thesis printed.
     *
     * <p>Cavity 02, line 15: {@code N75 X 177478 Y 163308} is an OCR 6↔8 slip for {@code Y 163306}.
     * (1) The next block {@code N80 G03 ... I 138522 J 107694} was computed by the program from the
     * rounded start point (seed §4.5), and puts the centre of arc 5 at 163306 + 107694 = 271000 µm,
     * circle 5 being (316, 271); with 163308 it would be 271.002. (2) N70→N75 is the G01 along line
     * 3 offset to t = 89.46, and the thesis's line–circle routine takes y from the line,
     * {@code y = (D - A·x) / B} (§3.3): for every x that prints as 177478 (177.477501 to
     * 177.478501 mm by {@code INT(v·1000 + .499)}) that gives 163305.78 to 163306.09 µm, which print
     * as 163306, while the printed point lies 1.97 µm off the line (our 163306.06 lies on it). Single-precision noise is far smaller: numbers near 163 mm are
     * 0.015 µm apart. (3) The same two blocks already hold one slip of the same kind, N80
     * {@code Y 112480} for 112460 (the sample README's table, seed §5.9). (4) The compat post,
     * which computes this junction in the program's own single-precision arithmetic, prints
     * {@code N75 X 177478 Y 163306}.
     */
    static final Map<String, List<String[]>> SCANNING_ERRORS = Map.of(
            "cavity02", List.<String[]>of(new String[] {"15", "N75 X 177478 Y 163308", "N75 X 177478 Y 163306"}));

    /** The program as the thesis printed it: the sample file with {@link #SCANNING_ERRORS} corrected. */
    static List<String> golden(String name) throws Exception {
        List<String> g = new java.util.ArrayList<>(printed(name));
        for (String[] fix : SCANNING_ERRORS.getOrDefault(name, List.of())) {
            int i = Integer.parseInt(fix[0]) - 1;
            assertEquals(fix[1], g.get(i), name + " line " + fix[0] + " is no longer the scanned text");
            g.set(i, fix[2]);
        }
        return g;
    }

    /**
     * The compat post computes as the thesis's program did ({@link org.fresa.pocket.compat.ThesisPasses}:
     * Microsoft single precision, coefficients written back as 7-digit text at every move, the
     * intersection routine's own formulas and tangency thresholds, exact square roots): six of the
     * eight printed programs come out character for character, the example part among them (its
     * near-tangent slot end, N90-N130, is single-precision noise that the arithmetic reproduces).
     */
    @ParameterizedTest
    @ValueSource(strings = {"examplepart", "cavity01", "cavity02", "cavity03", "cavity04", "cavity06"})
    void compatPostReproducesThePrintedProgram(String name) throws Exception {
        String nc = new Sinumerik7MPost(Sinumerik7MPost.Mode.COMPAT).write(plan(name));
        assertEquals(String.join("\n", golden(name)), String.join("\n", lines(nc)));
    }

    private static final Pattern WORD = Pattern.compile("([XYIJ]) ?(-?\\d+)");

    /**
     * What is left of cavities 05 and 07: the same blocks and words, vertices that differ where a
     * junction is decided by the last bits of the single-precision arithmetic.
     *
     * <p>Cavity 07 (N55 and its depth copy N160, X 63012 for 63011): the junction of lines 3 and 5
     * on the innermost pass lies at x = 63011.505 µm from the 7-digit coefficients 69.16655 and
     * -30.11363, so {@code INT(x·1000 + .499)} turns on the last bit of x; the printed 63011 needs
     * line 3 at 69.16654 or line 5 at -30.11364 there, one unit in the 7th digit of the text the
     * program carried from pass to pass. Those digits depend on the exact rounding of every
     * earlier move (.16 × 20 = 3.1999998, then 17 - 13.2, then +10), which the thesis's compiled
     * runtime did not do quite as this emulation of the interpreter's arithmetic does.
     *
     * <p>Cavity 05 (13 of 52 lines, up to 32 µm): the tangent junctions of the zero-radius arc 13
     * at the reflex corner between line 3 and arc 4 (N50, N55), of line 2 with arc 1 (N85, N90,
     * N135, N140, N195, N200, 6° apart) and of arcs 8, 9 and 12 (N105, N110, N120, N220, N225).
     * At a tangency the discriminant is a difference of two numbers near 10^4 whose exact value is
     * below their rounding, and the junction moves along the element by the square root of that
     * noise (20 to 30 µm for a few ulps). Running GOTA.BAS itself, with these same arithmetic rules,
     * in an emulated GW-BASIC gives the same N50 (X 60099 Y 44666) as this post, so the difference
     * is in the arithmetic of the thesis's compiled runtime, not in the port of the listing.
     */
    @ParameterizedTest
    @CsvSource(textBlock = """
            cavity05, 10 11 17 18 21 22 24 27 28 39 40 44 45, 32
            cavity07, 11 32,                                   1
            """)
    void compatPostDiffersFromThePrintedProgramOnlyAtIllConditionedJunctions(String name, String lines, long maxUm)
            throws Exception {
        List<String> nc = lines(new Sinumerik7MPost(Sinumerik7MPost.Mode.COMPAT).write(plan(name)));
        List<String> g = golden(name);
        assertEquals(g.size(), nc.size());
        List<Integer> differing = new java.util.ArrayList<>();
        long worst = 0;
        for (int i = 0; i < g.size(); i++) {
            assertEquals(
                    WORD.matcher(g.get(i)).replaceAll("$1"),
                    WORD.matcher(nc.get(i)).replaceAll("$1"),
                    "line " + (i + 1));
            Matcher a = WORD.matcher(g.get(i));
            Matcher b = WORD.matcher(nc.get(i));
            while (a.find() && b.find()) {
                worst = Math.max(worst, Math.abs(Long.parseLong(a.group(2)) - Long.parseLong(b.group(2))));
            }
            if (!g.get(i).equals(nc.get(i))) {
                differing.add(i + 1);
            }
        }
        assertEquals(
                java.util.Arrays.stream(lines.split(" ")).map(Integer::valueOf).toList(), differing);
        assertEquals(maxUm, worst);
    }

    @Test
    void compatRoundingIsTheBasicProgramsSinglePrecisionInt() {
        Sinumerik7MPost compat = new Sinumerik7MPost(Sinumerik7MPost.Mode.COMPAT);
        org.junit.jupiter.api.Assertions.assertAll(
                // above 2^17 µm single precision spaces numbers 1/64 µm apart: x.4995 + .499 rounds to x + 1
                () -> assertEquals(153101, compat.um(153.1004995)),
                () -> assertEquals(153100, compat.um(153.1004)),
                () -> assertEquals(12345, compat.um(12.3454995)),
                // INT is floor: a negative value comes out one micrometre too negative
                () -> assertEquals(-2215, compat.um(-2.2143)),
                () -> assertEquals(153100, new Sinumerik7MPost(Sinumerik7MPost.Mode.CORRECTED).um(153.1004995)));
    }

    @Test
    void correctedPostCutsEveryDepthPassAtItsOwnDepth() throws Exception {
        List<String> nc = lines(new Sinumerik7MPost(Sinumerik7MPost.Mode.CORRECTED).write(plan("cavity07")));
        long z = 0;
        boolean incremental = false;
        long deepest = 0;
        for (String l : nc) {
            assertTrue(l.matches("N\\d+ .*"), "blank after the block number: " + l);
            if (l.contains("G91")) {
                incremental = true;
            }
            if (l.contains("G90")) {
                incremental = false;
            }
            Matcher m = Pattern.compile("Z ?(-?\\d+)").matcher(l);
            if (incremental && m.find() && !l.contains("G53") && !l.contains("G43") && !l.contains("200000")) {
                z += Long.parseLong(m.group(1));
                deepest = Math.min(deepest, z);
            }
        }
        // from Z+5 above the top: first level -2.5 (Z-7500), second -5 (Z-10000 below +5)
        assertEquals(-10000, deepest);
        // each depth pass is entered on a zig-zag ramp of incremental G01 X Y Z legs, none steeper than 3 deg
        // (the 7M interpolates arcs in the plane only: no helix), no vertical feed
        assertFalse(nc.stream().anyMatch(l -> l.matches("N\\d+ G01 (G91 )?Z.*")), "a vertical feed");
        Pattern leg = Pattern.compile("X ?(-?\\d+) Y ?(-?\\d+) Z ?(-?\\d+)");
        long legs = 0;
        for (String l : nc) {
            Matcher m = leg.matcher(l);
            if (m.find() && !l.contains("G90")) {
                double run = Math.hypot(Long.parseLong(m.group(1)), Long.parseLong(m.group(2)));
                long dz = Long.parseLong(m.group(3));
                assertTrue(dz >= 0 || Math.toDegrees(Math.atan2(-dz, run)) <= 3, l);
                legs++;
            }
        }
        assertTrue(legs >= 4, "ramp legs: " + legs);
        assertFalse(nc.stream().anyMatch(l -> l.matches("N\\d{3}[A-Z].*")));
    }

    /**
     * Three passes of 5/3 mm: three steps rounded to 1667 um would end 1 um below the floor, which
     * the program check refuses; the passes lie at 1667, 3333 and 5000 um.
     */
    @Test
    void correctedPostEndsTheLastDepthPassOnTheFloorWhenTheStepIsNoWholeMicrometre() throws Exception {
        PocketTechnology t = new PocketTechnology(6, 0.6, 0.15, 0, -5, 2, 3000, 300, 150);
        var profile = DadReader.read(Files.readString(SAMPLES.resolve("examplepart.dad")), "examplepart.dad");
        List<String> nc = lines(new Sinumerik7MPost(Sinumerik7MPost.Mode.CORRECTED)
                .write(PassPlanner.plan(Recognition.of(profile), t)));
        assertEquals(3, t.depthPasses());
        // from Z+5 above the top (incremental Z): the floor at -5 is Z-10000
        assertEquals(-10000, deepestUm(nc));
    }

    private static long deepestUm(List<String> nc) {
        long z = 0;
        boolean incremental = false;
        long deepest = 0;
        for (String l : nc) {
            if (l.contains("G91")) {
                incremental = true;
            }
            if (l.contains("G90")) {
                incremental = false;
            }
            Matcher m = Pattern.compile("Z ?(-?\\d+)").matcher(l);
            if (incremental && m.find() && !l.contains("G53") && !l.contains("G43") && !l.contains("200000")) {
                z += Long.parseLong(m.group(1));
                deepest = Math.min(deepest, z);
            }
        }
        return deepest;
    }

    @Test
    void correctedPostRoundsNegativeNumbersSymmetrically() {
        Sinumerik7MPost compat = new Sinumerik7MPost(Sinumerik7MPost.Mode.COMPAT);
        Sinumerik7MPost fixed = new Sinumerik7MPost(Sinumerik7MPost.Mode.CORRECTED);
        assertEquals(-2215, compat.um(-2.2143));
        assertEquals(-2214, fixed.um(-2.2143));
        assertEquals(-2216, compat.um(-2.2147));
        assertEquals(-2215, fixed.um(-2.2147));
        assertEquals(2214, compat.um(2.2143));
        assertEquals(" 5", Sinumerik7MPost.str(5));
        assertEquals("-5", Sinumerik7MPost.str(-5));
    }
}
