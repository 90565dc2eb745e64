package org.fresa.chart;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Paint;
import java.awt.Stroke;
import java.awt.geom.Arc2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.LegendItem;
import org.jfree.chart.LegendItemCollection;
import org.jfree.chart.annotations.XYTextAnnotation;
import org.jfree.chart.axis.AxisSpace;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.block.BlockBorder;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.chart.ui.RectangleEdge;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;

/**
 * Draws a {@link PlotScene} as a JFreeChart XY plot in millimetres. Arcs are drawn as true arcs
 * (Java2D {@link Arc2D} shapes), not polylines. Equal scale on both axes depends on the size the
 * chart is drawn at: {@link EqualScale} sets it, for the plot view and for the files.
 */
public final class ToolpathChart {

    private ToolpathChart() {}

    /**
     * The chart of a scene: its title, axes named after the view, a legend of the layers' styles,
     * and the layers' curves. The axes are set to the scene's box (not yet at equal scale: that
     * needs the size it is drawn at, see {@link EqualScale} and {@link #writePng}).
     */
    public static JFreeChart create(PlotScene scene) {
        JFreeChart chart = frame(scene);
        XYPlot plot = chart.getXYPlot();
        for (PlotScene.Layer layer : scene.layers()) {
            if (layer.curves().isEmpty()) {
                continue;
            }
            Path2D path = toPath(layer);
            // even-odd: a layer of outer contours and their holes fills exactly the material
            path.setWindingRule(Path2D.WIND_EVEN_ODD);
            Style s = style(layer.style());
            plot.addAnnotation(new ShapeAnnotation(path, s.stroke, s.outline, s.fill), false);
        }
        for (PlotScene.Label l : scene.labels()) {
            XYTextAnnotation t = new XYTextAnnotation(l.text(), l.at().x(), l.at().y());
            t.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
            t.setPaint(new Color(0x1A237E));
            plot.addAnnotation(t, false);
        }
        return chart;
    }

    /**
     * The chart of a scene without its curves: title, named axes, legend and the scene's extent
     * (what Auto Range fits to). Laid out exactly as {@link #create} lays out the same scene, and
     * cheap to draw: the plot view keeps one on the event thread for zoom and the mouse.
     */
    public static JFreeChart frame(PlotScene scene) {
        XYSeriesCollection data = new XYSeriesCollection();
        XYSeries extent = new XYSeries("extent");
        scene.bounds().ifPresent(b -> {
            double pad = EqualScale.FIT_MARGIN * Math.max(1e-3, Math.max(b.width(), b.height()));
            extent.add(b.minX() - pad, b.minY() - pad);
            extent.add(b.maxX() + pad, b.maxY() + pad);
        });
        data.addSeries(extent);
        NumberAxis x = NumberAxes.of(scene.axes().horizontal());
        NumberAxis y = NumberAxes.of(scene.axes().vertical());
        for (NumberAxis a : List.of(x, y)) {
            a.setAutoRangeIncludesZero(false);
            // the extent already holds the margin
            a.setLowerMargin(0);
            a.setUpperMargin(0);
        }
        XYLineAndShapeRenderer r = new XYLineAndShapeRenderer(false, false);
        XYPlot plot = new XYPlot(data, x, y, r);
        plot.setBackgroundPaint(Color.WHITE);
        plot.setDomainGridlinePaint(new Color(0xE0E0E0));
        plot.setRangeGridlinePaint(new Color(0xE0E0E0));
        plot.setDomainPannable(true);
        plot.setRangePannable(true);
        // fixed room for the axes: the data area, and so the scale, does not move with the width
        // of the tick labels while the planner zooms and pans
        AxisSpace left = new AxisSpace();
        left.setLeft(AXIS_ROOM_LEFT_PX);
        plot.setFixedRangeAxisSpace(left);
        AxisSpace bottom = new AxisSpace();
        bottom.setBottom(AXIS_ROOM_BOTTOM_PX);
        plot.setFixedDomainAxisSpace(bottom);
        LegendItemCollection legend = legend(scene);
        plot.setFixedLegendItems(legend);
        JFreeChart chart = new JFreeChart(
                scene.title().isEmpty() ? null : scene.title(),
                new Font(Font.SANS_SERIF, Font.BOLD, 13),
                plot,
                legend.getItemCount() > 0);
        chart.setBackgroundPaint(Color.WHITE);
        if (chart.getLegend() != null) {
            chart.getLegend().setPosition(RectangleEdge.BOTTOM);
            chart.getLegend().setFrame(BlockBorder.NONE);
        }
        return chart;
    }

    private static final double AXIS_ROOM_LEFT_PX = 72;
    private static final double AXIS_ROOM_BOTTOM_PX = 42;

    /**
     * One legend entry per style drawn, named after its layers: the layer's name when one layer
     * has the style, the names joined when a few have it, the first and last of many (sizes).
     */
    static LegendItemCollection legend(PlotScene scene) {
        Map<PlotScene.Style, List<String>> names = new LinkedHashMap<>();
        for (PlotScene.Layer layer : scene.layers()) {
            if (!layer.curves().isEmpty()) {
                List<String> l = names.computeIfAbsent(layer.style(), k -> new ArrayList<>());
                if (!l.contains(layer.name())) {
                    l.add(layer.name());
                }
            }
        }
        LegendItemCollection items = new LegendItemCollection();
        for (Map.Entry<PlotScene.Style, List<String>> e : names.entrySet()) {
            List<String> l = e.getValue();
            String label = l.size() <= 3 ? String.join(", ", l) : l.get(0) + " ... " + l.get(l.size() - 1);
            Style s = style(e.getKey());
            LegendItem item;
            if (s.fill != null) {
                item = new LegendItem(
                        label, null, null, null, new Rectangle2D.Double(-6, -5, 12, 10), s.fill, s.stroke, s.outline);
            } else {
                item = new LegendItem(label, null, null, null, new Line2D.Double(-10, 0, 10, 0), s.stroke, s.outline);
            }
            items.add(item);
        }
        return items;
    }

    /**
     * The scene as a PNG image at equal scale, fitted to the image: for files written headless.
     */
    public static void writePng(PlotScene scene, int widthPx, int heightPx, java.io.OutputStream out)
            throws java.io.IOException {
        JFreeChart chart = create(scene);
        EqualScale.prepare(chart, scene.bounds(), widthPx, heightPx);
        ChartFiles.writePng(chart, widthPx, heightPx, out);
    }

    /** The layer's curves as one Java2D path; consecutive curves that meet are joined. */
    static Path2D toPath(PlotScene.Layer layer) {
        Path2D.Double p = new Path2D.Double();
        Point2D last = null;
        for (Curve2 c : layer.curves()) {
            boolean joined = last != null
                    && last.getX() == c.start().x()
                    && last.getY() == c.start().y();
            if (c instanceof Segment2 s) {
                if (!joined) {
                    p.moveTo(s.start().x(), s.start().y());
                }
                p.lineTo(s.end().x(), s.end().y());
            } else {
                Arc2 a = (Arc2) c;
                double r = a.radius();
                if (r == 0) {
                    if (!joined) {
                        p.moveTo(a.start().x(), a.start().y());
                    }
                    p.lineTo(a.end().x(), a.end().y());
                } else {
                    // Java2D angles are clockwise-positive in a y-down space; the data space is y-up,
                    // so the plot's transform flips y and the arc's math angles map through unchanged
                    Arc2D.Double arc = new Arc2D.Double(
                            a.center().x() - r,
                            a.center().y() - r,
                            2 * r,
                            2 * r,
                            -Math.toDegrees(a.startAngleRad()),
                            -Math.toDegrees(a.sweepRad()),
                            Arc2D.OPEN);
                    p.append(arc, joined);
                }
            }
            last = new Point2D.Double(c.end().x(), c.end().y());
        }
        return p;
    }

    private record Style(Stroke stroke, Paint outline, Paint fill) {}

    private static Style style(PlotScene.Style s) {
        switch (s) {
            case OUTLINE:
                return new Style(new BasicStroke(1.6f), new Color(0x212121), null);
            case PART:
                return new Style(new BasicStroke(1.2f), new Color(0x37474F), new Color(0x90A4AE, false));
            case HOLE:
                return new Style(new BasicStroke(1.2f), new Color(0x37474F), null);
            case PIERCE:
                return new Style(new BasicStroke(1.0f), new Color(0xB71C1C), new Color(0xE53935));
            case FEED:
                return new Style(new BasicStroke(1.0f), new Color(0x1565C0), null);
            case FINISH:
                return new Style(new BasicStroke(1.4f), new Color(0x2E7D32), null);
            case RAPID:
                return new Style(
                        new BasicStroke(
                                0.7f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {4f, 3f}, 0f),
                        new Color(0xE53935),
                        null);
            case WARNING:
                return new Style(new BasicStroke(2.0f), new Color(0xFF8F00), null);
            case AUX:
            default:
                return new Style(new BasicStroke(0.6f), new Color(0x9E9E9E), null);
        }
    }

    /** The bounds of the chart's data, to set equal-scale ranges. */
    public static java.util.Optional<Box2> bounds(PlotScene scene) {
        return scene.bounds();
    }
}
