package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Supplier;
import org.assertj.swing.core.KeyPressInfo;
import org.assertj.swing.core.MouseButton;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.JTableFixture;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.fresa.cutting.CutOrderOverride;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;
import org.fresa.job.Job;
import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.job.JobTask;
import org.junit.jupiter.api.Test;

/**
 * The planner orders the cuts by hand in the Cutting tab: Alt+Up over another hole, a part
 * refused over its own hole, a start picked with Shift+click in the plot and one typed, an undo,
 * Reset; each edit in the job. The tab is written to target/screenshots/cutting-order.png.
 */
class CuttingOrderGuiTest extends WindowGuiTest {

    // AssertJ Swing's robot takes the old modifier masks
    @SuppressWarnings("deprecation")
    private static final int ALT = InputEvent.ALT_MASK;

    @SuppressWarnings("deprecation")
    private static final int SHIFT = InputEvent.SHIFT_MASK;

    @Override
    java.awt.Dimension windowSize() {
        return new java.awt.Dimension(1400, 900);
    }

    private MainViewModel model;

    private CutOrderOverride jobOrder() {
        return GuiActionRunner.execute(() -> model.job().cutting().orElseThrow().cutOrder());
    }

    private static void await(String what, Supplier<Boolean> test) {
        Pause.pause(
                new Condition(what) {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(test::get);
                    }
                },
                Timeout.timeout(60_000));
    }

    private String[][] rows(JTableFixture t) {
        return GuiActionRunner.execute(() -> t.contents());
    }

    @Test
    void thePlannerReordersCutsAndMovesStartsByHand() throws Exception {
        model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        Path drawing = Path.of("samples/cutting/plate.dxf").toAbsolutePath();
        GuiActionRunner.execute(() -> model.setJob(Job.empty(JobTask.CUT)
                .withCutting(new CuttingSettings(
                        drawing,
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
        window.button("cutting-cut").click();
        JTableFixture table = window.table("cutting-order");
        await("the drawing is cut and its cuts listed", () -> table.target().getRowCount() == 10);
        String[][] auto = rows(table);

        // a hole one place earlier, over another hole: Alt+Up
        int hole = 1;
        while (!(auto[hole][1].contains("hole") && auto[hole - 1][1].contains("hole"))) {
            hole++;
        }
        String moved = auto[hole][1];
        table.selectRows(hole);
        table.pressAndReleaseKey(KeyPressInfo.keyCode(KeyEvent.VK_UP).modifiers(ALT));
        int up = hole - 1;
        await(
                "the hole is cut one place earlier",
                () -> table.target().getRowCount() == 10
                        && table.target().getValueAt(up, 1).equals(moved));
        assertEquals(
                up, GuiActionRunner.execute(() -> table.target().getSelectedRow()), "the moved cut stays selected");
        assertEquals(10, jobOrder().cuts().size(), "the order is the job's");
        assertEquals(moved, jobOrder().cuts().get(up).contour());

        // a part over its own last hole: refused, said beside Cut, the order unchanged
        String[][] now = rows(table);
        int part = 1;
        while (!(!now[part][1].contains("hole") && now[part - 1][1].startsWith(now[part][1] + " hole"))) {
            part++;
        }
        table.selectRows(part);
        table.pressAndReleaseKey(KeyPressInfo.keyCode(KeyEvent.VK_UP).modifiers(ALT));
        String said = GuiActionRunner.execute(
                () -> window.label("cutting-status").target().getToolTipText());
        assertTrue(said != null && said.contains("lies inside " + now[part][1]), said);
        assertEquals(java.util.Arrays.deepToString(now), java.util.Arrays.deepToString(rows(table)));

        // Shift+click on the middle of the first cut's path: it starts there
        PlotPanel plot = window.robot()
                .finder()
                .find(new org.assertj.swing.core.GenericTypeMatcher<PlotPanel>(PlotPanel.class, true) {
                    @Override
                    protected boolean isMatching(PlotPanel c) {
                        return true;
                    }
                });
        await("the plot is drawn", plot::isDrawn);
        Curve2 longest =
                GuiActionRunner.execute(() -> plot.scene().layers().stream()
                        .filter(l -> l.name().equals("cuts"))
                        .findFirst()
                        .orElseThrow()
                        .curves()
                        .stream()
                        .max(java.util.Comparator.comparingDouble(Curve2::length))
                        .orElseThrow());
        Vec2 mid = longest.pointAt(0.5);
        java.awt.Point at = GuiActionRunner.execute(() -> plot.toPixels(mid));
        window.robot().pressModifiers(SHIFT);
        try {
            window.robot().click(plot.chartComponent(), at, MouseButton.LEFT_BUTTON, 1);
        } finally {
            window.robot().releaseModifiers(SHIFT);
        }
        await(
                "a start picked in the plot",
                () -> jobOrder().cuts().stream().anyMatch(c -> c.startMm().isPresent())
                        && java.util.Arrays.stream(rowsNow(table)).anyMatch(r -> r[2].endsWith("*")));
        String[] picked = java.util.Arrays.stream(rows(table))
                .filter(r -> r[2].endsWith("*"))
                .findFirst()
                .orElseThrow();
        Vec2 pickedAt = CuttingViewModel.parseStart(picked[2].replace("*", "")).orElseThrow();
        assertTrue(pickedAt.distance(mid) < 2, "started near the click " + mid + ": " + pickedAt);

        // a start typed for the first cut, 4 mm right of where it starts; then undone
        table.selectRows(0);
        Vec2 was =
                CuttingViewModel.parseStart(rows(table)[0][2].replace("*", "")).orElseThrow();
        CutOrderOverride beforeTyping = jobOrder();
        window.textBox("cutting-start")
                .setText(String.format(java.util.Locale.ROOT, "%.3f, %.3f", was.x() + 4, was.y()));
        window.button("cutting-start-set").click();
        await(
                "the typed start is cut",
                () -> !jobOrder().equals(beforeTyping)
                        && table.target().getRowCount() == 10
                        && String.valueOf(table.target().getValueAt(0, 2)).endsWith("*"));
        window.robot().waitForIdle();
        shot("cutting-order.png");
        assertTrue(GuiActionRunner.execute(model::undo));
        await(
                "the typed start undone and cut again",
                () -> jobOrder().equals(beforeTyping)
                        && table.target().getRowCount() == 10
                        && !String.valueOf(table.target().getValueAt(0, 2)).endsWith("*"));

        // Reset: the automatic order and starts again, and the job without an order
        window.button("cutting-order-reset").click();
        await(
                "back to the automatic order",
                () -> jobOrder().isEmpty()
                        && table.target().getRowCount() == 10
                        && java.util.Arrays.deepEquals(rowsNow(table), auto));
    }

    private static String[][] rowsNow(JTableFixture t) {
        javax.swing.JTable j = t.target();
        String[][] out = new String[j.getRowCount()][j.getColumnCount()];
        for (int r = 0; r < out.length; r++) {
            for (int c = 0; c < out[r].length; c++) {
                out[r][c] = String.valueOf(j.getValueAt(r, c));
            }
        }
        return out;
    }

    private void shot(String name) throws java.io.IOException {
        java.awt.image.BufferedImage img =
                GuiActionRunner.execute(() -> TabScreenshotsTest.paint((javax.swing.JFrame) window.target()));
        Files.createDirectories(Path.of("target", "screenshots"));
        javax.imageio.ImageIO.write(
                img, "png", Path.of("target", "screenshots", name).toFile());
    }
}
