package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.awt.GraphicsEnvironment;
import java.nio.file.Path;
import org.assertj.swing.core.GenericTypeMatcher;
import org.assertj.swing.edt.FailOnThreadViolationRepaintManager;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.FrameFixture;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.fresa.job.JobSettings;
import org.fresa.job.RecentJobs;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The Robot, Position and Output tabs under a (virtual) display; a headless run skips it. */
class RobotTabsGuiTest {

    @TempDir
    Path dir;

    FrameFixture window;

    @BeforeAll
    static void needsADisplay() {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under xvfb-run");
        FailOnThreadViolationRepaintManager.install();
    }

    @BeforeEach
    void openWindow() {
        MainWindow w = GuiActionRunner.execute(() -> FresaApp.create(new RecentJobs(dir.resolve("recent.txt"))));
        window = new FrameFixture(w);
        window.show();
    }

    @AfterEach
    void closeWindow() {
        if (window != null) {
            window.cleanUp();
        }
    }

    @Test
    void example1IsComputedOnTheIrb140AndItsProgramPreviewed() {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        Path stp = Path.of("samples/stepnc/iso14649-11-example1.stp").toAbsolutePath();
        GuiActionRunner.execute(() -> model.setJob(model.job().withStepnc(new JobSettings.StepNcSettings(stp,
                "linuxcnc"))));
        waitUntilNoTaskRuns();

        window.tabbedPane("tabs").selectTab("Robot");
        window.comboBox("robot-choice").selectItem("irb140");
        window.table("robot-dh").requireRowCount(6);

        window.tabbedPane("tabs").selectTab("Position");
        setField("position-rt-X", "400");
        setField("position-rt-Y", "-200");
        setField("position-rt-Z", "500");
        setField("position-tp-Y", "10");
        window.textBox("position-rt-Z").requireText("500");
        window.button("position-compute").click();
        Pause.pause(new Condition("the summary shows the result") {
            @Override
            public boolean test() {
                String s = GuiActionRunner.execute(() -> window.textBox("position-summary").target().getText());
                return s.contains("Unreachable: 0");
            }
        }, Timeout.timeout(120_000));
        window.slider("position-replay").slideTo(GuiActionRunner.execute(
                () -> window.slider("position-replay").target().getMaximum() / 2));
        shoot("robot-position.png");
        assertTrue(window.label("position-point").target().getText().startsWith("Point "));
        JobSettings.RobotSettings r = GuiActionRunner.execute(() -> model.job().robot().orElseThrow());
        assertTrue(r.robotTable().xMm() == 400 && r.robotTable().zMm() == 500 && r.tablePiece().yMm() == 10,
                r.toString());

        window.tabbedPane("tabs").selectTab("Output");
        window.radioButton("output-preview-rapid").click();
        Pause.pause(new Condition("the RAPID program is previewed") {
            @Override
            public boolean test() {
                String s = GuiActionRunner.execute(() -> window.textBox("output-text").target().getText());
                return s.contains("MoveL");
            }
        }, Timeout.timeout(60_000));
        shoot("robot-output.png");
        window.tabbedPane("tabs").selectTab("Robot");
        window.button("robot-symbolic").click();
        Pause.pause(new Condition("the symbolic forward kinematics is shown") {
            @Override
            public boolean test() {
                String s = GuiActionRunner.execute(() -> window.textBox("robot-fk").target().getText());
                return s.contains("px = ");
            }
        }, Timeout.timeout(60_000));
        shoot("robot-robot.png");
    }

    /** For looking at after the build: target/screenshots/robot-*.png. */
    private void shoot(String name) {
        java.awt.image.BufferedImage img = GuiActionRunner.execute(
                () -> TabScreenshotsTest.paint((javax.swing.JFrame) window.target()));
        try {
            java.nio.file.Files.createDirectories(Path.of("target", "screenshots"));
            javax.imageio.ImageIO.write(img, "png", Path.of("target", "screenshots", name).toFile());
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private void setField(String name, String text) {
        window.textBox(name).deleteText().enterText(text);
    }

    private void waitUntilNoTaskRuns() {
        Pause.pause(new Condition("no task is running") {
            @Override
            public boolean test() {
                return GuiActionRunner.execute(() -> window.robot().finder().findAll(new GenericTypeMatcher<>(
                        javax.swing.JProgressBar.class, false) {
                    @Override
                    protected boolean isMatching(javax.swing.JProgressBar b) {
                        return b.isShowing();
                    }
                }).isEmpty());
            }
        }, Timeout.timeout(60_000));
    }
}
