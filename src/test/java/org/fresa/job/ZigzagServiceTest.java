package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.fresa.geom.Transform3;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.model.CamInputException;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.MillingDirection;
import org.fresa.pocket.PocketStrategy;
import org.fresa.post.NcPostsTest;
import org.fresa.post.Rs274;
import org.fresa.setting.SettingRanges;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code --strategy zigzag} through the pocket service: every G-code post and APT write the
 * program the program check passes, LinuxCNC's interpreter reads the G-code ones, the entries keep
 * the entry angle; the 7M posts refuse it plainly (bad input, exit 2); offset stays the default.
 */
class ZigzagServiceTest {

    private static final List<String> POSTS = List.of("linuxcnc", "iso", "fanuc", "840d", "apt");

    /**
     * A thesis contour's own technology from jobs.csv ({@code .dad}), else a 6 mm tool at this cut
     * 4 mm deep in two layers, with this post, climb, the default entry and strategy.
     */
    static PocketSettings settings(String file, String post, double cut) throws Exception {
        return file.endsWith(".dad")
                ? PocketServiceTest.settings(file.substring(0, file.length() - 4), post)
                : new PocketSettings(
                        Path.of("samples/pocket", file),
                        6,
                        cut,
                        0.1,
                        0,
                        -4,
                        2,
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

    private static PocketSettings zigzag(String file, String post, double angleDeg) throws Exception {
        PocketSettings s = settings(file, post, 0.6);
        return s.withStrategy(new PocketStrategy(PocketStrategy.Kind.ZIGZAG, angleDeg));
    }

    @ParameterizedTest
    @ValueSource(
            strings = {
                "examplepart.dad",
                "cavity01.dad",
                "cavity02.dad",
                "cavity03.dad",
                "cavity04.dad",
                "cavity05.dad",
                "cavity06.dad",
                "cavity07.dad",
                "rooms-islands.contour",
                "clover.contour"
            })
    @InterpreterCheck
    void everyPostWritesTheZigzagPocketAndLinuxCncReadsTheGcode(String file, @TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        for (String post : POSTS) {
            PocketSettings s = zigzag(file, post, 37);
            Path out = dir.resolve(post + ".nc");
            TaskOutcome o = PocketService.run(s, out, ProgressMonitor.NONE);
            assertEquals(0, o.exitStatus(), file + " " + post + ": " + o.problems());
            assertEquals("zigzag", o.summary().get("strategy"));
            if (post.equals("apt")) {
                continue;
            }
            String text = Files.readString(out);
            Path ngc = dir.resolve(post + ".ngc");
            Files.writeString(ngc, post.equals("840d") ? NcPostsTest.siemensAsNgc(text) : text);
            Rs274.Result r = Rs274.run(ngc, s.toolDiameterMm());
            assertEquals(0, r.exitStatus(), file + " " + post + ": " + Rs274.log(r));
            if (post.equals("linuxcnc")) {
                double steepest = EntryAngleTest.steepestDeg(
                        r.motions(), Transform3.IDENTITY, p -> true, s.zTopMm(), s.toolDiameterMm() / 2);
                System.out.printf(Locale.ROOT, "[zigzag] %s: steepest descent %.2f deg%n", file, steepest);
                assertTrue(
                        steepest <= EntryRule.DEFAULT_ANGLE_DEG + EntryAngleTest.TOLERANCE_DEG,
                        file + ": " + steepest + " deg");
            }
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"7m", "7m-compat"})
    void theSevenMPostsRefuseZigzagPlainly(String post, @TempDir Path dir) throws Exception {
        CamInputException e = assertThrows(
                CamInputException.class,
                () -> PocketService.run(zigzag("cavity05.dad", post, 0), dir.resolve("z.nc"), ProgressMonitor.NONE));
        assertTrue(e.getMessage().contains("zigzag needs one of linuxcnc"), e.getMessage());
        assertFalse(Files.exists(dir.resolve("z.nc")));
    }

    @Test
    void offsetIsTheDefaultAndTheSameProgram(@TempDir Path dir) throws Exception {
        assertEquals(PocketStrategy.DEFAULT, PocketSettings.DEFAULTS.strategy());
        PocketSettings s = PocketServiceTest.settings("cavity03", "linuxcnc");
        PocketService.run(s, dir.resolve("a.ngc"), ProgressMonitor.NONE);
        PocketService.run(
                s.withStrategy(new PocketStrategy(PocketStrategy.Kind.OFFSET, 45)),
                dir.resolve("b.ngc"),
                ProgressMonitor.NONE);
        assertEquals(Files.readString(dir.resolve("a.ngc")), Files.readString(dir.resolve("b.ngc")));
    }

    @Test
    void theAngleTurnsTheLines(@TempDir Path dir) throws Exception {
        PocketService.run(zigzag("cavity05.dad", "linuxcnc", 0), dir.resolve("a.ngc"), ProgressMonitor.NONE);
        PocketService.run(zigzag("cavity05.dad", "linuxcnc", 90), dir.resolve("b.ngc"), ProgressMonitor.NONE);
        assertFalse(Files.readString(dir.resolve("a.ngc")).equals(Files.readString(dir.resolve("b.ngc"))));
    }
}
