package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.assertj.swing.core.GenericTypeMatcher;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.fresa.job.JobSettings;
import org.junit.jupiter.api.Test;

/** The Robot, Position and Output tabs under a (virtual) display; a headless run skips it. */
class RobotTabsGuiTest extends WindowGuiTest {

    @Test
    void example1IsComputedOnTheIrb140AndItsProgramPreviewed() {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        Path stp = Path.of("samples/stepnc/iso14649-11-example1.stp").toAbsolutePath();
        GuiActionRunner.execute(() -> model.setJob(
                model.job().withStepnc(new JobSettings.StepNcSettings(stp, org.fresa.post.MillingPost.LINUXCNC))));
        waitUntilNoTaskRuns();

        showTab("Robot");
        window.comboBox("robot-choice").selectItem("irb140");
        window.table("robot-dh").requireRowCount(6);

        window.tabbedPane("tabs").selectTab("Position");
        setField("position-rt-X", "400");
        setField("position-rt-Y", "-200");
        setField("position-rt-Z", "500");
        setField("position-tp-Y", "10");
        window.textBox("position-rt-Z").requireText("500");
        window.button("position-compute").click();
        window.tabbedPane("position-results").selectTab("Summary");
        Pause.pause(
                new Condition("the summary shows the result") {
                    @Override
                    public boolean test() {
                        String s = GuiActionRunner.execute(() ->
                                window.textBox("position-summary").target().getText());
                        return s.contains("Unreachable: 0");
                    }
                },
                Timeout.timeout(120_000));
        window.slider("position-replay")
                .slideTo(GuiActionRunner.execute(
                        () -> window.slider("position-replay").target().getMaximum() / 2));
        shoot("robot-position.png");
        // what fresa run says of the job is listed under the figures, as it says it
        String[] said = window.list("position-warnings").contents();
        assertTrue(
                java.util.Arrays.stream(said).anyMatch(w -> w.startsWith("no spindle given")),
                java.util.Arrays.toString(said));
        assertTrue(window.label("position-point").target().getText().startsWith("Point "));
        JobSettings.RobotSettings r =
                GuiActionRunner.execute(() -> model.job().robot().orElseThrow());
        assertTrue(
                r.robotTable().xMm() == 400
                        && r.robotTable().zMm() == 500
                        && r.tablePiece().yMm() == 10,
                r.toString());

        window.tabbedPane("tabs").selectTab("Output");
        window.radioButton("output-preview-rapid").click();
        Pause.pause(
                new Condition("the RAPID program is previewed") {
                    @Override
                    public boolean test() {
                        String s = GuiActionRunner.execute(
                                () -> window.textBox("output-text").target().getText());
                        return s.contains("MoveL");
                    }
                },
                Timeout.timeout(60_000));
        shoot("robot-output.png");
        window.tabbedPane("tabs").selectTab("Robot");
        window.button("robot-symbolic").click();
        Pause.pause(
                new Condition("the symbolic forward kinematics is shown") {
                    @Override
                    public boolean test() {
                        String s = GuiActionRunner.execute(
                                () -> window.textBox("robot-fk").target().getText());
                        return s.contains("px = ");
                    }
                },
                Timeout.timeout(60_000));
        shoot("robot-robot.png");
    }

    @Test
    void aDhCellEditedWithTheKeyboardIsTheRobotTheJobComputesAndReplays() throws Exception {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        Path stp = Path.of("samples/stepnc/iso14649-11-example1.stp").toAbsolutePath();
        GuiActionRunner.execute(() -> model.setJob(
                model.job().withStepnc(new JobSettings.StepNcSettings(stp, org.fresa.post.MillingPost.LINUXCNC))));
        waitUntilNoTaskRuns();
        showTab("Robot");
        window.comboBox("robot-choice").selectItem("irb140");

        // joint 2's theta: a variable of another joint is refused with the reason
        typeIntoCell(1, RobotViewModel.THETA, "q3 - 90");
        window.label("robot-messages").requireText(java.util.regex.Pattern.compile(".*joint 2 may use only q2.*"));
        typeIntoCell(1, RobotViewModel.THETA, "q2 - 90");
        window.label("robot-messages").requireText(" ");
        // joint 6's theta gets an offset: the job then names a robot file with it
        // (only letters, digits, '-' and spaces: the robot's key map under Xvfb turns '+' into ']')
        typeIntoCell(5, RobotViewModel.THETA, "q6 - -10");
        window.table("robot-dh")
                .requireCellValue(org.assertj.swing.data.TableCell.row(5).column(RobotViewModel.THETA), "q6 - -10");
        Pause.pause(
                new Condition("the job names the edited robot") {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(
                                        () -> model.job().robot().orElseThrow().robot())
                                .startsWith(dir.resolve("robots").toString());
                    }
                },
                Timeout.timeout(10_000));
        String robotFile =
                GuiActionRunner.execute(() -> model.job().robot().orElseThrow().robot());
        org.fresa.kin.SerialRobot edited = (org.fresa.kin.SerialRobot) org.fresa.cell.RobotFiles.load(robotFile);
        assertEquals(10, edited.chain().joints().get(5).thetaDeg());
        assertEquals("irb140-edited", edited.name());
        Pause.pause(
                new Condition("the symbolic forward kinematics follows the table") {
                    @Override
                    public boolean test() {
                        String s = GuiActionRunner.execute(
                                () -> window.textBox("robot-fk").target().getText());
                        return s.startsWith("Forward kinematics of irb140-edited") && s.contains("px = ");
                    }
                },
                Timeout.timeout(60_000));
        shoot("robot-edited.png");

        window.tabbedPane("tabs").selectTab("Position");
        setField("position-rt-X", "400");
        setField("position-rt-Y", "-200");
        setField("position-rt-Z", "500");
        setField("position-tp-Y", "10");
        window.button("position-compute").click();
        window.tabbedPane("position-results").selectTab("Summary");
        Pause.pause(
                new Condition("the summary shows the result") {
                    @Override
                    public boolean test() {
                        String s = GuiActionRunner.execute(() ->
                                window.textBox("position-summary").target().getText());
                        return s.contains("Unreachable: 0");
                    }
                },
                Timeout.timeout(120_000));
        String summary = GuiActionRunner.execute(
                () -> window.textBox("position-summary").target().getText());
        assertTrue(summary.contains("Robot: irb140-edited"), summary);

        window.tabbedPane("position-results").selectTab("Joints");
        CellView cell = (CellView) window.robot().finder().findByName("position-cell");
        int max = GuiActionRunner.execute(
                () -> window.slider("position-replay").target().getMaximum());
        assertTrue(max > 10);
        for (int target : new int[] {max / 3, 2 * max / 3}) {
            window.slider("position-replay").slideTo(target);
            CellScene scene = GuiActionRunner.execute(cell::scene);
            CellScene.PathPoint sel = scene.selected().orElseThrow();
            java.util.List<org.fresa.geom.Vec3> arm = scene.links().get(0);
            // the robot drawn reaches the replayed point with its tool, which starts at the arm's flange
            org.fresa.geom.Vec3 flange = arm.get(arm.size() - 1);
            assertEquals(
                    0, scene.tool().map(CellScene.ToolShape::tip).orElse(flange).distance(sel.at()), 1e-6);
            scene.tool().ifPresent(t -> assertEquals(0, flange.distance(t.flange()), 1e-6));
            double marked = GuiActionRunner.execute(() -> {
                org.jfree.chart.ChartPanel p =
                        (org.jfree.chart.ChartPanel) window.robot().finder().findByName("position-joints-chart");
                var sub = ((org.jfree.chart.plot.CombinedDomainXYPlot)
                                p.getChart().getPlot())
                        .getSubplots()
                        .get(0);
                return ((org.jfree.chart.plot.ValueMarker) sub.getDomainMarkers(org.jfree.chart.ui.Layer.FOREGROUND)
                                .iterator()
                                .next())
                        .getValue();
            });
            assertEquals(target + 1, marked);
        }

        // the 3D view turns with the arrow keys and Home puts it back
        window.robot().click(cell);
        window.robot().pressAndReleaseKey(java.awt.event.KeyEvent.VK_LEFT);
        assertEquals(
                OrbitCamera.DEFAULT_AZIMUTH_DEG + 5,
                GuiActionRunner.execute(() -> cell.camera().azimuthDeg()),
                1e-9);
        window.robot().pressAndReleaseKey(java.awt.event.KeyEvent.VK_HOME);
        assertEquals(
                OrbitCamera.DEFAULT_AZIMUTH_DEG,
                GuiActionRunner.execute(() -> cell.camera().azimuthDeg()));
        shoot("robot-position-3d.png");
        window.tabbedPane("position-results").selectTab("Position error");
        shoot("robot-position-error.png");

        // Compute never changes what the job runs: the planner ticks the robot module (which drops
        // the new job's pocket, which has no settings); the saved job runs on the edited robot
        assertEquals(
                java.util.List.of(org.fresa.job.JobTask.POCKET),
                GuiActionRunner.execute(() -> model.job().runs()));
        window.menuItem("run-robot").click();
        assertEquals(
                java.util.List.of(org.fresa.job.JobTask.ROBOT),
                GuiActionRunner.execute(() -> model.job().runs()));
        Path job = dir.resolve("edited.xml");
        GuiActionRunner.execute(() -> {
            model.saveAs(job);
            return null;
        });
        java.io.StringWriter err = new java.io.StringWriter();
        int status = org.fresa.app.cli.FresaCommand.execute(
                new java.io.PrintWriter(new java.io.StringWriter(), true),
                new java.io.PrintWriter(err, true),
                "run",
                job.toString(),
                "--out",
                dir.resolve("out").toString());
        assertEquals(0, status, err.toString());
        String json = java.nio.file.Files.readString(dir.resolve("out").resolve("summary.json"));
        assertTrue(json.contains("irb140-edited"), json);
    }

    /** Keyboard only: arrows to the cell, type (which replaces its text), Enter. */
    private void typeIntoCell(int row, int col, String text) {
        window.table("robot-dh")
                .cell(org.assertj.swing.data.TableCell.row(0).column(0))
                .click();
        for (int i = 0; i < row; i++) {
            window.robot().pressAndReleaseKey(java.awt.event.KeyEvent.VK_DOWN);
        }
        for (int i = 0; i < col; i++) {
            window.robot().pressAndReleaseKey(java.awt.event.KeyEvent.VK_RIGHT);
        }
        window.robot().enterText(text);
        window.robot().pressAndReleaseKey(java.awt.event.KeyEvent.VK_ENTER);
        window.robot().waitForIdle();
    }

    /** For looking at after the build: target/screenshots/robot-*.png. */
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

    private void setField(String name, String text) {
        window.textBox(name).deleteText().enterText(text);
    }

    private void waitUntilNoTaskRuns() {
        Pause.pause(
                new Condition("no task is running") {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(() -> window.robot()
                                .finder()
                                .findAll(new GenericTypeMatcher<>(javax.swing.JProgressBar.class, false) {
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

    /** Selects a tab, again through the model when the virtual display lost the click. */
    private void showTab(String title) {
        window.tabbedPane("tabs").selectTab(title);
        GuiActionRunner.execute(() -> {
            javax.swing.JTabbedPane t = window.tabbedPane("tabs").target();
            t.setSelectedIndex(t.indexOfTab(title));
        });
        window.robot().waitForIdle();
    }
}
