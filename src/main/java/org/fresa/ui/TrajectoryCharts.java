package org.fresa.ui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.util.List;
import org.fresa.chart.RobotCharts;
import org.fresa.job.RobotTrajectoryService;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.plot.CombinedDomainXYPlot;
import org.jfree.chart.plot.ValueMarker;
import org.jfree.chart.plot.XYPlot;

/**
 * The Position tab's two charts of one solved trajectory, made on demand with the replayed point
 * marked. The data are computed once and never change, so any thread may make a chart: the tab
 * makes them off the event thread, a new one for each picture drawn.
 */
final class TrajectoryCharts {

    /** A chart and the marker of the replayed point in it (point numbers count from 1). */
    record Marked(JFreeChart chart, ValueMarker marker) {}

    private final String robot;
    private final List<RobotCharts.JointSeries> joints;
    private final double[][] errorsMm;
    private final org.fresa.job.ErrorStatistics stats;

    private TrajectoryCharts(
            String robot,
            List<RobotCharts.JointSeries> joints,
            double[][] errorsMm,
            org.fresa.job.ErrorStatistics stats) {
        this.robot = robot;
        this.joints = joints;
        this.errorsMm = errorsMm;
        this.stats = stats;
    }

    static TrajectoryCharts of(RobotTrajectoryService.Solved s) {
        return new TrajectoryCharts(
                s.request().robot().name(),
                RobotTrajectoryService.jointSeries(s.request().robot(), s.result()),
                RobotTrajectoryService.positionErrorsMm(s.result()),
                org.fresa.job.ErrorStatistics.of(s.result()));
    }

    Marked joints(double point) {
        JFreeChart c = RobotCharts.joints("Joint values, " + robot, joints);
        ValueMarker m = marker(point);
        if (c.getPlot() instanceof CombinedDomainXYPlot p) {
            for (Object sub : p.getSubplots()) {
                ((XYPlot) sub).addDomainMarker(m);
            }
        }
        return new Marked(c, m);
    }

    Marked errors(double point) {
        JFreeChart c = RobotCharts.positionErrors(
                "Position error per axis, " + robot,
                errorsMm,
                List.of(stats.positionLegend(0), stats.positionLegend(1), stats.positionLegend(2)),
                stats.orientationLine());
        ValueMarker m = marker(point);
        c.getXYPlot().addDomainMarker(m);
        return new Marked(c, m);
    }

    private static ValueMarker marker(double point) {
        return new ValueMarker(point, new Color(90, 90, 90), new BasicStroke(1.5f));
    }
}
