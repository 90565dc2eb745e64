package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.geom.Contour;
import org.fresa.geom.Vec2;
import org.fresa.io.OutputFolder;
import org.fresa.job.JobSettings.GradingSettings;
import org.fresa.model.CamInputException;
import org.fresa.setting.SettingRanges;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class GradingServiceTest {

    @TempDir
    Path dir;

    @Test
    void theSampleJobWritesEverySizeTheTableAndThePlot() throws Exception {
        Job job = JobXml.read(Path.of("samples/jobs/grade-sole40.xml"));
        TaskOutcome o = JobRunner.run(job, new OutputFolder(dir), ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        for (int n = 36; n <= 44; n++) {
            assertTrue(Files.size(dir.resolve("size-" + n + ".dxf")) > 500);
            assertTrue(Files.size(dir.resolve("size-" + n + ".csv")) > 100);
        }
        List<String> table = Files.readAllLines(dir.resolve("grading.csv"));
        assertEquals(
                "size,length_mm,width_mm,alfa,beta,length_factor,width_factor,heel_size,max_deviation_mm",
                table.get(0));
        assertEquals(10, table.size());
        for (int i = 1; i < table.size(); i++) {
            String[] f = table.get(i).split(",", -1);
            double n = Double.parseDouble(f[0]) - 40;
            assertAll(
                    () -> assertEquals(270 + n * 6.66, Double.parseDouble(f[1]), 1e-9),
                    () -> assertEquals(90 + n * 1.66, Double.parseDouble(f[2]), 1e-9),
                    () -> assertTrue(Double.parseDouble(f[8]) <= 0.005));
        }
        byte[] png = Files.readAllBytes(dir.resolve("grading.png"));
        assertEquals((byte) 0x89, png[0]);
        assertEquals(20, o.files().size());
    }

    @Test
    void csvPointsLieOnTheExactGradedOutline() throws Exception {
        GradingSettings s = settings("42-42", false);
        GradingService.run(s, new OutputFolder(dir), ProgressMonitor.NONE);
        List<String> lines = Files.readAllLines(dir.resolve("size-42.csv"));
        assertEquals("x,y", lines.get(0));
        Contour base = GradingService.readOutline(s.outline()).get(0);
        double bx = 1 + 2 * 1.66 / 90;
        double by = 1 + 2 * 6.66 / 270;
        for (String l : lines.subList(1, lines.size())) {
            String[] f = l.split(",");
            // the origin is the heel centre (0, 0) and the axes are the drawing's
            Vec2 back = new Vec2(Double.parseDouble(f[0]) / bx, Double.parseDouble(f[1]) / by);
            assertEquals(0, base.distanceTo(back), 1e-9, l);
        }
    }

    @Test
    void halfSizesAreNamedWithTheirFraction() throws Exception {
        GradingService.run(settings("40-41", true), new OutputFolder(dir), ProgressMonitor.NONE);
        assertTrue(Files.exists(dir.resolve("size-40.5.dxf")));
        assertTrue(Files.exists(dir.resolve("size-40.5.csv")));
    }

    @Test
    void anUnknownSystemIsBadInput() {
        CamInputException e = assertThrows(CamInputException.class, () -> SettingRanges.Grading.SYSTEM.check("zz"));
        assertTrue(
                e.getMessage().contains("--system") && e.getMessage().contains("br, paris, uk, us, mondopoint"),
                e.getMessage());
    }

    private static GradingSettings settings(String sizes, boolean half) {
        return new GradingSettings(
                Path.of("samples/grading/sole-40.contour").toAbsolutePath(),
                40,
                sizes,
                half,
                org.fresa.grading.SizeSystem.BR,
                OptionalDouble.empty(),
                OptionalDouble.empty(),
                Optional.empty(),
                0,
                org.fresa.grading.ShrinkageMode.MULTIPLICATIVE);
    }
}
