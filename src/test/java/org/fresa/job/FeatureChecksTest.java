package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fresa.geom.Tolerance;
import org.fresa.io.OutputFolder;
import org.fresa.stepnc.StepNcReader;
import org.fresa.testing.CorpusCheck;
import org.fresa.testing.TestInputs;
import org.fresa.toolpath.ToolpathPlanner;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What a file says of a feature that cannot be what its writer meant is told: a feature above
 * its block, a security plane below a feature's top, a blind hole its workingsteps leave short;
 * and a security plane inside the stock gives no program (the program check's rapid rule).
 */
class FeatureChecksTest {

    static final Path EXAMPLE2 = Path.of("samples/stepnc/example2.stp");
    static final Path FURO_CONICO = TestInputs.SHARED_CORPUS.resolve("stepnc/grima/FuroConico.p21");

    private static List<String> warnings(Path file) throws Exception {
        return ToolpathPlanner.plan(StepNcReader.read(file), Tolerance.DEFAULT).problems();
    }

    private static long count(List<String> problems, String words) {
        return problems.stream().filter(p -> p.contains(words)).count();
    }

    @Test
    void example2SaysNothingOfTheKind() throws Exception {
        List<String> p = warnings(EXAMPLE2);
        assertEquals(0, count(p, "lies wholly above"), p.toString());
        assertEquals(0, count(p, "security plane ("), p.toString());
        assertEquals(0, count(p, "mm short"), p.toString());
    }

    @Test
    void aSecurityPlaneInsideTheBlockIsToldAndItsProgramRefusedAtTheFirstRapid(@TempDir Path dir) throws Exception {
        String text = Files.readString(EXAMPLE2).replace("(0.0,0.0,225.0)", "(0.0,0.0,190.0)");
        Path input = dir.resolve("low-plane.stp");
        Files.writeString(input, text);
        List<String> p = warnings(input);
        // the 5 features on the block's top face (Z 200), each told once
        assertEquals(
                5, count(p, ") is 10 mm above its workingsteps' security plane (through (0, 0, 190)"), p.toString());
        TaskOutcome o = ToolpathService.run(
                input, org.fresa.post.MillingPost.LINUXCNC, new OutputFolder(dir.resolve("out")), ProgressMonitor.NONE);
        assertEquals(1, o.exitStatus(), o.problems().toString());
        assertEquals(
                1,
                o.problems().stream()
                        .filter(x -> x.startsWith("program.ngc not written")
                                && x.contains("rapid: rapid traverse into the material"))
                        .count(),
                o.problems().toString());
        assertTrue(Files.notExists(dir.resolve("out/program.ngc")));
    }

    @Test
    void featuresAboveTheBlockAreTold(@TempDir Path dir) throws Exception {
        // the block lowered by 100 mm: its top at Z 100, the features on the old top at Z 200
        String text = Files.readString(EXAMPLE2)
                .replace("#4=CARTESIAN_POINT('',(0.0,0.0,0.0));", "#4=CARTESIAN_POINT('',(0.0,0.0,-100.0));");
        Path input = dir.resolve("low-block.stp");
        Files.writeString(input, text);
        List<String> p = warnings(input);
        assertTrue(count(p, "lies wholly above the workpiece's block") >= 1, p.toString());
        assertTrue(
                p.stream()
                        .anyMatch(x ->
                                x.contains("feature 'Plane Base Hole' (#35) lies wholly above the workpiece's block:"
                                        + " its bottom is at Z 190 mm, the block's top at Z 100 mm")),
                p.toString());
    }

    @Test
    @CorpusCheck
    void grimasConicalHoleIsToldAllThree() throws Exception {
        assumeTrue(Files.isRegularFile(FURO_CONICO), TestInputs.sharedCorpusAbsent(FURO_CONICO.getParent()));
        List<String> p = warnings(FURO_CONICO);
        assertEquals(
                1,
                count(
                        p,
                        "feature 'Furo Base Conica' (#39) lies wholly above the workpiece's block: its bottom is at Z 80 mm,"
                                + " the block's top at Z 50 mm"),
                p.toString());
        assertEquals(
                1,
                count(
                        p,
                        "the top of feature 'Furo Base Conica' (#39) is 25 mm above its workingsteps' security plane (through (0, 0, 75)"),
                p.toString());
        assertEquals(
                1,
                count(
                        p,
                        "hole 'Furo Base Conica' (#39) is 20 mm deep, and its workingsteps' cutting_depth reaches 9 mm at most:"
                                + " the hole is left 11 mm short"),
                p.toString());
    }
}
