package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.event.KeyEvent;
import java.nio.file.Path;
import javax.swing.JTree;
import org.assertj.swing.core.GenericTypeMatcher;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.JSliderFixture;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.fresa.chart.PlotScene;
import org.fresa.job.JobSettings;
import org.junit.jupiter.api.Test;

/** The STEP-NC tab's toolpath view under a (virtual) display; a headless run skips it. */
class StepNcTabGuiTest extends WindowGuiTest {

    @Test
    void example1sPocketIsReplayedFromTheKeyboard() {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        Path stp = Path.of("samples/stepnc/iso14649-11-example1.stp").toAbsolutePath();
        window.tabbedPane("tabs").selectTab("STEP-NC");
        GuiActionRunner.execute(() -> model.setJob(
                model.job().withStepnc(new JobSettings.StepNcSettings(stp, org.fresa.post.MillingPost.LINUXCNC))));
        Pause.pause(
                new Condition("the program is read and planned") {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(() -> window.label("stepnc-cycle-time")
                                        .target()
                                        .getText())
                                .startsWith("Cycle time: this workingstep");
                    }
                },
                Timeout.timeout(60_000));

        window.tree("stepnc-tree").selectRow(row("WS FINISH POCKET1"));
        shoot("stepnc-selected.png");
        // per layer of 15: a rapid to 1 mm above the layer, a helix entry and a full circle at its
        // floor, the layer's passes, the retract; the end is the last retract to the security plane
        window.label("stepnc-replay-text")
                .requireText(java.util.regex.Pattern.compile(
                        ".* of .*: move 362 of 362 \\(rapid\\), tool at \\(86, 70, 30\\) mm"));
        assertTrue(window.textBox("stepnc-details").text().contains("Cycle time of this workingstep"));

        // Alt+R focuses the replay slider; Home goes to the start, each Right arrow one step on
        window.robot().pressKey(KeyEvent.VK_ALT);
        window.robot().pressAndReleaseKey(KeyEvent.VK_R);
        window.robot().releaseKey(KeyEvent.VK_ALT);
        window.robot().waitForIdle();
        JSliderFixture slider = window.slider("stepnc-replay");
        slider.requireFocused();
        slider.pressAndReleaseKeys(KeyEvent.VK_HOME);
        assertEquals(0, value(slider));
        window.label("stepnc-replay-text")
                .requireText(java.util.regex.Pattern.compile("0\\.0 s of .*before the first move.*"));
        String toolAtStart = toolCircle();
        for (int i = 0; i < 70; i++) {
            slider.pressAndReleaseKeys(KeyEvent.VK_RIGHT);
        }
        assertEquals(70, value(slider));
        String text = window.label("stepnc-replay-text").target().getText();
        assertTrue(text.matches(".* of .*: move \\d+ of 362 .*"), text);
        assertNotEquals(toolAtStart, toolCircle(), "the tool marker moved");

        // one layer: the replay goes to its end
        window.comboBox("stepnc-layer").selectItem(1);
        assertEquals(StepNcViewModel.REPLAY_STEPS, value(slider));
        String title = GuiActionRunner.execute(() -> plotScene().title());
        assertTrue(title.endsWith("layer 1 of 15"), title);
        slider.pressAndReleaseKeys(KeyEvent.VK_PAGE_DOWN);
        shoot("stepnc-layer.png");
        window.comboBox("stepnc-layer").selectItem(0);
        slider.focus();
        slider.pressAndReleaseKeys(KeyEvent.VK_HOME);
        for (int i = 0; i < 70; i++) {
            slider.pressAndReleaseKeys(KeyEvent.VK_RIGHT);
        }
        shoot("stepnc-toolpath.png");
        assertEquals(70, GuiActionRunner.execute(() -> slider.target().getValue()));
    }

    @Test
    void theThesissPathsArePickedInTheTabPlannedAndKeptInTheJob() throws Exception {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        Path stp = Path.of("samples/stepnc/iso14649-11-example1.stp").toAbsolutePath();
        window.tabbedPane("tabs").selectTab("STEP-NC");
        GuiActionRunner.execute(() -> model.setJob(
                model.job().withStepnc(new JobSettings.StepNcSettings(stp, org.fresa.post.MillingPost.LINUXCNC))));
        waitForThePlan();
        window.comboBox("stepnc-paths").requireSelection("Fresa's paths");
        window.comboBox("stepnc-paths").selectItem("the 2016 robot thesis's points");
        Pause.pause(
                new Condition("the job carries the thesis's paths") {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(
                                        () -> model.job().stepnc().orElseThrow().paths())
                                == org.fresa.toolpath.PathConvention.THESIS;
                    }
                },
                Timeout.timeout(10_000));
        waitForThePlan();
        int moves = org.fresa.toolpath.ToolpathPlanner.plan(
                        org.fresa.stepnc.StepNcReader.read(stp),
                        org.fresa.geom.Tolerance.DEFAULT,
                        org.fresa.toolpath.PlanningChoices.DEFAULT.withPaths(org.fresa.toolpath.PathConvention.THESIS))
                .toolpath()
                .sections()
                .stream()
                .filter(x -> x.label().equals("WS FINISH POCKET1"))
                .findFirst()
                .orElseThrow()
                .moves()
                .size();
        // planned again in the background: the workingstep shows the thesis's moves once it is done
        String want = "move " + moves + " of " + moves + " (rapid), tool at (0, 0, 30) mm";
        Pause.pause(
                new Condition("the thesis's plan is shown") {
                    @Override
                    public boolean test() {
                        try {
                            window.tree("stepnc-tree").selectRow(row("WS FINISH POCKET1"));
                        } catch (RuntimeException | AssertionError e) {
                            return false;
                        }
                        return GuiActionRunner.execute(() -> window.label("stepnc-replay-text")
                                        .target()
                                        .getText())
                                .endsWith(want);
                    }
                },
                Timeout.timeout(60_000));
        shoot("stepnc-thesis-paths.png");
    }

    /**
     * A toolpath job's problem list says what fresa run of it says: example 2's workingsteps on its
     * side faces, which the 3-axis program leaves for another setup.
     */
    @Test
    void aToolpathJobListsTheWorkingstepsItsProgramLeavesOut() {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        Path stp = Path.of("samples/stepnc/example2.stp").toAbsolutePath();
        window.tabbedPane("tabs").selectTab("STEP-NC");
        GuiActionRunner.execute(() -> model.setJob(model.job()
                .withTask(org.fresa.job.JobTask.TOOLPATH)
                .withStepnc(new JobSettings.StepNcSettings(stp, org.fresa.post.MillingPost.LINUXCNC))));
        waitForThePlan();
        String[] rows = window.list("stepnc-problems").contents();
        org.junit.jupiter.api.Assertions.assertTrue(
                java.util.Arrays.stream(rows)
                        .anyMatch(r -> r.endsWith("tool axis (0, -1, 0): a 3-axis program machines along +Z only;"
                                + " 11 workingsteps need another setup")),
                java.util.Arrays.toString(rows));
        shoot("stepnc-toolpath-job.png");
    }

    private void waitForThePlan() {
        Pause.pause(
                new Condition("the program is read and planned") {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(() -> window.label("stepnc-cycle-time")
                                        .target()
                                        .getText())
                                .startsWith("Cycle time: this workingstep");
                    }
                },
                Timeout.timeout(60_000));
    }

    private static int value(JSliderFixture slider) {
        return GuiActionRunner.execute(() -> slider.target().getValue());
    }

    private int row(String label) {
        return GuiActionRunner.execute(() -> {
            JTree t = window.tree("stepnc-tree").target();
            for (int i = 0; i < t.getRowCount(); i++) {
                if (t.getPathForRow(i).getLastPathComponent().toString().contains(label)) {
                    return i;
                }
            }
            throw new AssertionError("no row " + label);
        });
    }

    private PlotScene plotScene() {
        PlotPanel p = window.robot().finder().find(window.target(), new GenericTypeMatcher<>(PlotPanel.class, true) {
            @Override
            protected boolean isMatching(PlotPanel c) {
                return true;
            }
        });
        return p.scene();
    }

    private String toolCircle() {
        return GuiActionRunner.execute(() -> plotScene().layers().stream()
                .filter(l -> l.name().equals("tool"))
                .findFirst()
                .orElseThrow()
                .curves()
                .get(0)
                .toString());
    }

    /** For looking at after the build: target/screenshots/stepnc-*.png. */
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
}
