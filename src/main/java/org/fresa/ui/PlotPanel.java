package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.awt.Insets;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.geom.Rectangle2D;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JPanel;
import org.fresa.chart.ChartFiles;
import org.fresa.chart.EqualScale;
import org.fresa.chart.PlotScene;
import org.fresa.chart.ToolpathChart;
import org.fresa.geom.Box2;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.event.PlotChangeListener;
import org.jfree.chart.plot.XYPlot;
import org.jfree.data.Range;

/**
 * The plot view shared by all tabs: a {@link PlotScene} drawn with equal scale on both axes,
 * kept through every zoom, Auto Range and resize; zoom with the mouse wheel or a drag, pan with
 * Ctrl+drag, Home/F or the Fit button to fit, and export as PNG or SVG at equal scale.
 */
public final class PlotPanel extends JPanel {

    private static final long serialVersionUID = 1L;

    private final OffThreadChartPanel chartPanel;
    private transient PlotScene scene = PlotScene.empty("");
    // counts the scenes shown: the picture's key, cheaper than comparing two big scenes
    private long sceneVersion;
    // the event thread's chart holds only the frame (title, axes, legend, extent): the scene is
    // drawn off the event thread into a chart laid out the same
    private transient JFreeChart chart = ToolpathChart.frame(scene);
    private transient PlotChangeListener keepEqual = e -> keepEqualScale();
    private boolean equalizing;
    // the data area measured for the chart and panel size it was measured at
    private transient Object measuredKey;
    private transient Rectangle2D measured;

    public PlotPanel() {
        super(new BorderLayout());
        chartPanel = new OffThreadChartPanel(chart, this::picture);
        chartPanel.setMouseWheelEnabled(true);
        chartPanel.setMouseZoomable(true);
        chartPanel.setFocusable(true);
        chartPanel.setName("plot");
        chart.getXYPlot().addChangeListener(keepEqual);
        add(chartPanel, BorderLayout.CENTER);
        JButton fitButton = new JButton("Fit");
        fitButton.setName("fitPlot");
        fitButton.setToolTipText("Show the whole drawing at equal scale on both axes (Home, or F, in the plot)");
        fitButton.setMargin(new Insets(1, 8, 1, 8));
        fitButton.setFocusable(false);
        fitButton.addActionListener(e -> fit());
        JLabel hint = new JLabel("wheel: zoom, drag: zoom to the box, Ctrl+drag: pan, right click: menu");
        hint.setForeground(java.awt.Color.GRAY);
        JPanel bar = new JPanel(new FlowLayout(FlowLayout.RIGHT, 6, 1));
        bar.add(hint);
        bar.add(fitButton);
        add(bar, BorderLayout.NORTH);
        chartPanel.addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                fit();
            }
        });
        // a click in the plot takes the keyboard, so that Home fits right after it
        chartPanel.addMouseListener(new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                chartPanel.requestFocusInWindow();
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
        Rectangle2D area = chartPanel.getChartRenderingInfo().getPlotInfo().getDataArea();
        XYPlot xy = chart.getXYPlot();
        return org.fresa.geom.Vec2.of(
                xy.getDomainAxis().java2DToValue(j.getX(), area, xy.getDomainAxisEdge()),
                xy.getRangeAxis().java2DToValue(j.getY(), area, xy.getRangeAxisEdge()));
    }

    /** A plot point (mm) as a point of the chart component (pixels), e.g. to aim a drop in a test. */
    public java.awt.Point toPixels(org.fresa.geom.Vec2 mm) {
        Rectangle2D area = chartPanel.getChartRenderingInfo().getPlotInfo().getDataArea();
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

    /** The part of the plane in view: x and y ranges (mm) of the event thread's chart. */
    Box2 view() {
        XYPlot xy = chart.getXYPlot();
        Range x = xy.getDomainAxis().getRange();
        Range y = xy.getRangeAxis().getRange();
        return new Box2(x.getLowerBound(), y.getLowerBound(), x.getUpperBound(), y.getUpperBound());
    }

    /**
     * Millimetres per pixel along x over those along y in the picture on screen (1 at equal
     * scale), from the data area the last image was drawn with.
     */
    double shownAspect() {
        Rectangle2D area = chartPanel.getChartRenderingInfo().getPlotInfo().getDataArea();
        return EqualScale.aspect(chart.getXYPlot(), area);
    }

    /** The scene as it is shown now, to be drawn off the event thread. */
    private OffThreadChartPanel.Picture picture() {
        PlotScene s = scene;
        XYPlot xy = chart.getXYPlot();
        Range x = xy.getDomainAxis().getRange();
        Range y = xy.getRangeAxis().getRange();
        java.util.List<Object> key = java.util.List.of(sceneVersion, x, y);
        return new OffThreadChartPanel.Picture(key, () -> chartOf(s, x, y));
    }

    private static JFreeChart chartOf(PlotScene s, Range x, Range y) {
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
        newFrame(s);
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
        newFrame(s);
        chartPanel.repaint();
    }

    /** The event thread's chart for a new scene (title, axes, legend), at the view shown now. */
    private void newFrame(PlotScene s) {
        JFreeChart old = chart;
        Range x = old.getXYPlot().getDomainAxis().getRange();
        Range y = old.getXYPlot().getRangeAxis().getRange();
        old.getXYPlot().removeChangeListener(keepEqual);
        chart = ToolpathChart.frame(s);
        XYPlot plot = chart.getXYPlot();
        plot.getDomainAxis().setRange(x);
        plot.getRangeAxis().setRange(y);
        plot.addChangeListener(keepEqual);
        chartPanel.setChart(chart);
    }

    /**
     * Centres the view on a place of the scene, showing at least sizeMm around it at equal scale
     * (a warning's place). Call on the event thread.
     */
    public void showPlace(org.fresa.geom.Vec2 at, double sizeMm) {
        double h = Math.max(1e-3, sizeMm) / 2;
        Box2 b = new Box2(at.x() - h, at.y() - h, at.x() + h, at.y() + h);
        dataArea().ifPresent(area -> EqualScale.fit(chart.getXYPlot(), b, area));
    }

    /** Fits the scene into the view with equal millimetres per pixel on both axes. */
    public void fit() {
        Box2 b = scene.bounds().orElse(new Box2(0, 0, 100, 100));
        dataArea().ifPresent(area -> EqualScale.fit(chart.getXYPlot(), b, area));
    }

    /**
     * After any change of the view (a drag zoom, Auto Range of the plot's menu, a zoom of one
     * axis), widens one axis so that both show the same millimetres per pixel.
     */
    private void keepEqualScale() {
        if (equalizing) {
            return;
        }
        equalizing = true;
        try {
            dataArea().ifPresent(area -> EqualScale.equalize(chart.getXYPlot(), area));
        } finally {
            equalizing = false;
        }
    }

    /**
     * The data area the chart gets at the panel's present size, measured rather than taken from
     * the last image: after a resize the image of the new size is not drawn yet.
     */
    private java.util.Optional<Rectangle2D> dataArea() {
        Insets in = chartPanel.getInsets();
        int w = Math.min(8000, chartPanel.getWidth() - in.left - in.right);
        int h = Math.min(6000, chartPanel.getHeight() - in.top - in.bottom);
        if (w <= 10 || h <= 10) {
            // not laid out yet: the first resize fits
            return java.util.Optional.empty();
        }
        Object key = java.util.List.of(System.identityHashCode(chart), w, h);
        if (!key.equals(measuredKey)) {
            measured = EqualScale.dataArea(chart, w, h);
            measuredKey = key;
        }
        return measured.getWidth() > 1 && measured.getHeight() > 1
                ? java.util.Optional.of(measured)
                : java.util.Optional.empty();
    }

    /**
     * Writes the current plot as PNG or SVG, chosen by the file's extension, at equal scale: the
     * view on screen, its centre kept, one axis widened to the file's proportions.
     */
    public void export(Path file) throws IOException {
        int w = Math.max(800, chartPanel.getWidth());
        int h = Math.max(600, chartPanel.getHeight());
        XYPlot xy = chart.getXYPlot();
        JFreeChart full =
                chartOf(scene, xy.getDomainAxis().getRange(), xy.getRangeAxis().getRange());
        EqualScale.prepare(full, java.util.Optional.empty(), w, h);
        try (OutputStream out = Files.newOutputStream(file)) {
            if (file.getFileName().toString().toLowerCase(java.util.Locale.ROOT).endsWith(".svg")) {
                ChartFiles.writeSvg(full, w, h, out);
            } else {
                ChartFiles.writePng(full, w, h, out);
            }
        }
    }
}
