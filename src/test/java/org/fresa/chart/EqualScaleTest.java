package org.fresa.chart;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.util.List;
import java.util.Optional;
import javax.imageio.ImageIO;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.testing.Pictures;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.LegendItemCollection;
import org.jfree.chart.plot.XYPlot;
import org.junit.jupiter.api.Test;

class EqualScaleTest {

    /** A disc of radius 10 filled in the material colour, in a long thin outline: a wide scene. */
    static PlotScene discInAStrip() {
        return PlotScene.empty("disc")
                .with(new PlotScene.Layer(
                        "disc", PlotScene.Style.PART, List.of(Arc2.circle(Vec2.of(20, 10), 10, true))))
                .with(new PlotScene.Layer(
                        "strip",
                        PlotScene.Style.OUTLINE,
                        List.of(
                                Segment2.of(0, 0, 200, 0),
                                Segment2.of(200, 0, 200, 20),
                                Segment2.of(200, 20, 0, 20),
                                Segment2.of(0, 20, 0, 0))));
    }

    static double discRoundness(BufferedImage img) {
        return Pictures.roundness(img, 0x90A4AE);
    }

    @Test
    void aSceneWrittenAsPngDrawsARoundToolRound() throws Exception {
        for (int[] size : new int[][] {{1000, 1100}, {900, 300}, {400, 900}}) {
            ByteArrayOutputStream png = new ByteArrayOutputStream();
            ToolpathChart.writePng(discInAStrip(), size[0], size[1], png);
            BufferedImage img = ImageIO.read(new ByteArrayInputStream(png.toByteArray()));
            assertEquals(1, discRoundness(img), 0.03, size[0] + " x " + size[1]);
        }
    }

    @Test
    void aFitShowsTheWholeBoxAtEqualScale() {
        JFreeChart chart = ToolpathChart.frame(discInAStrip());
        Rectangle2D area = EqualScale.dataArea(chart, 700, 500);
        EqualScale.fit(chart.getXYPlot(), new Box2(0, 0, 200, 20), area);
        XYPlot plot = chart.getXYPlot();
        assertAll(
                () -> assertEquals(1, EqualScale.aspect(plot, area), 1e-9),
                () -> assertEquals(220, plot.getDomainAxis().getRange().getLength(), 1e-9),
                () -> assertEquals(100, plot.getDomainAxis().getRange().getCentralValue(), 1e-9),
                () -> assertEquals(10, plot.getRangeAxis().getRange().getCentralValue(), 1e-9));
    }

    @Test
    void equalizingAStretchedViewWidensTheNarrowAxisAndKeepsTheOther() {
        JFreeChart chart = ToolpathChart.frame(discInAStrip());
        XYPlot plot = chart.getXYPlot();
        Rectangle2D area = new Rectangle2D.Double(0, 0, 400, 200);
        // a drag zoom over a long flat box: 100 mm across 400 px, 5 mm across 200 px
        plot.getDomainAxis().setRange(50, 150);
        plot.getRangeAxis().setRange(10, 15);
        EqualScale.equalize(plot, area);
        assertAll(
                () -> assertEquals(1, EqualScale.aspect(plot, area), 1e-9),
                () -> assertEquals(50, plot.getDomainAxis().getLowerBound(), 1e-9),
                () -> assertEquals(150, plot.getDomainAxis().getUpperBound(), 1e-9),
                () -> assertEquals(50, plot.getRangeAxis().getRange().getLength(), 1e-9),
                () -> assertEquals(12.5, plot.getRangeAxis().getRange().getCentralValue(), 1e-9));
    }

    @Test
    void theDataAreaDoesNotMoveWithTheTickLabels() {
        JFreeChart chart = ToolpathChart.frame(discInAStrip());
        Rectangle2D before = EqualScale.dataArea(chart, 700, 500);
        chart.getXYPlot().getRangeAxis().setRange(-123456, 123456);
        Rectangle2D after = EqualScale.dataArea(chart, 700, 500);
        assertEquals(before, after);
    }

    @Test
    void prepareKeepsTheViewCentreAtTheImagesProportions() {
        JFreeChart chart = ToolpathChart.create(discInAStrip());
        XYPlot plot = chart.getXYPlot();
        plot.getDomainAxis().setRange(0, 40);
        plot.getRangeAxis().setRange(0, 20);
        EqualScale.prepare(chart, Optional.empty(), 500, 900);
        Rectangle2D area = EqualScale.dataArea(chart, 500, 900);
        assertAll(
                () -> assertEquals(1, EqualScale.aspect(plot, area), 1e-9),
                () -> assertEquals(20, plot.getDomainAxis().getRange().getCentralValue(), 1e-9),
                () -> assertEquals(10, plot.getRangeAxis().getRange().getCentralValue(), 1e-9),
                () -> assertTrue(plot.getRangeAxis().getRange().getLength() > 20));
    }

    @Test
    void theLegendNamesEachStyleDrawnAfterItsLayers() {
        PlotScene s = discInAStrip()
                .with(new PlotScene.Layer("size 36", PlotScene.Style.FEED, List.of(Segment2.of(0, 0, 1, 1))));
        for (int size = 37; size <= 40; size++) {
            s = s.with(new PlotScene.Layer("size " + size, PlotScene.Style.FEED, List.of(Segment2.of(0, 0, 1, 1))));
        }
        PlotScene scene = s.with(new PlotScene.Layer("nothing", PlotScene.Style.RAPID, List.of()));
        LegendItemCollection items = ToolpathChart.legend(scene);
        assertAll(
                () -> assertEquals(3, items.getItemCount()),
                () -> assertEquals("disc", items.get(0).getLabel()),
                () -> assertEquals("strip", items.get(1).getLabel()),
                () -> assertEquals("size 36 ... size 40", items.get(2).getLabel()),
                () -> assertTrue(ToolpathChart.create(scene).getLegend() != null, "the chart shows the legend"));
    }
}
