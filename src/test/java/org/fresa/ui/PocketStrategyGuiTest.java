package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.fresa.job.Job;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.job.JobTask;
import org.fresa.job.PocketService;
import org.fresa.job.ProgressMonitor;
import org.fresa.pocket.PocketStrategy;
import org.junit.jupiter.api.Test;

/**
 * The Pocket tab's strategy fields, as a planner uses them: each reached by its label's mnemonic,
 * a bad angle marked, zigzag at 30 degrees with 0.3 mm of stock computed into the job, and the
 * program shown is the one {@code fresa pocket} writes for the same settings.
 */
class PocketStrategyGuiTest extends WindowGuiTest {

    @Override
    java.awt.Dimension windowSize() {
        return new java.awt.Dimension(1400, 900);
    }

    private String status() {
        return GuiActionRunner.execute(() -> {
            javax.swing.JLabel l = window.label("pocket-status").target();
            return l.getToolTipText() != null ? l.getToolTipText() : l.getText();
        });
    }

    @Test
    void zigzagTypedInTheTabIsTheJobsAndItsProgramIsFresaPockets(@org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        GuiActionRunner.execute(() -> model.setJob(
                Job.empty(JobTask.POCKET).withPocket(PocketViewModelTest.roomsIslands(0.6, PocketStrategy.DEFAULT))));
        window.tabbedPane("tabs").selectTab("Pocket");
        window.comboBox(PocketViewModel.STRATEGY).requireSelection("offset");
        // a .contour file loads no rows into the .dad editor: that is said as a note, not in red
        javax.swing.JLabel editorStatus = GuiActionRunner.execute(() -> (javax.swing.JLabel)
                window.robot().finder().findByName(window.target(), "pocket-contour-status", false));
        assertTrue(
                GuiActionRunner.execute(() -> editorStatus.getText().startsWith("No elements typed")
                        && java.awt.Color.BLACK.equals(editorStatus.getForeground())),
                () -> GuiActionRunner.execute(editorStatus::getText));
        // and the plot shows the file's contours before any Compute
        String plotted = GuiActionRunner.execute(() -> window
                .robot()
                .finder()
                .findAll(
                        window.target(),
                        new org.assertj.swing.core.GenericTypeMatcher<PlotPanel>(PlotPanel.class, true) {
                            @Override
                            protected boolean isMatching(PlotPanel p) {
                                return true;
                            }
                        })
                .stream()
                .max(java.util.Comparator.comparingInt(PlotPanel::getWidth))
                .orElseThrow()
                .scene()
                .title());
        assertEquals("rooms-islands.contour as read, 2 islands: press Compute", plotted);
        // every strategy field has a label that names it and takes the keyboard there
        for (String name : new String[] {
            PocketViewModel.STRATEGY,
            PocketViewModel.ANGLE,
            PocketViewModel.STOCK_TO_LEAVE,
            PocketViewModel.ORDER,
            PocketViewModel.REST_TOOL
        }) {
            assertTrue(
                    GuiActionRunner.execute(() -> {
                        java.awt.Component field = window.robot().finder().findByName(window.target(), name, true);
                        for (java.awt.Component c : field.getParent().getComponents()) {
                            if (c instanceof javax.swing.JLabel l
                                    && l.getLabelFor() == field
                                    && l.getDisplayedMnemonic() != 0) {
                                return true;
                            }
                        }
                        return false;
                    }),
                    name);
        }
        window.comboBox(PocketViewModel.STRATEGY).selectItem("zigzag");
        window.textBox(PocketViewModel.ANGLE).deleteText().enterText("200");
        Pause.pause(
                new Condition("the bad angle is explained") {
                    @Override
                    public boolean test() {
                        return status().contains("Zigzag angle (deg)");
                    }
                },
                Timeout.timeout(30_000));
        window.button("pocket-compute").requireDisabled();
        window.textBox(PocketViewModel.ANGLE).deleteText().enterText("30");
        window.textBox(PocketViewModel.STOCK_TO_LEAVE).deleteText().enterText("0.3");
        window.button("pocket-compute").requireEnabled();
        window.button("pocket-compute").click();
        Pause.pause(
                new Condition("the program is computed") {
                    @Override
                    public boolean test() {
                        return status().equals("done") || status().contains("refused");
                    }
                },
                Timeout.timeout(60_000));
        assertEquals("done", status());
        PocketSettings s = GuiActionRunner.execute(() -> model.job().pocket().orElseThrow());
        assertEquals(
                new PocketStrategy(PocketStrategy.Kind.ZIGZAG, 30, 0.3, PocketStrategy.Order.INSIDE_OUT), s.strategy());
        Path out = dir.resolve("p.ngc");
        assertEquals(0, PocketService.run(s, out, ProgressMonitor.NONE).exitStatus());
        // the program's text, whichever of the tab's texts is in front
        String shown = GuiActionRunner.execute(() -> window.robot()
                .finder()
                .findByName(window.target(), "pocket-nc", javax.swing.text.JTextComponent.class, false)
                .getText());
        assertEquals(Files.readString(out), shown);
    }

    @Test
    void aRestToolTypedInTheTabIsCheckedAsTypedAndItsProgramIsFresaPockets(@org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        GuiActionRunner.execute(() -> model.setJob(
                Job.empty(JobTask.POCKET).withPocket(PocketViewModelTest.roomsIslands(0.6, PocketStrategy.DEFAULT))));
        window.tabbedPane("tabs").selectTab("Pocket");
        window.textBox(PocketViewModel.REST_TOOL).requireText("");
        window.textBox(PocketViewModel.REST_TOOL).enterText("6");
        Pause.pause(
                new Condition("the rest tool as large as the first is explained") {
                    @Override
                    public boolean test() {
                        return status().contains("Rest tool (mm)");
                    }
                },
                Timeout.timeout(30_000));
        window.button("pocket-compute").requireDisabled();
        window.textBox(PocketViewModel.REST_TOOL).deleteText().enterText("2");
        window.button("pocket-compute").requireEnabled();
        window.button("pocket-compute").click();
        Pause.pause(
                new Condition("the program is computed") {
                    @Override
                    public boolean test() {
                        return status().equals("done") || status().contains("refused");
                    }
                },
                Timeout.timeout(60_000));
        assertEquals("done", status());
        PocketSettings s = GuiActionRunner.execute(() -> model.job().pocket().orElseThrow());
        assertEquals(2, s.strategy().restToolDiameterMm());
        Path out = dir.resolve("p.ngc");
        assertEquals(0, PocketService.run(s, out, ProgressMonitor.NONE).exitStatus());
        String shown = GuiActionRunner.execute(() -> window.robot()
                .finder()
                .findByName(window.target(), "pocket-nc", javax.swing.text.JTextComponent.class, false)
                .getText());
        assertEquals(Files.readString(out), shown);
        assertTrue(shown.contains("T2 M6"));
    }

    @Test
    void adaptiveChosenInTheTabSaysWhatItSlowsAndItsProgramIsFresaPockets(@org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        GuiActionRunner.execute(() -> model.setJob(
                Job.empty(JobTask.POCKET).withPocket(PocketViewModelTest.roomsIslands(0.4, PocketStrategy.DEFAULT))));
        window.tabbedPane("tabs").selectTab("Pocket");
        window.comboBox(PocketViewModel.STRATEGY).selectItem("adaptive");
        window.button("pocket-compute").click();
        Pause.pause(
                new Condition("the program is computed") {
                    @Override
                    public boolean test() {
                        return status().startsWith("done") || status().contains("refused");
                    }
                },
                Timeout.timeout(120_000));
        // the rooms' narrow doors are slotted at a lower feed, and the status line says so before Save
        assertTrue(status().startsWith("done, with a warning: adaptive: "), status());
        PocketSettings s = GuiActionRunner.execute(() -> model.job().pocket().orElseThrow());
        assertEquals(PocketStrategy.Kind.ADAPTIVE, s.strategy().kind());
        Path out = dir.resolve("p.ngc");
        org.fresa.job.TaskOutcome o = PocketService.run(s, out, ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus());
        assertTrue(status().endsWith(o.problems().get(0).substring("warning: ".length())), status());
        String shown = GuiActionRunner.execute(() -> window.robot()
                .finder()
                .findByName(window.target(), "pocket-nc", javax.swing.text.JTextComponent.class, false)
                .getText());
        assertEquals(Files.readString(out), shown);
        java.nio.file.Path shots = Path.of("target/screenshots");
        Files.createDirectories(shots);
        javax.imageio.ImageIO.write(
                GuiActionRunner.execute(() -> TabScreenshotsTest.paint((javax.swing.JFrame) window.target())),
                "png",
                shots.resolve("pocket-adaptive.png").toFile());
    }
}
