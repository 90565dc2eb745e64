package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.event.KeyEvent;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.assertj.swing.data.TableCell;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.JTableFixture;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.fresa.io.OutputFolder;
import org.fresa.job.Job;
import org.fresa.job.JobRunner;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.job.JobTask;
import org.fresa.job.JobXml;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.TaskOutcome;
import org.fresa.pocket.DadContour;
import org.junit.jupiter.api.Test;

/**
 * A planner types a small pocket into the Pocket tab's contour editor, a rectangle with one side
 * an arc, by keyboard: the job holds the contour as typed (each edit one undo step), the saved
 * job run by {@link JobRunner} writes the program the tab shows, and Save contour as .dad writes
 * the thesis's records. Screenshot in target/screenshots/pocket-contour-editor.png.
 */
class PocketContourEditorGuiTest extends WindowGuiTest {

    @Override
    java.awt.Dimension windowSize() {
        return new java.awt.Dimension(1400, 900);
    }

    private String text(String label) {
        return GuiActionRunner.execute(() -> {
            javax.swing.JLabel l = window.label(label).target();
            return l.getToolTipText() != null ? l.getToolTipText() : l.getText();
        });
    }

    private void waitFor(String what, String label, java.util.function.Predicate<String> p) {
        Pause.pause(
                new Condition(what) {
                    @Override
                    public boolean test() {
                        return p.test(text(label));
                    }
                },
                Timeout.timeout(60_000));
    }

    private static void type(JTableFixture t, int row, PocketContourEditor.Column c, String value) {
        t.enterValue(TableCell.row(row).column(c.ordinal() + 1), value);
    }

    @Test
    void aContourTypedInTheTabIsTheJobsAndRunsToTheProgramTheTabShows() throws Exception {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        GuiActionRunner.execute(() -> model.setJob(Job.empty(JobTask.POCKET)));
        window.tabbedPane("tabs").selectTab("Pocket");
        window.tabbedPane("pocket-texts").selectTab("Contour elements");
        JTableFixture table = window.table("pocket-contour-table");
        table.focus();
        // four elements added by the Insert key, each a line y = 0 until typed over
        for (int i = 0; i < 4; i++) {
            table.pressAndReleaseKeys(KeyEvent.VK_INSERT);
        }
        assertEquals(4, table.rowCount());
        type(table, 0, PocketContourEditor.Column.D, "30");
        type(table, 1, PocketContourEditor.Column.TYPE, "arc");
        type(table, 1, PocketContourEditor.Column.A, "20");
        type(table, 1, PocketContourEditor.Column.B, "15");
        type(table, 1, PocketContourEditor.Column.D, "25");
        type(table, 1, PocketContourEditor.Column.SELECTOR, "L");
        type(table, 2, PocketContourEditor.Column.SELECTOR, "L");
        type(table, 3, PocketContourEditor.Column.A, "1");
        // a decimal comma: the cell is pink, the reason under the table
        type(table, 3, PocketContourEditor.Column.B, "0,0");
        waitFor("the bad cell is explained", "pocket-contour-status", s -> s.contains("decimals take a point"));
        assertEquals(
                "Element 4, B: '0,0' is not a number (decimals take a point: 0.0).", text("pocket-contour-status"));
        table.selectCell(TableCell.row(0).column(1));
        assertEquals(new java.awt.Color(255, 220, 220), GuiActionRunner.execute(() -> {
            javax.swing.JTable t = table.target();
            return t.prepareRenderer(t.getCellRenderer(3, 3), 3, 3).getBackground();
        }));
        // the job keeps the last valid value: the line x + y = 0 closed the contour already
        assertEquals(
                1,
                GuiActionRunner.execute(() -> model.job()
                        .pocket()
                        .orElseThrow()
                        .elements()
                        .orElseThrow()
                        .elements()
                        .get(3)
                        .b()));
        type(table, 3, PocketContourEditor.Column.B, "0");
        waitFor("the contour closes", "pocket-contour-status", s -> s.equals("4 elements, closed"));
        DadContour typed = PocketContourEditorTest.rectangleWithArc();
        assertEquals(
                typed,
                GuiActionRunner.execute(
                        () -> model.job().pocket().orElseThrow().elements().orElseThrow()));

        // one more edit is one undo step: the tab shows the contour from before it
        type(table, 0, PocketContourEditor.Column.D, "31");
        assertEquals(
                31,
                GuiActionRunner.execute(() -> model.job()
                        .pocket()
                        .orElseThrow()
                        .elements()
                        .orElseThrow()
                        .elements()
                        .get(0)
                        .d()));
        GuiActionRunner.execute(model::undo);
        assertEquals(
                typed,
                GuiActionRunner.execute(
                        () -> model.job().pocket().orElseThrow().elements().orElseThrow()));
        table.requireCellValue(TableCell.row(0).column(PocketContourEditor.Column.D.ordinal() + 1), "30");

        // the program the tab shows is the one the saved job writes
        window.button("pocket-compute").click();
        waitFor(
                "the pocket is computed",
                "pocket-status",
                s -> s.equals("done") || s.contains("refused") || s.contains("cannot"));
        assertEquals("done", text("pocket-status"));
        window.tabbedPane("pocket-texts").selectTab("NC program");
        String shown = GuiActionRunner.execute(
                () -> window.textBox("pocket-nc").target().getText());
        assertTrue(shown.contains("G2") || shown.contains("G02"), "the arc stays an arc:\n" + shown);
        Path job = dir.resolve("typed.xml");
        GuiActionRunner.execute(() -> {
            model.saveAs(job);
            return null;
        });
        Job read = JobXml.read(job);
        PocketSettings p = read.pocket().orElseThrow();
        assertEquals(typed, p.elements().orElseThrow());
        TaskOutcome run = JobRunner.run(read, new OutputFolder(dir.resolve("run")), ProgressMonitor.NONE);
        assertEquals(0, run.exitStatus(), run.problems().toString());
        Path program = run.files().stream()
                .filter(f -> f.getFileName().toString().endsWith(".ngc"))
                .findFirst()
                .orElseThrow(() -> new AssertionError(run.files().toString()));
        assertEquals(shown, Files.readString(program));

        // Save contour as .dad writes the thesis's records; the job keeps the elements under that name
        Path dad = dir.resolve("rectangle.dad");
        window.tabbedPane("pocket-texts").selectTab("Contour elements");
        window.button("pocket-save-contour").click();
        var chooser = window.fileChooser();
        WindowGuiTest.choose(chooser, dad);
        waitFor("the contour is saved", "pocket-status", s -> s.startsWith("Saved"));
        assertEquals(typed.toDad(), Files.readString(dad, StandardCharsets.ISO_8859_1));
        assertEquals(
                List.of(
                        " 4R                     1                     0                     0   1",
                        " 1R                     0                     1                    30   2",
                        " 2C                    20                    15                    25LF 3",
                        " 3R                     0                     1                     0L  4"),
                Files.readString(dad).lines().toList());
        assertEquals(
                dad,
                GuiActionRunner.execute(() -> model.job().pocket().orElseThrow().contour()));
        assertEquals(
                typed,
                GuiActionRunner.execute(
                        () -> model.job().pocket().orElseThrow().elements().orElseThrow()));

        table.selectCell(TableCell.row(1).column(1));
        java.awt.image.BufferedImage img =
                GuiActionRunner.execute(() -> TabScreenshotsTest.paint((javax.swing.JFrame) window.target()));
        Files.createDirectories(Path.of("target", "screenshots"));
        javax.imageio.ImageIO.write(
                img,
                "png",
                Path.of("target", "screenshots", "pocket-contour-editor.png").toFile());
    }
}
