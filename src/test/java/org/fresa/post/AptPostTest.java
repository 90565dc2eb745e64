package org.fresa.post;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.fresa.check.Limits;
import org.fresa.check.NcDialect;
import org.fresa.check.ProgramCheck;
import org.fresa.check.ToolLimits;
import org.junit.jupiter.api.Test;

/** The APT / CL-data post on the mixed sample: its golden file, arcs in every plane, the program check. */
class AptPostTest {

    private static final Path GOLDEN = Path.of("src/test/resources/org/fresa/post/mixed.apt");

    private static String program() throws IOException {
        StringWriter w = new StringWriter();
        NcPosts.byName("APT").orElseThrow().write(SampleToolpaths.mixed(), "mixed sample", w);
        return w.toString();
    }

    @Test
    void theMixedSampleIsItsGoldenFile() throws IOException {
        String text = program();
        if (Boolean.getBoolean("fresa.updateGolden")) {
            Files.writeString(GOLDEN, text, StandardCharsets.UTF_8);
        }
        assertEquals(Files.readString(GOLDEN, StandardCharsets.UTF_8), text);
    }

    @Test
    void everyArcStaysOneCircleEvenInATiltedPlane() throws IOException {
        String text = program();
        List<String> lines = text.lines().toList();
        // the linuxcnc program replaces the tilted half circle by 79 chords; APT keeps it one CIRCLE
        long tilted = lines.stream()
                .filter(l -> l.startsWith("CIRCLE/"))
                .filter(l -> {
                    String[] a = l.substring(7).split(",");
                    return Math.abs(Math.abs(Double.parseDouble(a[3]))
                                    + Math.abs(Double.parseDouble(a[4]))
                                    + Math.abs(Double.parseDouble(a[5]))
                                    - 1)
                            > 1e-6;
                })
                .count();
        assertEquals(1, tilted, text);
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).startsWith("CIRCLE/")) {
                assertTrue(
                        lines.get(i + 1).startsWith("GOTO/"), "a CIRCLE is followed by its GOTO: " + lines.get(i + 1));
            }
        }
        assertTrue(text.startsWith("PARTNO mixed sample\nUNITS/MM\n"), text);
        assertTrue(text.endsWith("SPINDL/OFF\nCOOLNT/OFF\nFINI\n"), text);
        assertEquals("apt", NcPosts.byName("apt").orElseThrow().fileExtension());
        assertEquals("ngc", NcPosts.byName("linuxcnc").orElseThrow().fileExtension());
    }

    @Test
    void numbersUseAPointWhateverTheDefaultLocale() throws IOException {
        Locale saved = Locale.getDefault();
        try {
            Locale.setDefault(Locale.GERMANY);
            assertEquals(Files.readString(GOLDEN, StandardCharsets.UTF_8), program());
        } finally {
            Locale.setDefault(saved);
        }
    }

    @Test
    void theProgramCheckReadsItLikeTheGcode() throws IOException {
        Limits any = Limits.milling().withOtherTools(ToolLimits.centreCuttingPlunge());
        ProgramCheck.Verdict apt = ProgramCheck.of(program(), NcDialect.APT, any);
        assertTrue(apt.ok(), () -> apt.failure().get().message());
        // a cutter that may not plunge: the same block of the same section fails in both
        Limits ramp =
                Limits.milling().withOtherTools(ToolLimits.notCentreCutting().withRadiusMm(3));
        var a = ProgramCheck.of(program(), NcDialect.APT, ramp).failure();
        var g = ProgramCheck.of(NcPostsTest.program("linuxcnc", SampleToolpaths.mixed()), NcDialect.LINUXCNC, ramp)
                .failure();
        assertEquals(g.isPresent(), a.isPresent());
        if (a.isPresent()) {
            assertEquals(g.get().rule(), a.get().rule());
        }
    }
}
