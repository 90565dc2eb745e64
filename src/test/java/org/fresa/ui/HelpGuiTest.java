package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Component;
import java.awt.Container;
import java.util.ArrayList;
import java.util.List;
import javax.swing.AbstractButton;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JSlider;
import javax.swing.JSpinner;
import javax.swing.JTabbedPane;
import javax.swing.JTable;
import javax.swing.JToggleButton;
import javax.swing.text.JTextComponent;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.DialogFixture;
import org.junit.jupiter.api.Test;

/** Help in the main window: F1 opens the user guide; every input of every tab says what it means. */
class HelpGuiTest extends WindowGuiTest {

    @Test
    void f1OpensTheUserGuideInTheWindow() {
        window.tabbedPane("tabs").selectTab("Cutting");
        window.pressAndReleaseKeys(java.awt.event.KeyEvent.VK_F1);
        DialogFixture guide = window.dialog("user-guide");
        guide.requireVisible();
        String text = GuiActionRunner.execute(() -> {
            javax.swing.JEditorPane p =
                    (javax.swing.JEditorPane) guide.robot().finder().findByName(guide.target(), "user-guide-text");
            return p.getDocument().getText(0, p.getDocument().getLength());
        });
        assertTrue(text.contains("Every plot keeps the same scale on both axes"), text);
        java.awt.image.BufferedImage img = GuiActionRunner.execute(() -> {
            javax.swing.JRootPane root = ((javax.swing.JDialog) guide.target()).getRootPane();
            java.awt.image.BufferedImage i = new java.awt.image.BufferedImage(
                    root.getWidth(), root.getHeight(), java.awt.image.BufferedImage.TYPE_INT_RGB);
            java.awt.Graphics2D g = i.createGraphics();
            root.printAll(g);
            g.dispose();
            return i;
        });
        try {
            java.nio.file.Files.createDirectories(java.nio.file.Path.of("target", "screenshots"));
            javax.imageio.ImageIO.write(
                    img,
                    "png",
                    java.nio.file.Path.of("target", "screenshots", "help-user-guide.png")
                            .toFile());
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
        guide.pressAndReleaseKeys(java.awt.event.KeyEvent.VK_ESCAPE);
        guide.requireNotVisible();
    }

    @Test
    void everyInputOfEveryTabHasATooltip() {
        // a real job, so that the tabs have validated and filled their fields
        GuiActionRunner.execute(() -> ((MainWindow) window.target())
                .openJob(java.nio.file.Path.of("samples/jobs/example2-irb140.xml")
                        .toAbsolutePath()));
        window.robot().waitForIdle();
        List<String> missing = GuiActionRunner.execute(() -> {
            JTabbedPane tabs = ((MainWindow) window.target()).tabs();
            List<String> out = new ArrayList<>();
            for (int i = 0; i < tabs.getTabCount(); i++) {
                collect(tabs.getTitleAt(i), tabs.getComponentAt(i), out);
            }
            return out;
        });
        assertEquals(List.of(), missing, missing.size() + " inputs without a tooltip");
    }

    /** The inputs (fields, lists to choose from, boxes, spinners, sliders, tables) without a tooltip. */
    private static void collect(String tab, Component c, List<String> out) {
        boolean input = c instanceof JTextComponent t && t.isEditable()
                || c instanceof JComboBox<?>
                || c instanceof JSpinner
                || c instanceof JSlider
                || c instanceof JToggleButton
                || c instanceof JTable;
        // a table says what it holds on its header (its cells give their own problems)
        JComponent said = c instanceof JTable t && t.getTableHeader() != null
                ? t.getTableHeader()
                : c instanceof JComponent j ? j : null;
        if (input
                && said != null
                && (said.getToolTipText() == null || said.getToolTipText().isBlank())) {
            String label = c instanceof AbstractButton b ? b.getText() : "";
            out.add(tab + ": " + c.getClass().getSimpleName() + " " + c.getName() + " " + label);
        }
        // a spinner's or combo box's own editor field is part of it, not another input
        if (c instanceof Container k
                && !(c instanceof JSpinner)
                && !(c instanceof JComboBox<?>)
                && !(c instanceof JTable)) {
            for (Component child : k.getComponents()) {
                collect(tab, child, out);
            }
        }
    }
}
