package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.BooleanSupplier;
import org.assertj.swing.core.GenericTypeMatcher;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.JFileChooserFixture;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.junit.jupiter.api.Test;

/**
 * One way to report a bad value, in the Cutting and Grading tabs: the field is marked, the
 * message stands beside the button in the planner's words, the job keeps the last good value, the
 * button is disabled and says why; a task that fails says "failed" in the status bar, no dialog.
 */
class ErrorStyleGuiTest extends WindowGuiTest {

    private static final Color BAD = new Color(255, 220, 220);
    private static final Path JOBS = Path.of("samples/jobs").toAbsolutePath();

    @Test
    void cuttingMarksABadKerfAndAFailedCutSaysFailed() throws Exception {
        open("cut-plate.xml");
        window.tabbedPane("tabs").selectTab("Cutting");
        window.textBox(CuttingViewModel.KERF).deleteText().enterText("6,5");
        window.button("cutting-cut").requireDisabled();
        assertEquals(
                "Correct the marked field first",
                window.button("cutting-cut").target().getToolTipText());
        assertEquals(BAD, window.textBox(CuttingViewModel.KERF).background().target());
        assertEquals(
                "Kerf (mm): '6,5' is not a number (decimals take a point: 6.5).",
                window.label("cutting-status").target().getToolTipText());
        assertEquals(2, model().job().cutting().orElseThrow().kerfMm());
        shoot("cutting-bad-field.png");
        window.textBox(CuttingViewModel.KERF).deleteText().enterText("2.5");
        window.button("cutting-cut").requireEnabled();
        // the good value goes into the job once the typing pauses
        waitFor(
                "the job's kerf is 2.5",
                () -> model().job().cutting().orElseThrow().kerfMm() == 2.5);

        Path bad = dir.resolve("broken.dxf");
        Files.writeString(bad, "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\nabc\n");
        window.button("cutting-open").click();
        JFileChooserFixture fc = window.fileChooser(Timeout.timeout(10_000));
        WindowGuiTest.choose(fc, bad);
        window.button("cutting-cut").click();
        waitFor(
                "the cut ended",
                () -> window.label("status").target().getText().startsWith("Cutting: f")
                        || window.label("status").target().getText().startsWith("Cutting: d"));
        window.label("status").requireText("Cutting: failed");
        String why = window.label("cutting-status").target().getToolTipText();
        assertTrue(why.contains("broken.dxf"), why);
        assertFalse(why.contains("Exception") || why.contains("--"), why);
        assertTrue(optionPanes() == 0, "a dialog was shown");
    }

    @Test
    void gradingMarksARefusedRangeBesideGradeWithoutADialog() throws Exception {
        open("grade-sole40.xml");
        window.tabbedPane("tabs").selectTab("Grading");
        waitFor("Grade may run", () -> window.button("grading-grade").target().isEnabled());
        window.textBox(GradingViewModel.SIZES).deleteText().enterText("44-36");
        window.button("grading-grade").requireDisabled();
        assertEquals(
                "Correct the marked field first",
                window.button("grading-grade").target().getToolTipText());
        assertEquals(BAD, window.textBox(GradingViewModel.SIZES).background().target());
        assertEquals(
                "Sizes: expected sizes A-B with A <= B, found '44-36'.",
                window.label("grading-status").target().getToolTipText());
        assertEquals("36-44", model().job().grading().orElseThrow().sizes());
        shoot("grading-bad-field.png");
        window.textBox(GradingViewModel.SHRINKAGE).deleteText().enterText("0,02");
        // a field that does not read comes first; the grading judges the values once every field reads
        assertEquals(
                "Shrinkage: '0,02' is not a number (decimals take a point: 0.02).",
                window.label("grading-status").target().getToolTipText());
        assertEquals(
                BAD, window.textBox(GradingViewModel.SHRINKAGE).background().target());
        window.textBox(GradingViewModel.SHRINKAGE).deleteText().enterText("0");
        window.textBox(GradingViewModel.SIZES).deleteText().enterText("38-42");
        window.button("grading-grade").requireEnabled();
        window.button("grading-grade").click();
        waitFor(
                "the grading is shown",
                () -> window.table("grading-table").target().getRowCount() == 5);
        window.label("status").requireText("Grading: done");
        assertEquals(0, optionPanes());
    }

    private void shoot(String name) throws java.io.IOException {
        java.awt.image.BufferedImage img =
                GuiActionRunner.execute(() -> TabScreenshotsTest.paint((javax.swing.JFrame) window.target()));
        Files.createDirectories(Path.of("target", "screenshots"));
        javax.imageio.ImageIO.write(
                img, "png", Path.of("target", "screenshots", name).toFile());
    }

    private int optionPanes() {
        return window.robot()
                .finder()
                .findAll(new GenericTypeMatcher<>(javax.swing.JOptionPane.class, true) {
                    @Override
                    protected boolean isMatching(javax.swing.JOptionPane p) {
                        return true;
                    }
                })
                .size();
    }

    private MainViewModel model() {
        return GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
    }

    private void open(String job) {
        GuiActionRunner.execute(() -> ((MainWindow) window.target()).openJob(JOBS.resolve(job)));
    }

    private void waitFor(String what, BooleanSupplier test) {
        Pause.pause(
                new Condition(what) {
                    @Override
                    public boolean test() {
                        return GuiActionRunner.execute(test::getAsBoolean);
                    }
                },
                Timeout.timeout(60_000));
    }
}
