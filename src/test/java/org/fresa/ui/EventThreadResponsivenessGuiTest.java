package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;
import org.assertj.swing.core.GenericTypeMatcher;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.JFileChooserFixture;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.fresa.job.Job;
import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.job.JobTask;
import org.fresa.stepnc.RepeatedPart21;
import org.fresa.testing.CorpusCheck;
import org.fresa.testing.TestInputs;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The window stays responsive, no event-thread task over 50 ms, while each long job
 * runs. Every job is started the way a planner starts it (a button, a file chooser) and recorded
 * from that press until its result is on screen and the event thread is idle again.
 *
 * <p>Not recorded, because it is not the job's work: the window's realisation and first paint,
 * the look and feel's start-up and the first paint of the job's tab (all done in
 * {@link #openWindow} and before {@link EventThreadWatchdog#record}), and the job's setup when it
 * is only a job file opened through the model (the tab's fields filled, not a computation). An
 * event's GC pauses, the time its thread waited for a core and the time it waited for the X server
 * are not counted (see {@link EventThreadWatchdog}): on a loaded 2-core machine each alone can pass
 * 50 ms and the application does not ask for them. The report, target/edt-responsiveness.txt, gives every slow
 * event with its wall time, both of these and its CPU time, and where the event thread was.
 */
class EventThreadResponsivenessGuiTest extends WindowGuiTest {

    private static final double THRESHOLD_MS = 50;
    private static final Path REPORT = Path.of("target", "edt-responsiveness.txt");

    private EventThreadWatchdog watchdog;

    @Override
    java.awt.Dimension windowSize() {
        return new java.awt.Dimension(1400, 860);
    }

    @BeforeEach
    void watch() throws Exception {
        // a -Dtest selection also runs this in the low-memory execution (-Xmx512m), which is for
        // the *LowMemoryTest readers; the window's jobs need the default execution's heap
        Assumptions.assumeTrue(
                Runtime.getRuntime().maxMemory() > 1024L * 1024 * 1024,
                "runs in the default surefire execution's heap");
        watchdog = EventThreadWatchdog.install(THRESHOLD_MS);
    }

    @AfterEach
    void stopWatching() throws Exception {
        if (watchdog != null) {
            watchdog.close();
        }
    }

    @Test
    void aBigPart21FileIsReadThroughTheFileChooser() throws Exception {
        Path big = dir.resolve("example2-x100.stp");
        RepeatedPart21.write(Path.of("samples/stepnc/example2.stp"), big, 4L * 1024 * 1024);
        window.tabbedPane("tabs").selectTab("STEP-NC");
        settle();
        window.button("stepnc-open").click();
        JFileChooserFixture chooser = window.fileChooser(Timeout.timeout(10_000));
        // chosen and approved on the event thread, as WindowGuiTest.choose says why
        GuiActionRunner.execute(() -> {
            chooser.target().setCurrentDirectory(dir.toFile());
            chooser.target().setSelectedFile(big.toFile());
        });
        settle();
        record("STEP-NC import of a 4 MiB Part 21 file", () -> {
            GuiActionRunner.execute(() -> chooser.target().approveSelection());
            waitFor(
                    "the program is read and planned",
                    () -> window.label("stepnc-cycle-time").target().getText().startsWith("Cycle time"));
        });
    }

    @Test
    void example2IsSolvedOnTheIrb140() {
        openJob("samples/jobs/example2-irb140.xml");
        waitUntilNoTaskRuns();
        window.tabbedPane("tabs").selectTab("Position");
        window.tabbedPane("position-results").selectTab("Summary");
        settle();
        record("robot IK of example 2 on the IRB-140", () -> {
            window.button("position-compute").click();
            waitFor(
                    "the summary shows the result",
                    () -> window.textBox("position-summary").target().getText().contains("Unreachable:"));
        });
    }

    @Test
    void aPocketIsComputed() {
        window.tabbedPane("tabs").selectTab("Pocket");
        // set, not typed: the robot's key map under Xvfb turns '/' into '&'
        window.textBox("pocket-contour")
                .setText(Path.of("samples/pocket/cavity02.dad").toAbsolutePath().toString());
        settle();
        record("pocket of samples/pocket/cavity02.dad", () -> {
            window.button("pocket-compute").click();
            waitFor(
                    "the pocket is computed",
                    () -> !List.of(" ", "computing")
                            .contains(window.label("pocket-status").target().getText()));
        });
        window.label("pocket-status").requireText("done");
    }

    @Test
    @CorpusCheck
    void theBigCorpusDrawingIsReadChainedAndCut() {
        Path p = TestInputs.DXF_CORPUS.resolve("ezdxf/examples_edgeminer_3_us_main.dxf");
        Assumptions.assumeTrue(Files.exists(p), "corpus absent");
        cut(p, "reading, chaining and cutting the 10 052-LINE corpus drawing");
    }

    @Test
    @CorpusCheck
    void aWorkshopDrawingIsCut() {
        Path p = TestInputs.DXF_CORPUS.resolve("dxf2gcode/pumpenteile.dxf");
        cut(p, "cutting " + p.getFileName());
    }

    @Test
    void aSoleIsGraded() {
        openJob("samples/jobs/grade-sole40.xml");
        window.tabbedPane("tabs").selectTab("Grading");
        settle();
        record("grading the size-40 sole over 36-44", () -> {
            window.button("grading-grade").click();
            waitFor(
                    "the table is filled",
                    () -> window.table("grading-table").target().getRowCount() == 9);
        });
    }

    private void cut(Path drawing, String job) {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        GuiActionRunner.execute(() -> model.setJob(Job.empty(JobTask.CUT)
                .withCutting(new CuttingSettings(
                        drawing.toAbsolutePath(),
                        2,
                        org.fresa.cutting.CutProcess.PLASMA,
                        3,
                        1,
                        org.fresa.cutting.LeadShape.ARC,
                        0.001,
                        org.fresa.dxf.DrawingUnits.AUTO,
                        false,
                        org.fresa.post.CuttingPost.LINUXCNC))));
        window.tabbedPane("tabs").selectTab("Cutting");
        settle();
        record(job, () -> {
            window.button("cutting-cut").click();
            waitFor(
                    "the drawing is cut",
                    () -> window.textBox("cutting-totals").target().getText().contains("pierces"));
        });
    }

    /** Records the job from its start until its result is painted, then checks every event's time. */
    private void record(String job, Runnable run) {
        watchdog.record();
        run.run();
        waitUntilNoTaskRuns();
        settle();
        watchdog.pause();
        List<EventThreadWatchdog.Slow> slow = watchdog.slowEvents();
        List<EventThreadWatchdog.Slow> over =
                slow.stream().filter(s -> s.isChargedOver(THRESHOLD_MS)).toList();
        double worstNet = slow.stream()
                .mapToDouble(EventThreadWatchdog.Slow::chargedMs)
                .max()
                .orElse(watchdog.worstMs());
        String line = String.format(
                Locale.ROOT,
                "%s: worst event-thread task %.1f ms wall (%s), %.1f ms charged "
                        + "to the application; %d over %.0f ms wall, %d of them charged over it%n",
                job,
                watchdog.worstMs(),
                watchdog.worstEvent(),
                Math.min(worstNet, watchdog.worstMs()),
                slow.size(),
                THRESHOLD_MS,
                over.size());
        StringBuilder sb = new StringBuilder(line);
        sb.append("  ").append(watchdog.threadsSinceRecord()).append('\n');
        slow.forEach(s -> sb.append("  ").append(s).append('\n'));
        try {
            Files.createDirectories(REPORT.getParent());
            Files.writeString(
                    REPORT, sb, java.nio.file.StandardOpenOption.CREATE, java.nio.file.StandardOpenOption.APPEND);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        System.out.print(sb);
        assertTrue(over.isEmpty(), sb.toString());
    }

    private void openJob(String file) {
        GuiActionRunner.execute(
                () -> ((MainWindow) window.target()).openJob(Path.of(file).toAbsolutePath()));
    }

    /** Lets pending paints and layouts run (twice: a paint may post another). */
    private void settle() {
        window.robot().waitForIdle();
        Pause.pause(300);
        window.robot().waitForIdle();
    }

    private void waitFor(String what, Supplier<Boolean> test) {
        Pause.pause(
                new Condition(what) {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(test::get);
                    }
                },
                Timeout.timeout(180_000));
    }

    private void waitUntilNoTaskRuns() {
        waitFor(
                "no task is running",
                () -> window.robot()
                        .finder()
                        .findAll(new GenericTypeMatcher<>(javax.swing.JProgressBar.class, false) {
                            @Override
                            protected boolean isMatching(javax.swing.JProgressBar b) {
                                return b.isShowing();
                            }
                        })
                        .isEmpty());
    }
}
