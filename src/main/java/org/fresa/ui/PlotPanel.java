package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.swing.JPanel;
import org.fresa.chart.ChartFiles;
import org.fresa.chart.PlotScene;
import org.fresa.chart.ToolpathChart;
import org.fresa.geom.Box2;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.plot.XYPlot;

/**
 * The plot view shared by all tabs: a {@link PlotScene} drawn with equal scale on both axes,
 * zoom with the mouse wheel or a drag, pan with Ctrl+drag, Home/F to fit, and export as PNG or SVG.
 */
public final class PlotPanel extends JPanel {

    private static final long serialVersionUID = 1L;

    private final OffThreadChartPanel chartPanel;
    private transient PlotScene scene = PlotScene.empty("");
    // counts the scenes shown: the picture's key, cheaper than comparing two big scenes
    private long sceneVersion;
    // set when a fit had to guess the data area because nothing was drawn yet at this size
    private boolean refitWhenDrawn;
    // the event thread's chart holds only the axes: the scene is drawn off the event thread
    private final transient JFreeChart chart = ToolpathChart.create(PlotScene.empty(""));

    public PlotPanel() {
        super(new BorderLayout());
        chartPanel = new OffThreadChartPanel(chart, this::picture);
        chartPanel.setMouseWheelEnabled(true);
        chartPanel.onDrawn(() -> {
            if (refitWhenDrawn) {
                fit();
            }
        });
        chartPanel.setMouseZoomable(true);
        chartPanel.setFocusable(true);
        chartPanel.setName("plot");
        add(chartPanel, BorderLayout.CENTER);
        chartPanel.addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                fit();
            }
        });
        javax.swing.InputMap im = chartPanel.getInputMap(WHEN_FOCUSED);
        im.put(javax.swing.KeyStroke.getKeyStroke("HOME"), "fit");
        im.put(javax.swing.KeyStroke.getKeyStroke("F"), "fit");
        chartPanel.getActionMap().put("fit", new javax.swing.AbstractAction() {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(java.awt.event.ActionEvent e) {
                fit();
            }
        });
    }

    /** The chart component itself: mouse listeners, key bindings and drops of the tabs go here. */
    public javax.swing.JComponent chartComponent() {
        return chartPanel;
    }

    /** A point of the chart component (pixels) as plot coordinates (mm). */
    public org.fresa.geom.Vec2 toPlotMm(java.awt.Point p) {
        java.awt.geom.Point2D j = chartPanel.translateScreenToJava2D(p);
        java.awt.geom.Rectangle2D area = chartPanel.getChartRenderingInfo().getPlotInfo().getDataArea();
        XYPlot xy = chart.getXYPlot();
        return org.fresa.geom.Vec2.of(xy.getDomainAxis().java2DToValue(j.getX(), area, xy.getDomainAxisEdge()),
                xy.getRangeAxis().java2DToValue(j.getY(), area, xy.getRangeAxisEdge()));
    }

    /** A plot point (mm) as a point of the chart component (pixels), e.g. to aim a drop in a test. */
    public java.awt.Point toPixels(org.fresa.geom.Vec2 mm) {
        java.awt.geom.Rectangle2D area = chartPanel.getChartRenderingInfo().getPlotInfo().getDataArea();
        XYPlot xy = chart.getXYPlot();
        double x = xy.getDomainAxis().valueToJava2D(mm.x(), area, xy.getDomainAxisEdge());
        double y = xy.getRangeAxis().valueToJava2D(mm.y(), area, xy.getRangeAxisEdge());
        java.awt.Point j = chartPanel.translateJava2DToScreen(new java.awt.geom.Point2D.Double(x, y));
        return j;
    }

    /** Turns the zoom-by-drag off while a tab drags something on the plot, and back on. */
    public void setDragZoom(boolean on) {
        chartPanel.setMouseZoomable(on);
    }

    public PlotScene scene() {
        return scene;
    }

    /** The scene as it is shown now, to be drawn off the event thread. */
    private OffThreadChartPanel.Picture picture() {
        PlotScene s = scene;
        XYPlot xy = chart.getXYPlot();
        org.jfree.data.Range x = xy.getDomainAxis().getRange();
        org.jfree.data.Range y = xy.getRangeAxis().getRange();
        java.util.List<Object> key = java.util.List.of(sceneVersion, x, y);
        return new OffThreadChartPanel.Picture(key, () -> chartOf(s, x, y));
    }

    private static JFreeChart chartOf(PlotScene s, org.jfree.data.Range x, org.jfree.data.Range y) {
        JFreeChart c = ToolpathChart.create(s);
        c.getXYPlot().getDomainAxis().setRange(x);
        c.getXYPlot().getRangeAxis().setRange(y);
        return c;
    }

    /** Whether what is on screen is the scene and view shown last (tests wait for it). */
    boolean isDrawn() {
        return chartPanel.isUpToDate();
    }

    /** Shows a new scene, fitted to the panel. Call on the event thread. */
    public void show(PlotScene s) {
        this.scene = s;
        sceneVersion++;
        fit();
        chartPanel.repaint();
    }

    /**
     * Shows a new scene keeping the current zoom and pan (a replay step, not a new picture).
     * Call on the event thread.
     */
    public void update(PlotScene s) {
        this.scene = s;
        sceneVersion++;
        chartPanel.repaint();
    }

    /** Fits the scene into the view with equal millimetres per pixel on both axes. */
    public void fit() {
        XYPlot plot = chart.getXYPlot();
        Box2 b = scene.bounds().orElse(new Box2(0, 0, 100, 100));
        java.awt.geom.Rectangle2D area = chartPanel.getScreenDataArea();
        refitWhenDrawn = area.getWidth() <= 10 || area.getHeight() <= 10;
        double w = area.getWidth() > 10 ? area.getWidth() : Math.max(100, getWidth() - 80);
        double h = area.getHeight() > 10 ? area.getHeight() : Math.max(100, getHeight() - 60);
        double pad = 0.05 * Math.max(1e-3, Math.max(b.width(), b.height()));
        double bw = b.width() + 2 * pad;
        double bh = b.height() + 2 * pad;
        double scale = Math.max(bw / w, bh / h);
        double cx = b.center().x();
        double cy = b.center().y();
        plot.getDomainAxis().setRange(cx - scale * w / 2, cx + scale * w / 2);
        plot.getRangeAxis().setRange(cy - scale * h / 2, cy + scale * h / 2);
    }

    /** Writes the current plot as PNG or SVG, chosen by the file's extension. */
    public void export(Path file) throws IOException {
        int w = Math.max(800, chartPanel.getWidth());
        int h = Math.max(600, chartPanel.getHeight());
        XYPlot xy = chart.getXYPlot();
        JFreeChart full = chartOf(scene, xy.getDomainAxis().getRange(), xy.getRangeAxis().getRange());
        try (OutputStream out = Files.newOutputStream(file)) {
            if (file.getFileName().toString().toLowerCase(java.util.Locale.ROOT).endsWith(".svg")) {
                ChartFiles.writeSvg(full, w, h, out);
            } else {
                ChartFiles.writePng(full, w, h, out);
            }
        }
    }
}
