package org.fresa.chart;

import java.awt.Graphics2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.Optional;
import org.fresa.geom.Box2;
import org.jfree.chart.ChartRenderingInfo;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.plot.XYPlot;
import org.jfree.data.Range;

/**
 * Axis ranges with the same millimetres per pixel on both axes of an XY plot, so that a round tool
 * is drawn round: a fit of the data into a data area, and the widening of one axis after a zoom
 * that stretched the view. Works on any chart whose plot is an {@link XYPlot}; the data area is
 * measured by laying the chart out at the size it will be drawn (title, legend and axis labels
 * take their room first).
 */
public final class EqualScale {

    /** The margin around fitted data, as a fraction of the larger side of the data's box. */
    public static final double FIT_MARGIN = 0.05;

    private EqualScale() {}

    /**
     * The data area (pixels, in the chart's drawing space) that drawing the chart at this size
     * gives. Lays the chart out into a throw-away 1 x 1 image; cheap for a chart without its
     * scene's shapes, and the shapes do not change the layout.
     */
    public static Rectangle2D dataArea(JFreeChart chart, double widthPx, double heightPx) {
        BufferedImage scratch = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = scratch.createGraphics();
        try {
            g.setClip(0, 0, 1, 1);
            ChartRenderingInfo info = new ChartRenderingInfo(null);
            chart.draw(g, new Rectangle2D.Double(0, 0, widthPx, heightPx), null, info);
            return info.getPlotInfo().getDataArea();
        } finally {
            g.dispose();
        }
    }

    /**
     * Sets both axes so that the box, with a margin of {@link #FIT_MARGIN}, fills the data area
     * along one axis and is centred along the other, at equal millimetres per pixel. A box of zero
     * size is shown with a view of 1 mm around it.
     */
    public static void fit(XYPlot plot, Box2 box, Rectangle2D dataArea) {
        double w = Math.max(1, dataArea.getWidth());
        double h = Math.max(1, dataArea.getHeight());
        double pad = FIT_MARGIN * Math.max(1e-3, Math.max(box.width(), box.height()));
        double mmPerPx = Math.max((box.width() + 2 * pad) / w, (box.height() + 2 * pad) / h);
        set(plot, box.center().x(), box.center().y(), mmPerPx, w, h);
    }

    /**
     * Widens the axis that shows fewer millimetres per pixel about its centre until both axes show
     * the same: everything that was in view stays in view (a drag zoom over a long thin rectangle
     * shows at least the rectangle). Leaves the plot untouched when the scales already agree
     * within a part in a million.
     */
    public static void equalize(XYPlot plot, Rectangle2D dataArea) {
        double w = Math.max(1, dataArea.getWidth());
        double h = Math.max(1, dataArea.getHeight());
        Range x = plot.getDomainAxis().getRange();
        Range y = plot.getRangeAxis().getRange();
        double sx = x.getLength() / w;
        double sy = y.getLength() / h;
        double s = Math.max(sx, sy);
        if (Math.abs(sx - sy) <= 1e-6 * s) {
            return;
        }
        set(plot, x.getCentralValue(), y.getCentralValue(), s, w, h);
    }

    /** Millimetres per pixel along x over those along y: 1 when the scale is equal. */
    public static double aspect(XYPlot plot, Rectangle2D dataArea) {
        double sx = plot.getDomainAxis().getRange().getLength() / dataArea.getWidth();
        double sy = plot.getRangeAxis().getRange().getLength() / dataArea.getHeight();
        return sx / sy;
    }

    /**
     * The chart laid out at this size with equal scale: fitted to the box when given, else the
     * current view kept in view (its centre kept, one axis widened).
     */
    public static void prepare(JFreeChart chart, Optional<Box2> fitTo, double widthPx, double heightPx) {
        XYPlot plot = chart.getXYPlot();
        // the tick labels' width depends on the ranges and moves the data area by a pixel or so:
        // a second pass settles it
        for (int pass = 0; pass < 2; pass++) {
            Rectangle2D area = dataArea(chart, widthPx, heightPx);
            if (fitTo.isPresent()) {
                fit(plot, fitTo.get(), area);
            } else {
                equalize(plot, area);
            }
        }
    }

    private static void set(XYPlot plot, double cx, double cy, double mmPerPx, double w, double h) {
        boolean notify = plot.isNotify();
        plot.setNotify(false);
        ValueAxis x = plot.getDomainAxis();
        ValueAxis y = plot.getRangeAxis();
        x.setRange(new Range(cx - mmPerPx * w / 2, cx + mmPerPx * w / 2), true, false);
        y.setRange(new Range(cy - mmPerPx * h / 2, cy + mmPerPx * h / 2), true, false);
        plot.setNotify(notify);
    }
}
