package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Point;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.function.Supplier;
import javax.swing.JComponent;
import org.assertj.swing.core.GenericTypeMatcher;
import org.assertj.swing.core.MouseButton;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.fresa.chart.PlotScene;
import org.fresa.geom.Box2;
import org.fresa.geom.Curve2;
import org.fresa.io.OutputFolder;
import org.fresa.job.Job;
import org.fresa.job.JobRunner;
import org.fresa.job.JobSettings;
import org.fresa.job.JobXml;
import org.fresa.job.ProgressMonitor;
import org.junit.jupiter.api.Test;

/**
 * The Sole tab under a (virtual) display: a library figure placed, nudged with the keys, dragged
 * with the mouse, the programs generated, and the saved job run unchanged by {@code fresa run}.
 */
class SoleTabGuiTest extends WindowGuiTest {

    private void waitFor(String what, Supplier<Boolean> test) {
        Pause.pause(
                new Condition(what) {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(test::get);
                    }
                },
                Timeout.timeout(90_000));
    }

    private JSettingsView placedDesign(MainViewModel model) {
        JobSettings.SoleSettings s =
                GuiActionRunner.execute(() -> model.job().sole().orElseThrow());
        JobSettings.SoleDesign d = s.designs().get(s.designs().size() - 1);
        return new JSettingsView(
                d.name(), d.copies().get(0).dxMm(), d.copies().get(0).dyMm());
    }

    private record JSettingsView(String name, double dxMm, double dyMm) {}

    private static Box2 selectedBox(PlotScene s) {
        PlotScene.Layer l = s.layers().stream()
                .filter(x -> x.style() == PlotScene.Style.WARNING)
                .findFirst()
                .orElseThrow();
        Box2 b = l.curves().get(0).bounds();
        for (Curve2 c : l.curves()) {
            b = b.union(c.bounds());
        }
        return b;
    }

    @Test
    void aFigureIsPlacedNudgedDraggedAndTheProgramsGenerated() throws Exception {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        GuiActionRunner.execute(() -> {
            model.open(Path.of("samples/jobs/sole-men40.xml"));
            return null;
        });
        window.tabbedPane("tabs").selectTab("Sole");
        window.button("sole-load").click();
        waitFor(
                "the sole is planned",
                () -> window.comboBox("sole-size").target().getItemCount() == 5
                        && window.comboBox("sole-designs").target().getItemCount() == 9);
        PlotPanel plot = GuiActionRunner.execute(() -> window
                .robot()
                .finder()
                .findAll(window.target(), new GenericTypeMatcher<PlotPanel>(PlotPanel.class, true) {
                    @Override
                    protected boolean isMatching(PlotPanel p) {
                        return true;
                    }
                })
                .stream()
                .max(Comparator.comparingInt(PlotPanel::getWidth))
                .orElseThrow());
        waitFor("the tread is shown", () -> plot.scene().title().startsWith("Sole 40"));

        // keyboard: Place puts SUB4 in the middle of the plot, the arrows move it
        window.list("sole-library").selectItem("SUB4");
        window.button("sole-place").click();
        waitFor(
                "the figure is placed",
                () -> window.comboBox("sole-designs").target().getItemCount() == 10);
        JSettingsView placed = placedDesign(model);
        assertEquals("SUB4 1", placed.name());
        assertEquals(
                "SUB4 1",
                GuiActionRunner.execute(
                        () -> window.comboBox("sole-designs").target().getSelectedItem()));
        window.table("sole-parameters").requireRowCount(7);
        JComponent chart = GuiActionRunner.execute(plot::chartComponent);
        window.robot().focus(chart);
        waitFor("the plot has the focus", chart::isFocusOwner);
        window.robot().pressAndReleaseKey(KeyEvent.VK_RIGHT);
        window.robot().pressKey(KeyEvent.VK_SHIFT);
        window.robot().pressAndReleaseKey(KeyEvent.VK_UP);
        window.robot().releaseKey(KeyEvent.VK_SHIFT);
        window.robot().waitForIdle();
        JSettingsView nudged = placedDesign(model);
        assertEquals(placed.dxMm() + 1, nudged.dxMm(), 1e-9);
        assertEquals(placed.dyMm() + 10, nudged.dyMm(), 1e-9);

        // the parameters panel: a bad value says why, a good one is taken
        window.table("sole-parameters")
                .enterValue(org.assertj.swing.data.TableCell.row(2).column(2), "-3");
        waitFor(
                "the bad radius is refused",
                () -> window.label("sole-status").target().getText().contains("RA"));
        window.table("sole-parameters")
                .enterValue(org.assertj.swing.data.TableCell.row(2).column(2), "12");
        waitFor(
                "the radius is taken",
                () -> model.job()
                        .sole()
                        .orElseThrow()
                        .designs()
                        .get(8)
                        .figures()
                        .get(0)
                        .params()
                        .contains("RA=12"));

        // mouse: drag the selected ring 60 pixels to the right
        Box2 b = GuiActionRunner.execute(() -> selectedBox(plot.scene()));
        Point from = GuiActionRunner.execute(
                () -> plot.toPixels(org.fresa.geom.Vec2.of(b.center().x(), b.maxY())));
        window.robot().pressMouse(chart, from, MouseButton.LEFT_BUTTON);
        window.robot().moveMouse(chart, new Point(from.x + 30, from.y));
        window.robot().moveMouse(chart, new Point(from.x + 60, from.y));
        window.robot().releaseMouse(MouseButton.LEFT_BUTTON);
        window.robot().waitForIdle();
        JSettingsView dragged = placedDesign(model);
        assertTrue(dragged.dxMm() > nudged.dxMm() + 5, dragged + " after " + nudged);
        assertEquals(nudged.dyMm(), dragged.dyMm(), 1.5);

        screenshot("sole-tab.png");

        // generate, then the saved job run headless gives the same programs
        Path out = dir.resolve("gui-out");
        window.textBox("sole-out").setText(out.toString());
        window.button("sole-generate").click();
        waitFor(
                "the programs are written",
                () -> window.label("sole-status").target().getText().contains("files written"));
        Path saved = dir.resolve("edited.xml");
        GuiActionRunner.execute(() -> {
            model.saveAs(saved);
            return null;
        });
        Job read = JobXml.read(saved);
        JobRunner.run(read, new OutputFolder(dir.resolve("run-out")), ProgressMonitor.NONE);
        for (String n : new String[] {"tread-40-right.ngc", "tread-38-left.ngc", "cavity-42-right.ngc"}) {
            assertEquals(
                    Files.readString(out.resolve(n)),
                    Files.readString(dir.resolve("run-out").resolve(n)),
                    n);
        }
        assertTrue(Files.readString(out.resolve("tread-40-right.ngc")).contains("G3")
                || Files.readString(out.resolve("tread-40-right.ngc")).contains("G2"));

        // Delete on the plot removes the selected figure from the job
        window.robot().focus(chart);
        waitFor("the plot has the focus again", chart::isFocusOwner);
        window.robot().pressAndReleaseKey(KeyEvent.VK_DELETE);
        waitFor(
                "the figure is deleted",
                () -> model.job().sole().orElseThrow().designs().size() == 8);
        assertEquals(
                "(none)",
                GuiActionRunner.execute(
                        () -> window.comboBox("sole-designs").target().getSelectedItem()));
    }

    private void screenshot(String name) throws Exception {
        java.awt.image.BufferedImage img =
                GuiActionRunner.execute(() -> TabScreenshotsTest.paint((javax.swing.JFrame) window.target()));
        Files.createDirectories(Path.of("target", "screenshots"));
        javax.imageio.ImageIO.write(
                img, "png", Path.of("target", "screenshots", name).toFile());
    }
}
