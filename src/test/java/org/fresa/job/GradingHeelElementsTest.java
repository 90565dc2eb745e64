package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.grading.GradedSize;
import org.fresa.grading.GradingResult;
import org.fresa.model.CamInputException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Heel coordination by the elements the planner designates (figure 4.4), saved in the job: the
 * sample sole (five elements, the first its heel arc) with that arc, element 1, as the
 * heel and one heel per three sizes.
 */
class GradingHeelElementsTest {

    private static Path job(Path dir, String attributes) throws Exception {
        String xml = Files.readString(Path.of("samples/jobs/grade-sole40.xml"))
                .replace(
                        "outline=\"../grading/sole-40.contour\"",
                        "outline=\""
                                + Path.of("samples/grading/sole-40.contour").toAbsolutePath() + "\" " + attributes);
        Path p = dir.resolve("grade.xml");
        Files.writeString(p, xml);
        return p;
    }

    @Test
    void sizesOfOneGroupShareTheDesignatedHeelAndTheJobKeepsIt(@TempDir Path dir) throws Exception {
        Job j = JobXml.read(job(dir, "heelElements=\"1\" heelGroup=\"3\""));
        JobSettings.GradingSettings s = j.grading().orElseThrow();
        assertEquals("1", s.coordination().orElseThrow().heelElements());
        GradingResult r = GradingService.grade(
                GradingService.readOutline(s.outline()), "sole-40", s, GradingService.Options.DEFAULT);
        // base 40, groups of 3: 42, 43 and 44 take the heel of 43
        GradedSize g42 = size(r, 42);
        GradedSize g43 = size(r, 43);
        GradedSize g44 = size(r, 44);
        assertEquals(43, g42.heelSize().getAsDouble(), 0);
        assertEquals(43, g44.heelSize().getAsDouble(), 0);
        Curve2 heel42 = g42.output().get(0).get(0);
        Curve2 heel44 = g44.output().get(0).get(0);
        for (double t : new double[] {0, 0.5, 1}) {
            assertEquals(0, heel42.pointAt(t).distance(heel44.pointAt(t)), 1e-9, "the same heel arc");
            assertEquals(
                    0, heel42.pointAt(t).distance(g43.output().get(0).get(0).pointAt(t)), 1e-9);
        }
        // the toe grows with every size
        assertNotEquals(0, toe(g42).pointAt(0.5).distance(toe(g44).pointAt(0.5)), 1e-3);
        // saved in the job as it was read
        Path copy = dir.resolve("copy.xml");
        JobXml.write(j, copy);
        assertTrue(Files.readString(copy).contains("heelElements=\"1\""));
        assertEquals(s.coordination(), JobXml.read(copy).grading().orElseThrow().coordination());
    }

    @Test
    void elementsTheOutlineLacksOrBothKindsOfHeelAreRefused(@TempDir Path dir) throws Exception {
        JobSettings.GradingSettings s =
                JobXml.read(job(dir, "heelElements=\"1,9\"")).grading().orElseThrow();
        List<Contour> outline = GradingService.readOutline(s.outline());
        CamInputException e = assertThrows(
                CamInputException.class,
                () -> GradingService.grade(outline, "sole-40", s, GradingService.Options.DEFAULT));
        assertTrue(
                e.getMessage().contains("heel element 9 does not exist: the outline has 5 elements"), e.getMessage());
        JobSettings.GradingSettings both = JobXml.read(job(dir, "heelElements=\"1\" coordinationMm=\"60\""))
                .grading()
                .orElseThrow();
        e = assertThrows(
                CamInputException.class,
                () -> GradingService.grade(outline, "sole-40", both, GradingService.Options.DEFAULT));
        assertTrue(e.getMessage().contains("not both"), e.getMessage());
        JobSettings.GradingSettings bad =
                JobXml.read(job(dir, "heelElements=\"1-x\"")).grading().orElseThrow();
        e = assertThrows(
                CamInputException.class,
                () -> GradingService.grade(outline, "sole-40", bad, GradingService.Options.DEFAULT));
        assertTrue(e.getMessage().contains("'1-x'"), e.getMessage());
    }

    private static GradedSize size(GradingResult r, double n) {
        return r.sizes().stream()
                .filter(g -> g.factors().size() == n)
                .findFirst()
                .orElseThrow();
    }

    private static Curve2 toe(GradedSize g) {
        return g.output().get(0).get(2);
    }
}
