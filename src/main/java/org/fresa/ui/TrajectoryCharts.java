package org.fresa.ui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.util.ArrayList;
import java.util.List;
import org.fresa.chart.RobotCharts;
import org.fresa.job.RobotTrajectoryService;
import org.fresa.kin.ErrorStatistics;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.plot.CombinedDomainXYPlot;
import org.jfree.chart.plot.ValueMarker;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYItemRenderer;
import org.jfree.chart.title.TextTitle;
import org.jfree.chart.title.Title;
import org.jfree.data.xy.DefaultXYDataset;

/**
 * The data of the Position tab's two charts of one solved trajectory (joint values with their
 * limits, the position error per axis), worked out once off the event thread and never changed
 * after: any thread may read them. The charts themselves are a {@link Screen}'s, made once and
 * given the data of each new trajectory.
 */
final class TrajectoryCharts {

    private final String robot;
    private final List<RobotCharts.JointSeries> joints;
    private final double[][] errorsMm;
    // the error curves' legends (their figures) and the orientation's line under the title (or "")
    private final List<String> legends;
    private final String subtitle;
    // per curve {x, y} as the charts plot them (point numbers from 1; errors in micrometres; NaN a gap)
    private final List<double[][]> jointCurves;
    private final List<double[][]> errorCurves;

    private TrajectoryCharts(
            String robot,
            List<RobotCharts.JointSeries> joints,
            double[][] errorsMm,
            List<String> legends,
            String subtitle) {
        this.robot = robot;
        this.joints = List.copyOf(joints);
        this.errorsMm = errorsMm;
        this.legends = List.copyOf(legends);
        this.subtitle = subtitle;
        double[] x = new double[errorsMm.length];
        for (int i = 0; i < x.length; i++) {
            x[i] = i + 1;
        }
        List<double[][]> jc = new ArrayList<>();
        for (RobotCharts.JointSeries j : joints) {
            jc.add(new double[][] {x, j.values()});
        }
        List<double[][]> ec = new ArrayList<>();
        for (int a = 0; a < 3; a++) {
            double[] y = new double[errorsMm.length];
            for (int i = 0; i < y.length; i++) {
                // as RobotCharts plots them: the same product, so the same pixels
                y[i] = Double.isNaN(errorsMm[i][a]) ? Double.NaN : errorsMm[i][a] * 1000;
            }
            ec.add(new double[][] {x, y});
        }
        this.jointCurves = List.copyOf(jc);
        this.errorCurves = List.copyOf(ec);
    }

    static TrajectoryCharts of(RobotTrajectoryService.Solved s) {
        ErrorStatistics stats = ErrorStatistics.of(s.result());
        return of(
                s.request().robot().name(),
                RobotTrajectoryService.jointSeries(s.request().robot(), s.result()),
                RobotTrajectoryService.positionErrorsMm(s.result()),
                List.of(stats.positionLegend(0), stats.positionLegend(1), stats.positionLegend(2)),
                stats.orientationLine());
    }

    /**
     * @param errorsMm per point {ex, ey, ez} (mm), NaN where the point was not reached; not
     *     written after
     * @param legends the three error curves' legends
     * @param subtitle the line under the error chart's title, or "" for none
     */
    static TrajectoryCharts of(
            String robot,
            List<RobotCharts.JointSeries> joints,
            double[][] errorsMm,
            List<String> legends,
            String subtitle) {
        return new TrajectoryCharts(robot, joints, errorsMm, legends, subtitle);
    }

    private String jointsTitle() {
        return "Joint values, " + robot;
    }

    private String errorsTitle() {
        return "Position error per axis, " + robot;
    }

    /** What a joints chart's panels depend on besides the data: the joints' names, units and limits. */
    private List<Object> jointPanels() {
        List<Object> key = new ArrayList<>();
        for (RobotCharts.JointSeries j : joints) {
            key.add(List.of(j.name(), j.unit(), j.min(), j.max()));
        }
        return key;
    }

    /**
     * The two charts a panel pair shows, made once and given each new trajectory's data and marked
     * point: a change of the placements replaces the curves' data (one chart event per chart)
     * instead of building new charts. Not thread-safe: each thread that draws or shows charts has
     * its own.
     */
    static final class Screen {
        /**
         * The smallest span (um) of the error axis: about the spacing of doubles at a metre (1.1e-10
         * um), so that errors that are all rounding still get an axis of their own size instead of
         * JFreeChart's default of 1e-8, and all-zero errors an axis at all.
         */
        static final double MIN_ERROR_SPAN_UM = 1e-10;

        /** An axis's range in a {@link #view}: its automatic range, or not. */
        private static final String AUTO = "auto";

        private final boolean thin;
        private JFreeChart joints;
        private List<Object> jointPanels;
        private List<Object> jointsHome;
        private final ValueMarker jointsMarker = marker();
        private JFreeChart errors;
        private boolean errorsSubtitled;
        private List<Object> errorsHome;
        private final ValueMarker errorsMarker = marker();

        /** @param thin whether the curves draw only the points each pixel column needs ({@link ThinLineRenderer}) */
        Screen(boolean thin) {
            this.thin = thin;
        }

        /** The joints chart (one panel per joint, its limits in red) of c, point marked (from 1). */
        JFreeChart joints(TrajectoryCharts c, double point) {
            List<Object> panels = c.jointPanels();
            if (joints == null || !panels.equals(jointPanels)) {
                // another robot: other panels, made once for it
                joints = RobotCharts.joints(c.jointsTitle(), c.joints);
                jointPanels = panels;
                for (XYPlot sub : subplots(joints)) {
                    thin(sub);
                    sub.addDomainMarker(jointsMarker);
                }
                jointsHome = view(joints);
            }
            joints.setNotify(false);
            joints.setTitle(c.jointsTitle());
            List<XYPlot> subs = subplots(joints);
            for (int i = 0; i < subs.size(); i++) {
                subs.get(i)
                        .setDataset(
                                dataset(List.of(c.joints.get(i).name()), List.<double[][]>of(c.jointCurves.get(i))));
            }
            jointsMarker.setValue(point);
            joints.setNotify(true);
            return joints;
        }

        /** The position error chart of c (a curve per axis, its figures in the legend), point marked. */
        JFreeChart errors(TrajectoryCharts c, double point) {
            String subtitle = c.subtitle;
            List<String> legends = c.legends;
            if (errors == null || errorsSubtitled != !subtitle.isEmpty()) {
                errors = RobotCharts.positionErrors(c.errorsTitle(), c.errorsMm, legends, subtitle);
                errorsSubtitled = !subtitle.isEmpty();
                thin(errors.getXYPlot());
                errors.getXYPlot().addDomainMarker(errorsMarker);
                ((NumberAxis) errors.getXYPlot().getRangeAxis()).setAutoRangeMinimumSize(MIN_ERROR_SPAN_UM);
                errorsHome = view(errors);
            }
            errors.setNotify(false);
            errors.setTitle(c.errorsTitle());
            for (int i = 0; i < errors.getSubtitleCount(); i++) {
                Title t = errors.getSubtitle(i);
                if (t instanceof TextTitle text) {
                    text.setText(subtitle);
                }
            }
            errors.getXYPlot().setDataset(dataset(legends, c.errorCurves));
            errorsMarker.setValue(point);
            errors.setNotify(true);
            return errors;
        }

        /**
         * What the zoom shows of a chart: per axis (the shared point axis first, then each panel's
         * value axis) its range, or {@link #AUTO} where it follows the data. Equal for two charts
         * whose axes show the same.
         */
        static List<Object> view(JFreeChart chart) {
            List<Object> v = new ArrayList<>();
            for (ValueAxis a : axes(chart)) {
                v.add(a.isAutoRange() ? AUTO : a.getRange());
            }
            return List.copyOf(v);
        }

        /** Sets the chart's axes to a {@link #view} of a chart of the same panels. */
        static void show(JFreeChart chart, List<Object> view) {
            List<ValueAxis> axes = axes(chart);
            if (axes.size() != view.size()) {
                return;
            }
            for (int i = 0; i < axes.size(); i++) {
                ValueAxis a = axes.get(i);
                if (view.get(i) instanceof org.jfree.data.Range r) {
                    if (a.isAutoRange() || !a.getRange().equals(r)) {
                        a.setRange(r);
                    }
                } else if (!a.isAutoRange()) {
                    a.setAutoRange(true);
                }
            }
        }

        /** Shows the whole trajectory again in the chart (the joints or the errors) after a zoom. */
        void unzoom(boolean ofJoints) {
            JFreeChart c = ofJoints ? joints : errors;
            if (c != null) {
                show(c, ofJoints ? jointsHome : errorsHome);
            }
        }

        private static List<ValueAxis> axes(JFreeChart chart) {
            List<ValueAxis> axes = new ArrayList<>();
            List<XYPlot> subs = subplots(chart);
            if (subs.isEmpty()) {
                axes.add(chart.getXYPlot().getDomainAxis());
                axes.add(chart.getXYPlot().getRangeAxis());
            } else {
                axes.add(((CombinedDomainXYPlot) chart.getPlot()).getDomainAxis());
                for (XYPlot sub : subs) {
                    axes.add(sub.getRangeAxis());
                }
            }
            return axes;
        }

        /** Moves the marked point of both charts (from 1). */
        void mark(double point) {
            jointsMarker.setValue(point);
            errorsMarker.setValue(point);
        }

        /** The joints chart's marker, as the tab shows it (tests read it). */
        double markedPoint() {
            return jointsMarker.getValue();
        }

        private void thin(XYPlot plot) {
            if (!thin) {
                return;
            }
            XYItemRenderer full = plot.getRenderer();
            ThinLineRenderer r = new ThinLineRenderer();
            for (int s = 0; s < 3; s++) {
                if (full.getSeriesPaint(s) != null) {
                    r.setSeriesPaint(s, full.getSeriesPaint(s));
                }
            }
            plot.setRenderer(r);
        }

        private static List<XYPlot> subplots(JFreeChart chart) {
            List<XYPlot> subs = new ArrayList<>();
            if (chart.getPlot() instanceof CombinedDomainXYPlot p) {
                for (Object sub : p.getSubplots()) {
                    subs.add((XYPlot) sub);
                }
            }
            return subs;
        }

        private static DefaultXYDataset dataset(List<String> names, List<double[][]> curves) {
            DefaultXYDataset d = new DefaultXYDataset();
            for (int i = 0; i < curves.size(); i++) {
                // the arrays are never written after the trajectory's data is made
                d.addSeries(names.get(i), curves.get(i));
            }
            return d;
        }

        private static ValueMarker marker() {
            return new ValueMarker(1, new Color(90, 90, 90), new BasicStroke(1.5f));
        }
    }
}
