package org.fresa.chart;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.geom.Path2D;
import java.awt.geom.PathIterator;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.util.List;
import javax.imageio.ImageIO;
import org.fresa.geom.Arc2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.jfree.chart.JFreeChart;
import org.junit.jupiter.api.Test;

class ToolpathChartTest {

    @Test
    void arcsBecomeCurvesNotPolylines() {
        PlotScene.Layer layer =
                new PlotScene.Layer("arc", PlotScene.Style.FEED, List.of(Arc2.ofAngles(Vec2.ZERO, 10, 0, Math.PI / 2)));
        Path2D p = ToolpathChart.toPath(layer);
        int cubic = 0;
        for (PathIterator it = p.getPathIterator(null); !it.isDone(); it.next()) {
            if (it.currentSegment(new double[6]) == PathIterator.SEG_CUBICTO) {
                cubic++;
            }
        }
        assertTrue(cubic >= 1, "an arc is drawn with curve segments");
        assertAll(
                () -> assertEquals(0, p.getBounds2D().getMinX(), 1e-9),
                () -> assertEquals(10, p.getBounds2D().getMaxX(), 1e-9),
                () -> assertEquals(10, p.getBounds2D().getMaxY(), 1e-9),
                () -> assertEquals(0, p.getBounds2D().getMinY(), 1e-9));
    }

    @Test
    void toolpathScenesSeparateRapidsFromFeedsAndKeepArcs() {
        ToolpathSection s = new ToolpathSection(
                "WS1",
                Vec3.UNIT_Z,
                10,
                1,
                1000,
                Vec3.of(0, 0, 10),
                List.of(
                        new Move.Rapid(Vec3.of(10, 0, 10)),
                        new Move.Linear(Vec3.of(10, 0, -1), 100),
                        new Move.Circular(Vec3.of(0, 10, -1), Vec3.of(0, 0, -1), Vec3.UNIT_Z, true, 0, 200)));
        PlotScene scene = PlotScene.empty("t").withToolpath(new Toolpath(List.of(s)));
        PlotScene.Layer rapid = scene.layers().get(0);
        PlotScene.Layer feed = scene.layers().get(1);
        assertAll(
                () -> assertEquals(List.of(Segment2.of(0, 0, 10, 0)), rapid.curves()),
                () -> assertEquals(List.of(new Arc2(Vec2.ZERO, Vec2.of(10, 0), Vec2.of(0, 10), true)), feed.curves()));
    }

    @Test
    void aVerticalLineIsDrawnToo() throws Exception {
        // JFreeChart's own shape annotation divides by the bounding-box width and drops such lines
        PlotScene scene = PlotScene.empty("")
                .with(new PlotScene.Layer("v", PlotScene.Style.OUTLINE, List.of(Segment2.of(0, 0, 0, 100))))
                .withLabel(Vec2.of(50, 50), "");
        BufferedImage with = image(ToolpathChart.create(scene));
        // the same frame (axes, legend) without the line's shape
        BufferedImage without = image(ToolpathChart.frame(scene));
        int changed = 0;
        for (int x = 0; x < with.getWidth(); x++) {
            for (int y = 0; y < with.getHeight(); y++) {
                if (with.getRGB(x, y) != without.getRGB(x, y)) {
                    changed++;
                }
            }
        }
        assertTrue(changed > 100, "outline pixels drawn: " + changed);
    }

    private static BufferedImage image(JFreeChart chart) throws java.io.IOException {
        ByteArrayOutputStream png = new ByteArrayOutputStream();
        ChartFiles.writePng(chart, 400, 400, png);
        return ImageIO.read(new ByteArrayInputStream(png.toByteArray()));
    }
}
