package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.GraphicsEnvironment;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JTable;
import javax.swing.SwingUtilities;
import org.fresa.job.JobSettings.GradingSettings;
import org.fresa.job.JobTask;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The Grading tab on a (virtual) screen: a job's settings fill it, Grade fills the table. */
class GradingTabTest {

    @TempDir
    Path dir;

    @Test
    void gradeFillsTheTableForTheJobsSizes() throws Exception {
        Assumptions.assumeFalse(GraphicsEnvironment.isHeadless(), "needs a display (xvfb-run)");
        AtomicReference<GradingTab> tab = new AtomicReference<>();
        AtomicReference<JFrame> frame = new AtomicReference<>();
        MainViewModel model = new MainViewModel(new RecentJobs(dir.resolve("recent.txt")));
        SwingUtilities.invokeAndWait(() -> {
            JFrame f = new JFrame("test");
            StatusBar bar = new StatusBar();
            AppContext ctx = new AppContext(model, new BackgroundTasks(bar, f), f);
            GradingTab t = new GradingTab(ctx);
            f.add(t.component());
            f.setSize(1200, 800);
            f.setVisible(true);
            model.setJob(model.job()
                    .withTask(JobTask.GRADE)
                    .withGrading(new GradingSettings(
                            Path.of("samples/grading/sole-40.contour").toAbsolutePath(),
                            40,
                            "38-42",
                            false,
                            org.fresa.grading.SizeSystem.BR,
                            java.util.OptionalDouble.empty(),
                            java.util.OptionalDouble.empty(),
                            java.util.Optional.empty(),
                            0,
                            org.fresa.grading.ShrinkageMode.MULTIPLICATIVE)));
            tab.set(t);
            frame.set(f);
        });
        SwingUtilities.invokeAndWait(() ->
                find(tab.get().component(), JButton.class, "grading-grade").doClick());
        JTable table = find(tab.get().component(), JTable.class, "grading-table");
        for (int i = 0; i < 200 && table.getRowCount() == 0; i++) {
            Thread.sleep(50);
        }
        assertEquals(5, table.getRowCount());
        assertEquals("38", table.getValueAt(0, 0));
        assertTrue(tab.get().plot().isPresent());
        SwingUtilities.invokeAndWait(() -> {
            BufferedImage img = new BufferedImage(1200, 800, BufferedImage.TYPE_INT_RGB);
            frame.get().getContentPane().paint(img.getGraphics());
            try {
                javax.imageio.ImageIO.write(img, "png", dir.resolve("tab.png").toFile());
                if (System.getenv("FRESA_SCREENSHOT") != null) {
                    javax.imageio.ImageIO.write(img, "png", new java.io.File(System.getenv("FRESA_SCREENSHOT")));
                }
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
            frame.get().dispose();
        });
    }

    private static <T extends java.awt.Component> T find(java.awt.Container c, Class<T> type, String name) {
        for (java.awt.Component k : c.getComponents()) {
            if (type.isInstance(k) && name.equals(k.getName())) {
                return type.cast(k);
            }
            if (k instanceof java.awt.Container sub) {
                T t = find(sub, type, name);
                if (t != null) {
                    return t;
                }
            }
        }
        return null;
    }
}
