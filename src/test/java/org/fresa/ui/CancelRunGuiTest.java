package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.stream.Stream;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.DialogFixture;
import org.assertj.swing.fixture.JFileChooserFixture;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.fresa.io.AtomicFiles;
import org.fresa.job.Job;
import org.fresa.job.JobSettings.GradingSettings;
import org.fresa.job.JobTask;
import org.fresa.robustness.CompleteOutputs;
import org.junit.jupiter.api.Test;

/**
 * Job > Run (F5) on a long grading job, then Cancel (Esc) while it writes: the run
 * stops, every file under a final name is complete, no temporary file is left, and the window
 * runs the next job as usual.
 */
class CancelRunGuiTest extends WindowGuiTest {

    static Job grading(String sizes, boolean half) {
        return Job.empty(JobTask.GRADE)
                .withGrading(new GradingSettings(
                        Path.of("samples/grading/sole-40.contour").toAbsolutePath(),
                        40,
                        sizes,
                        half,
                        org.fresa.grading.SizeSystem.BR,
                        OptionalDouble.empty(),
                        OptionalDouble.empty(),
                        Optional.empty(),
                        0,
                        org.fresa.grading.ShrinkageMode.MULTIPLICATIVE));
    }

    /** Presses a key in the window, clicking it first: without a window manager a closed chooser leaves no focus. */
    void pressInWindow(int key) {
        window.label("status").click();
        window.label("status").pressAndReleaseKeys(key);
    }

    void runInto(Path out) throws InterruptedException {
        String before = status();
        // the chooser's approve can land before the chooser has taken the selected file (seen
        // once in a full suite: the run never started); then the window is as before: ask again
        // or the approve did not land at all and the chooser is still open: then it is approved again
        for (int attempt = 0; attempt < 3; attempt++) {
            JFileChooserFixture fc = attempt == 0 ? null : openChooser();
            if (fc == null) {
                pressInWindow(KeyEvent.VK_F5);
                fc = window.fileChooser(Timeout.timeout(10_000));
            }
            // the folder chosen on the event thread: the robot's select and approve in the chooser
            // sometimes did not take (a run that never started, in 1 of about 4 loaded runs), and this
            // test is about the cancel, not the chooser, which other tests drive by the robot
            JFileChooserFixture chooser = fc;
            GuiActionRunner.execute(() -> {
                chooser.target().setSelectedFile(out.toFile());
                chooser.target().approveSelection();
            });
            long until = System.currentTimeMillis() + 10_000;
            while (status().equals(before) && System.currentTimeMillis() < until) {
                Thread.sleep(20);
            }
            if (!status().equals(before)) {
                return;
            }
        }
    }

    /** The chooser of an earlier attempt when it is still open, else null. */
    JFileChooserFixture openChooser() {
        try {
            return window.fileChooser(Timeout.timeout(1_000));
        } catch (org.assertj.swing.exception.WaitTimedOutError e) {
            return null;
        }
    }

    String status() {
        return window.label("status").text();
    }

    static List<String> names(Path d) throws Exception {
        try (Stream<Path> s = Files.list(d)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void cancellingARunLeavesOnlyCompleteFilesAndTheWindowUsable() throws Exception {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        GuiActionRunner.execute(() -> model.setJob(grading("17-50", true)));
        Path out = Files.createDirectories(dir.resolve("long"));
        runInto(out);
        // wait until the run has written something, then cancel while it goes on
        long until = System.currentTimeMillis() + 60_000;
        while (names(out).size() < 2 && System.currentTimeMillis() < until) {
            Thread.sleep(20);
        }
        assertTrue(names(out).size() >= 2, "the run writes: " + names(out) + ", status " + status());
        try {
            var pane = window.optionPane(Timeout.timeout(100));
            throw new AssertionError("no dialog while running, found: "
                    + GuiActionRunner.execute(() -> String.valueOf(pane.target().getMessage())) + "; files "
                    + names(out));
        } catch (org.assertj.swing.exception.WaitTimedOutError expected) {
            // running: no dialog yet
        }
        pressInWindow(KeyEvent.VK_ESCAPE);
        Pause.pause(
                new org.assertj.swing.timing.Condition("the run reports it is cancelled") {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(() -> status()).endsWith("cancelled");
                    }
                },
                Timeout.timeout(20_000));
        // the worker stops at its next check: wait until the folder stops changing
        List<String> before;
        List<String> after = names(out);
        do {
            before = after;
            Thread.sleep(1500);
            after = names(out);
        } while (!after.equals(before));
        List<String> files = after;
        assertAll(
                () -> assertFalse(files.contains("grading.csv"), "cancelled before the end: " + files),
                () -> assertTrue(
                        files.stream().noneMatch(f -> f.startsWith(AtomicFiles.TEMP_PREFIX)),
                        "no temporary file: " + files),
                () -> assertEquals(List.of(), CompleteOutputs.incomplete(out), "every final-named file is complete"));

        try {
            var pane = window.optionPane(Timeout.timeout(1000));
            throw new AssertionError("no dialog after Cancel, found: "
                    + GuiActionRunner.execute(() -> String.valueOf(pane.target().getMessage())));
        } catch (org.assertj.swing.exception.WaitTimedOutError expected) {
            // no dialog: the cancelled run said so in the status bar only
        }
        // the window still works: another run goes through to its end
        GuiActionRunner.execute(() -> model.setJob(grading("40-41", false)));
        Path next = Files.createDirectories(dir.resolve("next"));
        runInto(next);
        DialogFixture done = window.dialog(Timeout.timeout(60_000));
        done.close();
        assertAll(
                () -> assertTrue(status().endsWith("done"), status()),
                () -> assertTrue(
                        names(next).containsAll(List.of("grading.csv", "grading.png", "size-40.dxf", "size-41.dxf")),
                        names(next).toString()),
                () -> assertEquals(List.of(), CompleteOutputs.incomplete(next)));
    }
}
