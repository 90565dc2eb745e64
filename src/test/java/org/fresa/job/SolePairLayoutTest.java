package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fresa.grading.GradedSize;
import org.fresa.io.Json;
import org.fresa.io.OutputFolder;
import org.fresa.model.CamInputException;
import org.fresa.model.Toolpath;
import org.fresa.sole.Foot;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The pair laid out in the mould block by equations 6.1-6.9 in the programs the sample sole job
 * writes: the sample carries the thesis's cavity block (D 20, DLM 225, E 0, S 11, CM 350, CP 270,
 * DPI 29, XTANP 60), so its right sole's part zero must be the thesis's table (App. F, seed 004
 * section 6.3, columns "XZ cavities", "YZ cavities") and the left one its mirror about x = 225.
 */
class SolePairLayoutTest {

    private static final Path SAMPLE = Path.of("samples/jobs/sole-men40.xml");
    private static final Pattern WORD = Pattern.compile("([XYZIJKF])(-?\\d+(?:\\.\\d+)?)");

    @TempDir
    static Path dir;
    /** The sample job run once: its programs in {@link #dir}. */
    static TaskOutcome run;

    @BeforeAll
    static void runTheSample() throws Exception {
        run = JobRunner.run(JobXml.read(SAMPLE), new OutputFolder(dir), ProgressMonitor.NONE);
    }

    /**
     * Size 40 is the size the thesis machined: its factors are exactly 1 + CTM = 1.02, and the
     * programs stand at the thesis's XZ(40) = 296.200, YZ(40) = 77.880. For the other sizes the
     * grading module's ALFA and BETA divide VL and VC by the outline's measured width and length
     * (269.23 mm) where the thesis divides by its rounded LP 90 and CP 270 (its table: XZ(38) =
     * 293.987, YZ(38) = 83.109; XZ(42) = 298.413, YZ(42) = 72.651), so the expected part zero is
     * the equations with the job's own factors, stated here:
     * xz = DLM + E + D/2 + XTANP (ALFA + CTM) = 235 + 60 w, yz = S + DPI (BETA + CTM) + (CM - CP (BETA + CTM)) / 2
     * = 11 + 29 l + (350 - 270 l) / 2, with w and l the size's width and length factors.
     */
    @ParameterizedTest
    @CsvSource({"38, 293.987, 83.109", "40, 296.200, 77.880", "42, 298.413, 72.651"})
    void eachFootsProgramsStandWhereTheEquationsPutItsPartZero(String size, double thesisXz, double thesisYz)
            throws Exception {
        Job job = JobXml.read(SAMPLE);
        assertEquals(0, run.exitStatus(), run.problems().toString());
        SoleService.SolePlan p = SoleService.plan(job.sole().orElseThrow(), job.name());
        GradedSize g = p.grader().grade(Double.parseDouble(size));
        double w = g.factors().width();
        double l = g.factors().length();
        double xzRight = 235 + 60 * w; // (6.2), (6.8)
        double yz = 11 + 29 * l + (350 - 270 * l) / 2; // (6.6), (6.7), (6.9)
        // within 0.1 mm of the thesis's table, which grades by the rounded LP 90, CP 270
        assertEquals(thesisXz, xzRight, size.equals("40") ? 5e-4 : 0.1, "XZ");
        assertEquals(thesisYz, yz, size.equals("40") ? 5e-4 : 0.1, "YZ");
        double xzLeft = 2 * 225 - xzRight; // (6.1): DLM + E - D/2 - XTANP(ND)
        for (Foot foot : Foot.values()) {
            double xz = foot == Foot.RIGHT ? xzRight : xzLeft;
            String tread = Files.readString(dir.resolve("tread-" + size + "-" + foot.id() + ".ngc"));
            assertShifted(write(p, SoleService.treadProgram(p, g, foot)), tread, xz, yz, foot + " tread " + size);
            String cavity = Files.readString(dir.resolve("cavity-" + size + "-" + foot.id() + ".ngc"));
            assertShifted(
                    write(p, SoleService.cavityProgram(p, g, foot).orElseThrow()),
                    cavity,
                    xz,
                    yz,
                    foot + " cavity " + size);
            assertTrue(
                    tread.contains(String.format(Locale.ROOT, "(%s foot, part zero X%.3f Y%.3f: ", foot.id(), xz, yz)),
                    "the program names its part zero");
        }
    }

    @Test
    void theSummaryGivesTheBlockAndBothPartZeros() {
        String json = Json.write(run.summary());
        assertTrue(json.contains("\"mirror_line_x_mm\": 225") || json.contains("\"mirror_line_x_mm\":225"), json);
        assertTrue(json.replace(" ", "").contains("\"right_part_zero_mm\":[296.2,77.88"), json);
        assertTrue(json.replace(" ", "").contains("\"left_part_zero_mm\":[153.8,77.88"), json);
    }

    @Test
    void aBlockShorterThanAGradedPatternIsRefusedWithTheSizeAndLength(@TempDir Path tmp) throws Exception {
        Path job = tmp.resolve("short.xml");
        Files.writeString(
                job,
                Files.readString(SAMPLE)
                        .replace("cmMm=\"350\"", "cmMm=\"280\"")
                        .replace(
                                "outline=\"../sole/men40.contour\"",
                                "outline=\""
                                        + Path.of("samples/sole/men40.contour").toAbsolutePath() + "\""));
        Job j = JobXml.read(job);
        CamInputException e = assertThrows(
                CamInputException.class, () -> SoleService.plan(j.sole().orElseThrow(), j.name()));
        // CP(41) = 270 (BETA(41) + 0.02) = 282.08 mm (282.06 with the thesis's BETA): 38-40 fit, 41 does not
        assertTrue(
                e.getMessage().contains("size 41")
                        && e.getMessage().contains("282.0")
                        && e.getMessage().contains("280.000"),
                e.getMessage());
        Path out = tmp.resolve("out");
        assertThrows(CamInputException.class, () -> JobRunner.run(j, new OutputFolder(out), ProgressMonitor.NONE));
        assertFalse(Files.exists(out.resolve("tread-38-right.ngc")), "nothing written");
    }

    @Test
    void withoutABlockEachFootStaysInTheOutlinesFrame() throws Exception {
        Job job = JobXml.read(SAMPLE);
        JobSettings.SoleSettings s = job.sole().orElseThrow().withBlock(java.util.Optional.empty());
        SoleService.SolePlan p = SoleService.plan(s, job.name());
        GradedSize g = p.grader().grade(40);
        Toolpath tp = SoleService.treadProgram(p, g, Foot.RIGHT);
        assertEquals(tp, SoleService.placed(p, g, Foot.RIGHT, tp));
        assertTrue(SoleService.partZero(p, g, Foot.LEFT).isEmpty());
    }

    private static String write(SoleService.SolePlan p, Toolpath tp) throws Exception {
        StringWriter w = new StringWriter();
        p.post().write(tp, "part", w);
        return w.toString();
    }

    /**
     * Block by block, the written program is the part-frame program with X and Y shifted by the
     * part zero (within the 0.001 mm of the written decimals, twice rounded) and every other word
     * (Z, arc centre offsets I J, feeds) the same.
     */
    private static void assertShifted(String partFrame, String written, double dx, double dy, String what) {
        List<String> a = motions(partFrame);
        List<String> b = motions(written);
        assertEquals(a.size(), b.size(), what + ": motion blocks");
        assertTrue(a.size() > 10, what);
        int shifted = 0;
        for (int i = 0; i < a.size(); i++) {
            Matcher ma = WORD.matcher(a.get(i));
            Matcher mb = WORD.matcher(b.get(i));
            while (ma.find()) {
                assertTrue(mb.find(), what + ": " + b.get(i));
                assertEquals(ma.group(1), mb.group(1), what + ": " + a.get(i) + " / " + b.get(i));
                double va = Double.parseDouble(ma.group(2));
                double vb = Double.parseDouble(mb.group(2));
                double expect = va + (ma.group(1).equals("X") ? dx : ma.group(1).equals("Y") ? dy : 0);
                assertEquals(expect, vb, 1.01e-3, what + ": " + a.get(i) + " -> " + b.get(i));
                shifted += ma.group(1).equals("X") ? 1 : 0;
            }
        }
        assertTrue(shifted > 10, what);
    }

    private static List<String> motions(String program) {
        List<String> out = new ArrayList<>();
        for (String line : program.split("\n")) {
            if (line.matches("^(N\\d+ )?G[0-3] .*")) {
                out.add(line);
            }
        }
        return out;
    }
}
