package org.fresa.ui;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import java.util.function.Supplier;
import javax.swing.SwingUtilities;
import org.jfree.chart.ChartPanel;
import org.jfree.chart.ChartRenderingInfo;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.plot.PlotRenderingInfo;

/**
 * A chart panel whose chart is drawn off the event thread into an image, which the event thread
 * then only copies: drawing a big toolpath or many joint curves takes far longer than the 50 ms an
 * event may take. The picture is described by a {@link Picture} taken on the event
 * thread at paint time; a picture that has changed is drawn again in the background while the
 * previous image stays on screen. The chart the panel holds is the event thread's: zoom, pan and
 * the pixel-to-value mapping work on it as in any chart panel, with the data area of the image.
 */
final class OffThreadChartPanel extends ChartPanel {

    /**
     * The chart's own tooltips (its entities), else the text a tab set for the place under the
     * mouse (a contour not cut and its reason): ChartPanel alone ignores the latter.
     */
    @Override
    public String getToolTipText(java.awt.event.MouseEvent e) {
        String own = super.getToolTipText(e);
        return own != null ? own : getToolTipText();
    }

    private static final long serialVersionUID = 1L;

    /** What to draw: a chart built from values captured on the event thread, and their identity. */
    /**
     * @param key equal for two pictures that look the same (the scene, the axis ranges, the markers)
     * @param builder makes a new chart of the picture; runs on the drawing thread, so it must touch
     *     no shared state
     */
    record Picture(Object key, Supplier<JFreeChart> builder) {
        JFreeChart build() {
            return builder.get();
        }
    }

    // one thread for all panels: drawing is CPU work and the machine may have two cores
    private static final ExecutorService DRAWING = BackgroundThreads.single("fresa-plot-drawing");

    // whether the picture the drawing thread draws ahead is no longer wanted (unset: it is)
    private static final ThreadLocal<BooleanSupplier> ABANDONED = new ThreadLocal<>();

    /**
     * Whether the picture being drawn ahead on this thread is no longer wanted ({@link #prepare}'s
     * stale): a renderer may then leave the rest of it undrawn, as it is dropped. False elsewhere.
     */
    static boolean drawingAbandoned() {
        BooleanSupplier s = ABANDONED.get();
        return s != null && s.getAsBoolean();
    }

    private final transient Supplier<Picture> picture;
    private transient BufferedImage image;
    private transient Object imageKey;
    private transient volatile Object pendingKey;
    // the frame ChartPanel copies to the screen, when the last image has another size than the panel
    private transient BufferedImage frame;
    private transient Runnable onDrawn = () -> {};
    private transient Drawn lastDrawn;
    private String placeholder;
    // the size of the image the last paint asked for: that of an image drawn ahead of its paint
    private transient volatile Size lastSize;

    /**
     * When (System.nanoTime) the last image's steps ended, and the drawing thread's CPU time (ns,
     * -1 where the JVM does not count it): asked at a paint, taken up by the drawing thread, the
     * chart built, the image drawn, shown on the event thread.
     */
    record Drawn(long asked, long started, long built, long drawn, long shown, long buildCpuNanos, long drawCpuNanos) {}

    /** The chart size (pixels) and screen scale an image is drawn at. */
    private record Size(int width, int height, double scale) {}

    /** An image drawn on the drawing thread, with the areas of the chart in it and its times. */
    private record Rendered(
            BufferedImage image,
            ChartRenderingInfo info,
            long started,
            long built,
            long drawn,
            long buildCpuNanos,
            long drawCpuNanos) {}

    /**
     * A picture drawn ahead of the paint that shows it ({@link #prepare}), to be given to the
     * panel with {@link #install} on the event thread.
     */
    static final class Prepared {
        private final Object key;
        private final Rendered rendered;
        private final long asked;

        private Prepared(Object key, Rendered rendered, long asked) {
            this.key = key;
            this.rendered = rendered;
            this.asked = asked;
        }
    }

    /** picture is asked on the event thread at every paint; null means nothing to draw. */
    OffThreadChartPanel(JFreeChart chart, Supplier<Picture> picture) {
        // the off-screen buffer is on: ChartPanel asks paintChartToBuffer for it, which this class
        // answers with the image drawn in the background
        super(chart, DEFAULT_WIDTH, DEFAULT_HEIGHT, 10, 10, 8000, 6000, true, false, false, false, true, false);
        this.picture = picture;
    }

    @Override
    public void paintComponent(Graphics g) {
        super.paintComponent(g);
        if (getChart() == null && placeholder != null) {
            g.setColor(Color.GRAY);
            g.drawString(placeholder, 16, 30);
        }
    }

    /**
     * Called by ChartPanel's paint on the event thread instead of drawing the chart there: asks
     * for the picture of the moment to be drawn in the background if it has changed, and gives
     * the last image drawn. ChartPanel copies it to the screen and draws the zoom rectangle on it.
     */
    @Override
    protected BufferedImage paintChartToBuffer(
            Graphics2D g2, Dimension bufferSize, Dimension chartSize, Point2D anchor, ChartRenderingInfo info) {
        int w = chartSize.width;
        int h = chartSize.height;
        double scale = g2.getTransform().getScaleX();
        lastSize = new Size(w, h, scale);
        Picture p = picture.get();
        if (p != null) {
            Object key = List.of(p.key(), w, h, scale);
            if (!key.equals(imageKey) && !key.equals(pendingKey)) {
                pendingKey = key;
                long asked = System.nanoTime();
                DRAWING.execute(() -> draw(p, key, w, h, scale, asked));
            }
        }
        if (image != null && image.getWidth() == bufferSize.width && image.getHeight() == bufferSize.height) {
            return image;
        }
        // an older image of another size is shown cropped or padded, copied 1:1, until the new one
        // is drawn: a scaled copy of a large image took 95 ms on the event thread (Xvfb)
        if (frame == null || frame.getWidth() != bufferSize.width || frame.getHeight() != bufferSize.height) {
            frame = new BufferedImage(
                    Math.max(1, bufferSize.width), Math.max(1, bufferSize.height), BufferedImage.TYPE_INT_RGB);
        }
        Graphics2D f = frame.createGraphics();
        f.setColor(Color.WHITE);
        f.fillRect(0, 0, frame.getWidth(), frame.getHeight());
        if (image != null) {
            f.drawImage(image, 0, 0, null);
        }
        f.dispose();
        return frame;
    }

    /** Runs on the drawing thread. */
    private void draw(Picture p, Object key, int w, int h, double scale, long asked) {
        if (!key.equals(pendingKey)) {
            // a newer picture was asked for while this one waited
            return;
        }
        Rendered r = render(p, w, h, scale);
        SwingUtilities.invokeLater(() -> show(r.image(), key, r.info(), drawn(r, asked)));
    }

    /** Builds the picture's chart and draws it into an image of w x h at the scale (drawing thread). */
    private static Rendered render(Picture p, int w, int h, double scale) {
        long started = System.nanoTime();
        long cpu0 = LiveReachability.cpuNanos();
        JFreeChart c = p.build();
        long built = System.nanoTime();
        long cpu1 = LiveReachability.cpuNanos();
        int iw = (int) Math.ceil(w * scale);
        int ih = (int) Math.ceil(h * scale);
        BufferedImage img = new BufferedImage(iw, ih, BufferedImage.TYPE_INT_RGB);
        Graphics2D g2 = img.createGraphics();
        g2.setColor(Color.WHITE);
        g2.fillRect(0, 0, iw, ih);
        g2.scale(scale, scale);
        // no entity collection: the panel has no tooltips, and one entity per item costs time
        ChartRenderingInfo info = new ChartRenderingInfo(null);
        c.draw(g2, new Rectangle2D.Double(0, 0, w, h), null, info);
        g2.dispose();
        long drawn = System.nanoTime();
        long cpu2 = LiveReachability.cpuNanos();
        return new Rendered(img, info, started, built, drawn, cpu0 < 0 ? -1 : cpu1 - cpu0, cpu0 < 0 ? -1 : cpu2 - cpu1);
    }

    private static Drawn drawn(Rendered r, long asked) {
        return new Drawn(
                asked, r.started(), r.built(), r.drawn(), System.nanoTime(), r.buildCpuNanos(), r.drawCpuNanos());
    }

    /**
     * Draws a picture on the drawing thread at the size of the panel's last paint, before the
     * event thread shows it: while the event thread paints something else, the picture is made,
     * and its own paint then only copies it. Then runs on the event thread with the image, or
     * with null when the panel has not been painted yet (its first paint draws the picture) or
     * when {@code stale} says, before or after the drawing, that it is no longer wanted (the
     * drawing stops early then). Any thread.
     */
    void prepare(Picture p, BooleanSupplier stale, Consumer<Prepared> then) {
        long asked = System.nanoTime();
        Size s = lastSize;
        if (s == null) {
            SwingUtilities.invokeLater(() -> then.accept(null));
            return;
        }
        DRAWING.execute(() -> {
            Prepared d = null;
            if (!stale.getAsBoolean()) {
                // a newer change makes the curves not yet drawn stop (ThinLineRenderer asks):
                // the drawing thread is free for the newer picture sooner
                ABANDONED.set(stale);
                try {
                    Rendered r = render(p, s.width(), s.height(), s.scale());
                    d = stale.getAsBoolean()
                            ? null
                            : new Prepared(List.of(p.key(), s.width(), s.height(), s.scale()), r, asked);
                } finally {
                    ABANDONED.remove();
                }
            }
            Prepared drawn = d;
            SwingUtilities.invokeLater(() -> then.accept(drawn));
        });
    }

    /**
     * Takes an image drawn ahead ({@link #prepare}) as the panel's (event thread): its next paint
     * copies it when it shows the picture drawn and the panel has kept its size, else it draws anew.
     */
    void install(Prepared d) {
        Rendered r = d.rendered;
        if (d.key.equals(pendingKey)) {
            pendingKey = null;
        }
        take(r.image(), d.key, r.info(), drawn(r, d.asked));
        repaint();
    }

    private void show(BufferedImage img, Object key, ChartRenderingInfo drawn, Drawn times) {
        if (!key.equals(pendingKey) && isUpToDate()) {
            // an older picture, drawn while the one on screen was installed ahead of it
            return;
        }
        if (key.equals(pendingKey)) {
            pendingKey = null;
        }
        take(img, key, drawn, times);
        repaint();
        onDrawn.run();
    }

    /** The image on screen, and the chart and data areas of it, for the zoom and the pixel-to-value mapping. */
    private void take(BufferedImage img, Object key, ChartRenderingInfo drawn, Drawn times) {
        lastDrawn = times;
        image = img;
        imageKey = key;
        ChartRenderingInfo mine = getChartRenderingInfo();
        mine.clear();
        mine.setChartArea(drawn.getChartArea());
        PlotRenderingInfo pi = mine.getPlotInfo();
        pi.setPlotArea(drawn.getPlotInfo().getPlotArea());
        pi.setDataArea(drawn.getPlotInfo().getDataArea());
        for (int i = 0; i < drawn.getPlotInfo().getSubplotCount(); i++) {
            PlotRenderingInfo sub = new PlotRenderingInfo(mine);
            sub.setPlotArea(drawn.getPlotInfo().getSubplotInfo(i).getPlotArea());
            sub.setDataArea(drawn.getPlotInfo().getSubplotInfo(i).getDataArea());
            pi.addSubplotInfo(sub);
        }
    }

    /** The times of the image on screen, or null before the first (tests and the timing log read them). */
    Drawn lastDrawn() {
        return lastDrawn;
    }

    /** A grey line of text shown while there is no chart. */
    void setPlaceholder(String text) {
        placeholder = text;
    }

    /** Runs on the event thread after each image arrives (its data area is then known). */
    void onDrawn(Runnable r) {
        onDrawn = r;
    }

    /** Whether the image on screen is the picture the panel shows now (tests wait for it). */
    boolean isUpToDate() {
        Picture p = getChart() == null ? null : picture.get();
        return p == null
                || image != null && imageKey instanceof List<?> k && k.get(0).equals(p.key()) && pendingKey == null;
    }
}
