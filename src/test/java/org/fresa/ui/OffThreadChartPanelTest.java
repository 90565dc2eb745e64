package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.awt.image.BufferedImage;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;

/**
 * A plot drawn ahead of its paint for a live answer: a newer change while it is drawn drops it,
 * and its curves are left undrawn, so the drawing thread is free for the newer one.
 */
class OffThreadChartPanelTest {

    @Test
    void aPictureThatBecomesStaleWhileItIsDrawnIsDroppedAndOneStillWantedIsKept() throws Exception {
        TrajectoryCharts t = TrajectoryChartsTest.trajectory(7, 0);
        OffThreadChartPanel.Picture picture = new OffThreadChartPanel.Picture(
                List.of("errors", 7), () -> new TrajectoryCharts.Screen(true).errors(t, 1));
        OffThreadChartPanel panel = onEventThread(() -> {
            OffThreadChartPanel p =
                    new OffThreadChartPanel(new TrajectoryCharts.Screen(false).errors(t, 1), () -> picture);
            p.setSize(430, 420);
            // the first paint gives the size the pictures are drawn ahead at
            BufferedImage img = new BufferedImage(430, 420, BufferedImage.TYPE_INT_RGB);
            p.paint(img.createGraphics());
            return p;
        });
        assertNotNull(drawnAhead(panel, picture, () -> false), "still wanted");
        // wanted when the drawing starts, no longer once the renderer asks (a newer change came)
        AtomicInteger asked = new AtomicInteger();
        assertNull(drawnAhead(panel, picture, () -> asked.incrementAndGet() > 1), "stale");
        // asked before the drawing, by the renderer before each of the three curves, and after
        assertEquals(5, asked.get());
    }

    private static OffThreadChartPanel.Prepared drawnAhead(
            OffThreadChartPanel panel, OffThreadChartPanel.Picture picture, BooleanSupplier stale) throws Exception {
        CompletableFuture<OffThreadChartPanel.Prepared> drawn = new CompletableFuture<>();
        panel.prepare(picture, stale, drawn::complete);
        return drawn.get(60, TimeUnit.SECONDS);
    }

    private static <T> T onEventThread(java.util.concurrent.Callable<T> c) throws Exception {
        CompletableFuture<T> f = new CompletableFuture<>();
        SwingUtilities.invokeAndWait(() -> {
            try {
                f.complete(c.call());
            } catch (Exception e) {
                f.completeExceptionally(e);
            }
        });
        return f.get();
    }
}
