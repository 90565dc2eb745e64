package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.fresa.geom.Transform3;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.model.CamInputException;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.PocketStrategy;
import org.fresa.post.NcPostsTest;
import org.fresa.post.Rs274;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code --strategy adaptive} through the pocket service: each post (every G-code post and APT,
 * two pockets each, the thesis's own technology for its contours) writes the program the program
 * check passes, LinuxCNC's interpreter reads the G-code ones and the entries keep the entry angle;
 * the 7M posts refuse it plainly.
 */
class AdaptiveServiceTest {

    private static PocketSettings adaptive(String file, String post) throws Exception {
        PocketSettings s = ZigzagServiceTest.settings(file, post, 0.4);
        return s.withStrategy(new PocketStrategy(PocketStrategy.Kind.ADAPTIVE, 0));
    }

    @ParameterizedTest
    @CsvSource({
        "examplepart.dad, linuxcnc",
        "cavity01.dad, iso",
        "cavity02.dad, fanuc",
        "cavity04.dad, 840d",
        "cavity06.dad, apt",
        "cavity07.dad, linuxcnc",
        "rooms-islands.contour, iso",
        "clover.contour, fanuc",
        "rooms.contour, 840d",
        "cavity03.dad, apt"
    })
    @InterpreterCheck
    void eachPostWritesTheAdaptivePocketAndLinuxCncReadsTheGcode(String file, String post, @TempDir Path dir)
            throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        PocketSettings s = adaptive(file, post);
        Path out = dir.resolve(post + ".nc");
        TaskOutcome o = PocketService.run(s, out, ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), file + " " + post + ": " + o.problems());
        assertEquals("adaptive", o.summary().get("strategy"));
        assertTrue(o.summary().containsKey("slowed_cuts"), o.summary().toString());
        if (post.equals("apt")) {
            return;
        }
        String text = Files.readString(out);
        Path ngc = dir.resolve(post + ".ngc");
        Files.writeString(ngc, post.equals("840d") ? NcPostsTest.siemensAsNgc(text) : text);
        Rs274.Result r = Rs274.run(ngc, s.toolDiameterMm());
        assertEquals(0, r.exitStatus(), file + " " + post + ": " + Rs274.log(r));
        double steepest = EntryAngleTest.steepestDeg(
                r.motions(), Transform3.IDENTITY, p -> true, s.zTopMm(), s.toolDiameterMm() / 2);
        System.out.printf(
                Locale.ROOT, "[adaptive] %s %s: steepest descent %.2f deg, %s%n", file, post, steepest, o.problems());
        assertTrue(steepest <= EntryRule.DEFAULT_ANGLE_DEG + EntryAngleTest.TOLERANCE_DEG, file + ": " + steepest);
    }

    @ParameterizedTest
    @ValueSource(strings = {"7m", "7m-compat"})
    void theSevenMPostsRefuseAdaptivePlainly(String post, @TempDir Path dir) throws Exception {
        CamInputException e = assertThrows(
                CamInputException.class,
                () -> PocketService.run(adaptive("cavity05.dad", post), dir.resolve("a.nc"), ProgressMonitor.NONE));
        assertTrue(e.getMessage().contains("adaptive needs one of linuxcnc"), e.getMessage());
        assertFalse(Files.exists(dir.resolve("a.nc")));
    }

    @org.junit.jupiter.api.Test
    void theWalksTellHowFarTheyAreAndStopWhenCancelled() throws Exception {
        PocketSettings s = adaptive("cavity05.dad", "linuxcnc");
        java.util.List<Double> told = new java.util.ArrayList<>();
        PocketService.strategyPlan(s, new ProgressMonitor() {
            @Override
            public void progress(double fraction, String what) {
                assertTrue(what.startsWith("adaptive walks: "), what);
                told.add(fraction);
            }

            @Override
            public boolean isCancelled() {
                return false;
            }
        });
        assertFalse(told.isEmpty());
        for (int i = 0; i < told.size(); i++) {
            assertTrue(told.get(i) >= 0 && told.get(i) <= 1, told.toString());
            assertTrue(i == 0 || told.get(i) >= told.get(i - 1), told.toString());
        }
        // the user's Cancel: the walks stop at the next word of progress
        assertThrows(
                java.util.concurrent.CancellationException.class,
                () -> PocketService.strategyPlan(s, new ProgressMonitor() {
                    @Override
                    public void progress(double fraction, String what) {}

                    @Override
                    public boolean isCancelled() {
                        return true;
                    }
                }));
    }
}
