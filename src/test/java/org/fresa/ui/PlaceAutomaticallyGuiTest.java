package org.fresa.ui;

import java.nio.file.Path;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.fresa.job.JobSettings;
import org.fresa.model.Placement;
import org.junit.jupiter.api.Test;

/** The Position tab's "Place automatically" under a (virtual) display; a headless run skips it. */
class PlaceAutomaticallyGuiTest extends WindowGuiTest {

    @Test
    void thePlacementFoundFillsTheFieldsAndTheTriceptReachesEveryPoint() {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        Path stp = Path.of("samples/stepnc/iso14649-11-example1.stp").toAbsolutePath();
        GuiActionRunner.execute(() -> model.setJob(
                model.job().withStepnc(new JobSettings.StepNcSettings(stp, org.fresa.post.MillingPost.LINUXCNC))));
        waitUntilNoTaskRuns();
        window.tabbedPane("tabs").selectTab("Robot");
        window.comboBox("robot-choice").selectItem("tricept806");

        window.tabbedPane("tabs").selectTab("Position");
        // at the origin the part is in the Tricept's base: the search moves the table far below it
        window.button("position-place-auto").click();
        Pause.pause(
                new Condition("the job's placement is the one found") {
                    @Override
                    public boolean test() {
                        Placement p = GuiActionRunner.execute(
                                () -> model.job().robot().orElseThrow().robotTable());
                        return p.zMm() < -1000;
                    }
                },
                Timeout.timeout(180_000));
        waitUntilNoTaskRuns();
        Placement p =
                GuiActionRunner.execute(() -> model.job().robot().orElseThrow().robotTable());
        window.textBox("position-rt-Z").requireText(RobotViewModel.num(p.zMm()));
        window.textBox("position-rt-RZ").requireText(RobotViewModel.num(p.rzDeg()));
        window.tabbedPane("position-results").selectTab("Summary");
        // the summary first says which placement was found; the live reachability of the new
        // placement then takes its place, and must find every target reached
        Pause.pause(
                new Condition("the summary says the placement found reaches every target") {
                    @Override
                    public boolean test() {
                        String said = GuiActionRunner.execute(() ->
                                window.textBox("position-summary").target().getText());
                        return said.startsWith("placement found: --robot-table ") || said.contains("Out of reach: 0");
                    }
                },
                Timeout.timeout(60_000));

        window.button("position-compute").click();
        Pause.pause(
                new Condition("every point is reached from the placement found") {
                    @Override
                    public boolean test() {
                        String s = GuiActionRunner.execute(() ->
                                window.textBox("position-summary").target().getText());
                        return s.contains("Unreachable: 0");
                    }
                },
                Timeout.timeout(120_000));
        shoot("position-place-auto.png");
    }

    /** For looking at after the build: target/screenshots/position-place-auto.png. */
    private void shoot(String name) {
        java.awt.image.BufferedImage img =
                GuiActionRunner.execute(() -> TabScreenshotsTest.paint((javax.swing.JFrame) window.target()));
        try {
            java.nio.file.Files.createDirectories(Path.of("target", "screenshots"));
            javax.imageio.ImageIO.write(
                    img, "png", Path.of("target", "screenshots", name).toFile());
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private void waitUntilNoTaskRuns() {
        Pause.pause(
                new Condition("no task is running") {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(() -> window.robot()
                                .finder()
                                .findAll(
                                        new org.assertj.swing.core.GenericTypeMatcher<>(
                                                javax.swing.JProgressBar.class, false) {
                                            @Override
                                            protected boolean isMatching(javax.swing.JProgressBar b) {
                                                return b.isShowing();
                                            }
                                        })
                                .isEmpty());
                    }
                },
                Timeout.timeout(60_000));
    }
}
