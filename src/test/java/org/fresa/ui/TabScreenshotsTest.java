package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.awt.GraphicsEnvironment;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Renders every tab of the main window to target/screenshots/NN-tab.png, so that what the planner
 * sees can be looked at after each build (and the README's screenshot refreshed from it).
 */
class TabScreenshotsTest {

    @TempDir
    Path home;

    @Test
    void everyTabRendersToAPicture() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under xvfb-run");
        Path out = Path.of("target", "screenshots");
        Files.createDirectories(out);
        MainWindow[] holder = new MainWindow[1];
        SwingUtilities.invokeAndWait(() -> {
            holder[0] = FresaApp.create(new RecentJobs(home.resolve("recent.txt")));
            holder[0].setVisible(true);
            // a real job, so that the tabs show what a planner sees, not empty forms
            holder[0].openJob(Path.of("samples/jobs/example2-irb140.xml").toAbsolutePath());
        });
        Thread.sleep(3000);
        MainWindow w = holder[0];
        try {
            for (int i = 0; i < w.tabCount(); i++) {
                int index = i;
                BufferedImage[] img = new BufferedImage[1];
                SwingUtilities.invokeAndWait(() -> w.tabs().setSelectedIndex(index));
                Thread.sleep(300);
                SwingUtilities.invokeAndWait(() -> img[0] = paint(w));
                String name = w.tabs()
                        .getTitleAt(i)
                        .toLowerCase(java.util.Locale.ROOT)
                        .replaceAll("[^a-z0-9]+", "-");
                Path file = out.resolve(String.format(java.util.Locale.ROOT, "%02d-%s.png", i + 1, name));
                ImageIO.write(img[0], "png", file.toFile());
                assertTrue(Files.size(file) > 1000, file.toString());
            }
        } finally {
            SwingUtilities.invokeAndWait(w::dispose);
        }
    }

    static BufferedImage paint(JFrame f) {
        java.awt.Container root = f.getRootPane();
        BufferedImage img = new BufferedImage(root.getWidth(), root.getHeight(), BufferedImage.TYPE_INT_RGB);
        java.awt.Graphics2D g = img.createGraphics();
        root.printAll(g);
        g.dispose();
        return img;
    }
}
