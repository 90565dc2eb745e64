package org.fresa.chart;

import java.awt.BasicStroke;
import java.awt.Color;
import java.util.List;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.plot.CombinedDomainXYPlot;
import org.jfree.chart.plot.ValueMarker;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;

/**
 * The robot trajectory plots of the thesis's figures 5.9-5.14: joint values along the path with
 * their limits, and the position error per axis per point.
 */
public final class RobotCharts {

    private static final Color LIMIT = new Color(0xC62828);
    private static final Color[] SERIES = {new Color(0x1565C0), new Color(0x2E7D32), new Color(0xEF6C00)};

    private RobotCharts() {}

    /**
     * One joint.
     *
     * @param name q1, q2, ...
     * @param unit deg or mm
     * @param min lower limit
     * @param max upper limit
     * @param values per trajectory point; NaN where the point has no solution (a gap)
     */
    public record JointSeries(String name, String unit, double min, double max, double[] values) {
        public JointSeries {
            values = values.clone();
        }
    }

    /** Joint values against the point index, one stacked panel per joint, limits as red lines. */
    public static JFreeChart joints(String title, List<JointSeries> joints) {
        CombinedDomainXYPlot plot = new CombinedDomainXYPlot(NumberAxes.of("point"));
        plot.setGap(6);
        for (JointSeries j : joints) {
            XYSeries s = new XYSeries(j.name(), false, true);
            double[] v = j.values();
            for (int i = 0; i < v.length; i++) {
                s.add(i + 1, Double.isNaN(v[i]) ? null : v[i], false);
            }
            NumberAxis y = NumberAxes.of(j.name() + " (" + j.unit() + ")");
            y.setAutoRangeIncludesZero(false);
            double pad = 0.05 * (j.max() - j.min());
            y.setRange(j.min() - pad, j.max() + pad);
            XYLineAndShapeRenderer r = lines();
            r.setSeriesPaint(0, SERIES[0]);
            XYPlot sub = new XYPlot(new XYSeriesCollection(s), null, y, r);
            sub.setBackgroundPaint(Color.WHITE);
            sub.setRangeGridlinePaint(new Color(0xE0E0E0));
            for (double lim : new double[] {j.min(), j.max()}) {
                ValueMarker m = new ValueMarker(lim, LIMIT, new BasicStroke(1.2f));
                sub.addRangeMarker(m);
            }
            plot.add(sub, 1);
        }
        JFreeChart chart = new JFreeChart(title, JFreeChart.DEFAULT_TITLE_FONT, plot, false);
        chart.setBackgroundPaint(Color.WHITE);
        return chart;
    }

    /**
     * Position error (target - reached) per axis against the point index, in micrometres; NaN
     * values (unreachable points) leave gaps.
     *
     * @param errorsMm per point {ex, ey, ez} in mm
     */
    public static JFreeChart positionErrors(String title, double[][] errorsMm) {
        return positionErrors(title, errorsMm, List.of("error x", "error y", "error z"), "");
    }

    /**
     * The position error curves with a legend of their own (the figures of each axis) and a line
     * under the title (the orientation's figures; none when empty).
     */
    public static JFreeChart positionErrors(String title, double[][] errorsMm, List<String> legends, String subtitle) {
        XYSeriesCollection data = new XYSeriesCollection();
        for (int a = 0; a < 3; a++) {
            XYSeries s = new XYSeries(legends.get(a), false, true);
            for (int i = 0; i < errorsMm.length; i++) {
                double e = errorsMm[i][a];
                s.add(i + 1, Double.isNaN(e) ? null : e * 1000, false);
            }
            data.addSeries(s);
        }
        NumberAxis y = NumberAxes.of("target - reached (um)");
        y.setAutoRangeIncludesZero(true);
        XYLineAndShapeRenderer r = lines();
        for (int a = 0; a < 3; a++) {
            r.setSeriesPaint(a, SERIES[a]);
        }
        XYPlot plot = new XYPlot(data, NumberAxes.of("point"), y, r);
        plot.setBackgroundPaint(Color.WHITE);
        plot.setRangeGridlinePaint(new Color(0xE0E0E0));
        JFreeChart chart = new JFreeChart(title, JFreeChart.DEFAULT_TITLE_FONT, plot, true);
        chart.setBackgroundPaint(Color.WHITE);
        if (!subtitle.isEmpty()) {
            chart.addSubtitle(new org.jfree.chart.title.TextTitle(subtitle));
        }
        return chart;
    }

    /**
     * Lines without shapes, each series stroked as one path: thousands of separate segments took
     * most of the time of writing joints.png (1.1 s of 4 458 points x 6 joints); gaps (null
     * values) still break the path.
     */
    private static XYLineAndShapeRenderer lines() {
        XYLineAndShapeRenderer r = new XYLineAndShapeRenderer(true, false);
        r.setDrawSeriesLineAsPath(true);
        return r;
    }
}
