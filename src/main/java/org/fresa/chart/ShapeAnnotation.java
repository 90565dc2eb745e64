package org.fresa.chart;

import java.awt.Graphics2D;
import java.awt.Paint;
import java.awt.Shape;
import java.awt.Stroke;
import java.awt.geom.AffineTransform;
import java.awt.geom.Rectangle2D;
import org.jfree.chart.annotations.AbstractXYAnnotation;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.plot.PlotOrientation;
import org.jfree.chart.plot.PlotRenderingInfo;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.ui.RectangleEdge;

/**
 * A shape in data coordinates drawn on an XY plot. Unlike JFreeChart's XYShapeAnnotation, the
 * data-to-screen transform comes from the axes alone, so shapes with a zero-width bounding box
 * (a vertical rapid move) are drawn too, and arcs stay arcs at every zoom.
 */
final class ShapeAnnotation extends AbstractXYAnnotation {

    private static final long serialVersionUID = 1L;

    private final transient Shape shape;
    private final transient Stroke stroke;
    private final transient Paint outline;
    private final transient Paint fill;

    ShapeAnnotation(Shape shape, Stroke stroke, Paint outline, Paint fill) {
        this.shape = shape;
        this.stroke = stroke;
        this.outline = outline;
        this.fill = fill;
    }

    @Override
    public void draw(
            Graphics2D g2,
            XYPlot plot,
            Rectangle2D dataArea,
            ValueAxis domainAxis,
            ValueAxis rangeAxis,
            int rendererIndex,
            PlotRenderingInfo info) {
        PlotOrientation orientation = plot.getOrientation();
        RectangleEdge de =
                org.jfree.chart.plot.Plot.resolveDomainAxisLocation(plot.getDomainAxisLocation(), orientation);
        RectangleEdge re = org.jfree.chart.plot.Plot.resolveRangeAxisLocation(plot.getRangeAxisLocation(), orientation);
        double x0 = domainAxis.valueToJava2D(0, dataArea, de);
        double x1 = domainAxis.valueToJava2D(1, dataArea, de);
        double y0 = rangeAxis.valueToJava2D(0, dataArea, re);
        double y1 = rangeAxis.valueToJava2D(1, dataArea, re);
        AffineTransform t = new AffineTransform(x1 - x0, 0, 0, y1 - y0, x0, y0);
        Shape s = t.createTransformedShape(shape);
        java.awt.Shape oldClip = g2.getClip();
        g2.clip(dataArea);
        if (fill != null) {
            g2.setPaint(fill);
            g2.fill(s);
        }
        if (outline != null && stroke != null) {
            g2.setPaint(outline);
            g2.setStroke(stroke);
            g2.draw(s);
        }
        g2.setClip(oldClip);
    }
}
