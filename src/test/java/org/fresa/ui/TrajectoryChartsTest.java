package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.fresa.chart.RobotCharts;
import org.jfree.chart.ChartRenderingInfo;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.plot.CombinedDomainXYPlot;
import org.jfree.chart.plot.ValueMarker;
import org.jfree.chart.plot.XYPlot;
import org.junit.jupiter.api.Test;

/**
 * The Position tab's charts, kept from one placement to the next: given a new trajectory they
 * draw what a chart made for it draws, and thinned for the screen they still cover in each pixel
 * column the rows the full curves cover.
 */
class TrajectoryChartsTest {

    private static final int W = 430;
    private static final int H = 420;

    @Test
    void aChartGivenANewTrajectoryDrawsWhatANewChartDraws() {
        TrajectoryCharts first = trajectory(1, 0.0);
        TrajectoryCharts second = trajectory(2, 0.3);
        TrajectoryCharts.Screen screen = new TrajectoryCharts.Screen(false);
        JFreeChart joints = screen.joints(first, 1);
        JFreeChart errors = screen.errors(first, 1);
        draw(joints);
        draw(errors);
        assertSame(joints, screen.joints(second, 700));
        assertSame(errors, screen.errors(second, 700));

        JFreeChart newJoints = RobotCharts.joints("Joint values, irb140", joints(2, 0.3));
        for (Object sub : ((CombinedDomainXYPlot) newJoints.getPlot()).getSubplots()) {
            ((XYPlot) sub).addDomainMarker(marker(700));
        }
        TrajectoryCharts s = second;
        JFreeChart newErrors = RobotCharts.positionErrors(
                "Position error per axis, irb140", errors(2, 0.3), legends(2), "orientation error 2");
        newErrors.getXYPlot().addDomainMarker(marker(700));
        assertEquals(0, differing(draw(newJoints), draw(screen.joints(s, 700))), "joints");
        assertEquals(0, differing(draw(newErrors), draw(screen.errors(s, 700))), "errors");
    }

    @Test
    void theThinnedChartsCoverTheRowsOfTheFullOnesInEveryColumn() {
        TrajectoryCharts t = trajectory(3, 0.25);
        TrajectoryCharts.Screen full = new TrajectoryCharts.Screen(false);
        TrajectoryCharts.Screen thin = new TrajectoryCharts.Screen(true);
        for (boolean joints : new boolean[] {true, false}) {
            BufferedImage a = draw(joints ? full.joints(t, 10) : full.errors(t, 10));
            BufferedImage b = draw(joints ? thin.joints(t, 10) : thin.errors(t, 10));
            int d = differing(a, b);
            int[] worst = worstInkShift(a, b, dataAreas(joints ? full.joints(t, 10) : full.errors(t, 10)), joints);
            System.out.printf(
                    "%s: %d of %d pixels differ; of %d columns' curves the top row shifts by at most %d px,"
                            + " the bottom row by %d px%n",
                    joints ? "joints" : "errors", d, W * H, worst[2], worst[0], worst[1]);
            // what differs is the anti-aliasing where thousands of segments overlapped in one column
            // (measured: 3765 and 1719 pixels), and the faint edge of a spike's flank in the next
            // column (1 and at most 5 rows)
            assertTrue(d < W * H / 40, d + " pixels differ");
            assertTrue(worst[2] > 200, "columns with curves: " + worst[2]);
            assertTrue(worst[0] <= (joints ? 1 : 6) && worst[1] <= (joints ? 1 : 6), java.util.Arrays.toString(worst));
        }
    }

    @Test
    void theErrorAxisSpansErrorsOfDoublesRoundingNotJFreeChartsDefaultSpan() {
        // errors of a trajectory solved to the last bit: +-5e-13 mm, +-5e-10 um
        double[][] e = new double[100][3];
        for (int i = 0; i < e.length; i++) {
            for (int a = 0; a < 3; a++) {
                e[i][a] = (i % 2 == 0 ? 5e-13 : -5e-13) * (a + 1) / 3;
            }
        }
        TrajectoryCharts t = TrajectoryCharts.of("irb140", joints(4, 0), e, legends(4), "orientation error 4");
        org.jfree.data.Range y = new TrajectoryCharts.Screen(true)
                .errors(t, 1)
                .getXYPlot()
                .getRangeAxis()
                .getRange();
        // the data and JFreeChart's margins of 5 %, not its default span of 1e-8 um
        assertAll(
                () -> assertTrue(y.getLowerBound() <= -5e-10 && y.getUpperBound() >= 5e-10, y.toString()),
                () -> assertTrue(y.getLowerBound() > -1e-9 && y.getUpperBound() < 1e-9, y.toString()));
    }

    @Test
    void aChartShowingAZoomedChartsViewDrawsWhatItDrawsAndHomeGivesTheWholeTrajectoryBack() {
        TrajectoryCharts t = trajectory(5, 0.1);
        for (boolean joints : new boolean[] {true, false}) {
            TrajectoryCharts.Screen shown = new TrajectoryCharts.Screen(false);
            TrajectoryCharts.Screen drawn = new TrajectoryCharts.Screen(false);
            JFreeChart zoomed = joints ? shown.joints(t, 10) : shown.errors(t, 10);
            BufferedImage whole = draw(zoomed);
            List<Object> home = TrajectoryCharts.Screen.view(zoomed);
            ChartRenderingInfo info = new ChartRenderingInfo(null);
            zoomed.draw(
                    new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB).createGraphics(),
                    new Rectangle2D.Double(0, 0, W, H),
                    null,
                    info);
            // as the mouse wheel zooms in at a point of the first panel
            Rectangle2D area = joints
                    ? info.getPlotInfo().getSubplotInfo(0).getDataArea()
                    : info.getPlotInfo().getDataArea();
            java.awt.geom.Point2D at = new java.awt.geom.Point2D.Double(area.getCenterX(), area.getCenterY());
            ((org.jfree.chart.plot.Zoomable) zoomed.getPlot()).zoomDomainAxes(0.5, info.getPlotInfo(), at, true);
            ((org.jfree.chart.plot.Zoomable) zoomed.getPlot()).zoomRangeAxes(0.5, info.getPlotInfo(), at, true);
            List<Object> view = TrajectoryCharts.Screen.view(zoomed);
            JFreeChart copy = joints ? drawn.joints(t, 10) : drawn.errors(t, 10);
            TrajectoryCharts.Screen.show(copy, view);
            BufferedImage zoomedImage = draw(zoomed);
            String what = joints ? "joints" : "errors";
            assertAll(
                    () -> assertTrue(!view.equals(home), what + " " + view),
                    () -> assertTrue(differing(whole, zoomedImage) > 1000, what),
                    () -> assertEquals(0, differing(zoomedImage, draw(copy)), what));
            shown.unzoom(joints);
            TrajectoryCharts.Screen.show(copy, TrajectoryCharts.Screen.view(zoomed));
            assertAll(
                    () -> assertEquals(home, TrajectoryCharts.Screen.view(zoomed), what),
                    () -> assertEquals(0, differing(whole, draw(zoomed)), what),
                    () -> assertEquals(0, differing(whole, draw(copy)), what));
        }
    }

    /**
     * Per pixel column of each data area, the top and bottom rows the curves colour (a saturated
     * colour; for the joints their blue, not the limits' red): the largest shift of either between
     * two images, in pixels, and the number of columns compared.
     */
    private static int[] worstInkShift(BufferedImage a, BufferedImage b, List<Rectangle2D> areas, boolean blue) {
        int[] worst = new int[3];
        for (Rectangle2D area : areas) {
            for (int x = (int) Math.ceil(area.getMinX()) + 2; x < (int) area.getMaxX() - 2; x++) {
                int[] ea = ink(a, x, area, blue);
                int[] eb = ink(b, x, area, blue);
                worst[0] = Math.max(worst[0], Math.abs(ea[0] - eb[0]));
                worst[1] = Math.max(worst[1], Math.abs(ea[1] - eb[1]));
                worst[2] += ea[0] >= 0 ? 1 : 0;
            }
        }
        return worst;
    }

    private static int[] ink(BufferedImage img, int x, Rectangle2D area, boolean blue) {
        int top = -1;
        int bottom = -1;
        for (int y = (int) Math.ceil(area.getMinY()) + 2; y < (int) area.getMaxY() - 2; y++) {
            int rgb = img.getRGB(x, y);
            int r = (rgb >> 16) & 0xFF;
            int g = (rgb >> 8) & 0xFF;
            int bl = rgb & 0xFF;
            boolean curve = blue ? bl - r > 60 : Math.max(r, Math.max(g, bl)) - Math.min(r, Math.min(g, bl)) > 60;
            if (curve) {
                top = top < 0 ? y : top;
                bottom = y;
            }
        }
        return new int[] {top, bottom};
    }

    private static List<Rectangle2D> dataAreas(JFreeChart c) {
        ChartRenderingInfo info = new ChartRenderingInfo(null);
        BufferedImage img = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        c.draw(g, new Rectangle2D.Double(0, 0, W, H), null, info);
        g.dispose();
        List<Rectangle2D> areas = new ArrayList<>();
        int subs = info.getPlotInfo().getSubplotCount();
        for (int i = 0; i < subs; i++) {
            areas.add(info.getPlotInfo().getSubplotInfo(i).getDataArea());
        }
        if (subs == 0) {
            areas.add(info.getPlotInfo().getDataArea());
        }
        return areas;
    }

    private static ValueMarker marker(double at) {
        return new ValueMarker(at, new Color(90, 90, 90), new java.awt.BasicStroke(1.5f));
    }

    private static int differing(BufferedImage a, BufferedImage b) {
        int n = 0;
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                n += a.getRGB(x, y) != b.getRGB(x, y) ? 1 : 0;
            }
        }
        return n;
    }

    static BufferedImage draw(JFreeChart c) {
        BufferedImage img = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, W, H);
        c.draw(g, new Rectangle2D.Double(0, 0, W, H), null, new ChartRenderingInfo(null));
        g.dispose();
        return img;
    }

    /** A trajectory of example 2's length: joints wandering within their limits, errors of some um. */
    static TrajectoryCharts trajectory(long seed, double unreachedFraction) {
        return TrajectoryCharts.of(
                "irb140",
                joints(seed, unreachedFraction),
                errors(seed, unreachedFraction),
                legends(seed),
                "orientation error " + seed);
    }

    private static final int POINTS = 6518;

    private static List<RobotCharts.JointSeries> joints(long seed, double unreachedFraction) {
        Random r = new Random(seed);
        List<RobotCharts.JointSeries> out = new ArrayList<>();
        for (int j = 0; j < 6; j++) {
            double[] v = new double[POINTS];
            double q = 0;
            for (int i = 0; i < POINTS; i++) {
                q = Math.max(-170, Math.min(170, q + r.nextGaussian()));
                v[i] = i > POINTS * (1 - unreachedFraction) ? Double.NaN : q;
            }
            out.add(new RobotCharts.JointSeries("q" + (j + 1), "deg", -180, 180, v));
        }
        return out;
    }

    private static double[][] errors(long seed, double unreachedFraction) {
        Random r = new Random(seed + 100);
        double[][] e = new double[POINTS][3];
        for (int i = 0; i < POINTS; i++) {
            for (int a = 0; a < 3; a++) {
                e[i][a] = i > POINTS * (1 - unreachedFraction)
                        ? Double.NaN
                        : 1e-6 * r.nextGaussian() * (r.nextInt(500) == 0 ? 20 : 1);
            }
        }
        return e;
    }

    private static List<String> legends(long seed) {
        return List.of("error x " + seed, "error y " + seed, "error z " + seed);
    }
}
