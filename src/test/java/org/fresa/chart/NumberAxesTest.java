package org.fresa.chart;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Graphics2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.Locale;
import org.fresa.geom.Vec2;
import org.jfree.chart.ChartRenderingInfo;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.axis.NumberTickUnitSource;
import org.jfree.chart.axis.TickUnit;
import org.jfree.chart.axis.TickUnitSource;
import org.jfree.chart.plot.CombinedDomainXYPlot;
import org.junit.jupiter.api.Test;

/**
 * The tick labels of every chart the application draws (the Position tab's plots, the files of a
 * robot run, the toolpath and grading plots) read the same on a German machine as anywhere: a
 * point as the decimal mark, no dot between thousands.
 */
class NumberAxesTest {

    @Test
    void aGermanMachineLabelsTheErrorAndPointAxesAsEveryOther() {
        Locale was = Locale.getDefault();
        Locale.setDefault(Locale.GERMANY);
        try {
            // errors of doubles' rounding along example 2's 6518 points, as the Position tab plots them
            double[][] e = new double[6518][3];
            for (int i = 0; i < e.length; i++) {
                for (int a = 0; a < 3; a++) {
                    e[i][a] = (i % 3 - 1) * 5.5e-13;
                }
            }
            JFreeChart errors = RobotCharts.positionErrors("Position error per axis, irb140", e);
            draw(errors);
            NumberAxis error = (NumberAxis) errors.getXYPlot().getRangeAxis();
            NumberAxis point = (NumberAxis) errors.getXYPlot().getDomainAxis();
            JFreeChart joints = RobotCharts.joints(
                    "Joint values, irb140",
                    List.of(new RobotCharts.JointSeries("track", "mm", 0, 3000, new double[] {500, 1500})));
            draw(joints);
            NumberAxis track = (NumberAxis) ((CombinedDomainXYPlot) joints.getPlot())
                    .getSubplots()
                    .get(0)
                    .getRangeAxis();
            JFreeChart outline = ToolpathChart.create(PlotScene.empty("outline")
                    .withMarker("a", Vec2.ZERO, 0.1)
                    .withMarker("b", Vec2.of(0.25, 0.25), 0.1));
            draw(outline);
            NumberAxis xMm = (NumberAxis) outline.getXYPlot().getDomainAxis();
            assertAll(
                    () -> assertEquals("5.5E-10", error.getTickUnit().valueToString(5.5e-10)),
                    () -> assertEquals("1,000", point.getTickUnit().valueToString(1000)),
                    () -> assertEquals("1,500", track.getTickUnit().valueToString(1500)),
                    () -> assertTrue(
                            xMm.getTickUnit().valueToString(0.5).matches("0\\.50*"),
                            xMm.getTickUnit().valueToString(0.5)));
        } finally {
            Locale.setDefault(was);
        }
    }

    @Test
    void theTicksAreJFreeChartsOwnOneTwoOrFiveTimesAPowerOfTen() {
        TickUnitSource root = NumberAxes.of("x").getStandardTickUnits();
        TickUnitSource own = new NumberTickUnitSource();
        for (double size : new double[] {3e-11, 1e-10, 7e-5, 0.1, 0.3, 1, 2, 4.9, 5, 100, 2.2e6, 3e7}) {
            TickUnit r = root.getCeilingTickUnit(size);
            TickUnit o = own.getCeilingTickUnit(size);
            assertEquals(o.getSize(), r.getSize(), "ceiling of " + size);
            assertEquals(o.getMinorTickCount(), r.getMinorTickCount(), "ceiling of " + size);
            TickUnit rl = root.getLargerTickUnit(r);
            TickUnit ol = own.getLargerTickUnit(o);
            assertEquals(ol.getSize(), rl.getSize(), "larger than " + size);
            assertEquals(
                    o.valueToString(12345.678).replace(",", "").replace(".", ""),
                    r.valueToString(12345.678).replace(",", "").replace(".", ""),
                    "the digits of the same pattern, at " + size);
        }
    }

    private static void draw(JFreeChart c) {
        BufferedImage img = new BufferedImage(550, 590, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        c.draw(g, new Rectangle2D.Double(0, 0, 550, 590), null, new ChartRenderingInfo(null));
        g.dispose();
    }
}
