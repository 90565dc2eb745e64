package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import javax.swing.text.Highlighter;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.fresa.job.Job;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.job.JobTask;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.MillingDirection;
import org.fresa.pocket.PocketStrategy;
import org.junit.jupiter.api.Test;

/**
 * The Pocket tab's entry fields and its side of the program check, as a planner uses them: a bad
 * entry angle is marked with its reason and the job keeps the last valid one; a plunge asked for a
 * cutter not said to cut at its centre is computed, its program shown with the failing block
 * marked, the status naming the rule, and Save program refuses it; declared centre-cutting, the
 * same plunge passes and the program is saved. Screenshots in target/screenshots.
 */
class PocketTabGuiTest extends WindowGuiTest {

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

    private void waitFor(String what, java.util.function.Predicate<String> p) {
        Pause.pause(
                new Condition(what) {
                    @Override
                    public boolean test() {
                        return p.test(status());
                    }
                },
                Timeout.timeout(60_000));
    }

    private void shoot(String name) throws Exception {
        java.awt.image.BufferedImage img =
                GuiActionRunner.execute(() -> TabScreenshotsTest.paint((javax.swing.JFrame) window.target()));
        Files.createDirectories(Path.of("target", "screenshots"));
        javax.imageio.ImageIO.write(
                img, "png", Path.of("target", "screenshots", name).toFile());
    }

    @Test
    void aPlungeOfACutterNotCuttingAtItsCentreIsShownRefusedAtItsBlockAndCannotBeSaved() throws Exception {
        MainViewModel model = GuiActionRunner.execute(() -> ((MainWindow) window.target()).model());
        // the thesis's cavity 01 opened as a job (samples/pocket/jobs.csv), on the thesis's 7M post
        GuiActionRunner.execute(() -> model.setJob(Job.empty(JobTask.POCKET)
                .withPocket(new PocketSettings(
                        Path.of("samples/pocket/cavity01.dad").toAbsolutePath(),
                        6,
                        0.62,
                        0.13,
                        30,
                        27,
                        3,
                        3200,
                        290,
                        100,
                        org.fresa.post.PocketPost.SINUMERIK_7M_COMPAT,
                        MillingDirection.CLIMB,
                        EntryRule.Kind.AUTO,
                        EntryRule.DEFAULT_ANGLE_DEG,
                        false,
                        Optional.empty(),
                        PocketStrategy.DEFAULT))));
        window.tabbedPane("tabs").selectTab("Pocket");
        window.comboBox(PocketViewModel.ENTRY).requireSelection("auto");
        window.textBox(PocketViewModel.ENTRY_ANGLE).requireText("3");
        window.checkBox(PocketViewModel.CENTRE_CUTTING).requireNotSelected();

        // a typo in the entry angle: the field is marked with the reason, the job keeps 3 degrees
        window.textBox(PocketViewModel.ENTRY_ANGLE).deleteText().enterText("0,2");
        waitFor("the bad angle is explained", s -> s.contains("Entry angle (deg)"));
        assertTrue(status().contains("decimals take a point"), status());
        assertEquals(
                new java.awt.Color(255, 220, 220),
                GuiActionRunner.execute(() ->
                        window.textBox(PocketViewModel.ENTRY_ANGLE).target().getBackground()));
        assertTrue(GuiActionRunner.execute(() ->
                        window.textBox(PocketViewModel.ENTRY_ANGLE).target().getToolTipText())
                .contains("not a number"));
        window.button("pocket-compute").requireDisabled();
        assertEquals(
                3,
                GuiActionRunner.execute(() -> model.job().pocket().orElseThrow().entryAngleDeg()));
        window.textBox(PocketViewModel.ENTRY_ANGLE).deleteText().enterText("3");
        window.button("pocket-compute").requireEnabled();

        // G-code, straight down, the cutter left as one that does not cut at its centre
        window.comboBox("pocket-post").selectItem("linuxcnc");
        window.comboBox(PocketViewModel.ENTRY).selectItem("plunge");
        window.button("pocket-compute").click();
        waitFor("the program is computed", s -> s.contains("refused") || s.equals("done"));
        String refused = status();
        assertTrue(refused.startsWith("The program is refused and not written:"), refused);
        assertTrue(
                refused.contains("entry angle")
                        && refused.contains("(a plunge)")
                        && refused.contains("a cutter not cutting at its centre"),
                refused);
        // the failing block is marked in the program, which is in front
        assertEquals("NC program", GuiActionRunner.execute(() -> {
            javax.swing.JTabbedPane texts = window.tabbedPane("pocket-texts").target();
            return texts.getTitleAt(texts.getSelectedIndex());
        }));
        Highlighter.Highlight[] marked = GuiActionRunner.execute(
                () -> window.textBox("pocket-nc").target().getHighlighter().getHighlights());
        assertEquals(1, marked.length);
        String block = GuiActionRunner.execute(() -> {
            javax.swing.JTextArea t =
                    (javax.swing.JTextArea) window.textBox("pocket-nc").target();
            return t.getText()
                    .substring(marked[0].getStartOffset(), Math.min(t.getText().length(), marked[0].getEndOffset()))
                    .strip();
        });
        java.util.regex.Matcher n =
                java.util.regex.Pattern.compile("line (\\d+)").matcher(refused);
        assertTrue(n.find(), refused);
        assertTrue(refused.contains(block), block + " / " + refused);
        assertTrue(block.startsWith("G1") && block.contains("Z"), block);
        window.label("status").requireText("Pocket program check (entry angle): failed");
        Pause.pause(1500); // the plot is drawn off the event thread
        shoot("pocket-refused-plunge.png");

        // Save program refuses it, without asking for a file
        window.button("pocket-save-program").click();
        waitFor("the save is refused", s -> s.startsWith("The program is not saved"));
        assertTrue(status().contains("entry angle"), status());
        shoot("pocket-refused-save.png");

        // declared centre-cutting, the same plunge is allowed: the program passes and may be saved
        window.checkBox(PocketViewModel.CENTRE_CUTTING).check();
        window.button("pocket-compute").click();
        waitFor("the program is computed", s -> s.equals("done") || s.contains("refused"));
        assertEquals("done", status());
        assertEquals(
                0,
                GuiActionRunner.execute(() ->
                        window.textBox("pocket-nc").target().getHighlighter().getHighlights().length));
        PocketSettings job = GuiActionRunner.execute(() -> model.job().pocket().orElseThrow());
        assertTrue(
                job.centreCutting()
                        && job.entry() == org.fresa.pocket.EntryRule.Kind.PLUNGE
                        && job.post() == org.fresa.post.PocketPost.LINUXCNC,
                job.toString());
        Path saved = dir.resolve("cavity01.ngc");
        window.button("pocket-save-program").click();
        org.assertj.swing.fixture.JFileChooserFixture chooser = window.fileChooser(Timeout.timeout(10_000));
        WindowGuiTest.choose(chooser, saved);
        waitFor("the program is saved", s -> s.startsWith("Saved "));
        assertTrue(Files.readString(saved).contains("M3"));
        assertFalse(Files.list(dir).anyMatch(p -> p.getFileName().toString().startsWith(".fresa-tmp-")));
        shoot("pocket-centre-cutting-plunge.png");
    }
}
