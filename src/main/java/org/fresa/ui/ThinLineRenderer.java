package org.fresa.ui;

import java.awt.Graphics2D;
import java.awt.geom.GeneralPath;
import java.awt.geom.Rectangle2D;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.plot.CrosshairState;
import org.jfree.chart.plot.PlotOrientation;
import org.jfree.chart.plot.PlotRenderingInfo;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYItemRendererState;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.data.xy.XYDataset;

/**
 * Lines without shapes, each series stroked as one path, as the saved plots draw them, but of
 * each pixel column only the points that shape it ({@link ColumnThinning}): the screen's plots of a
 * path of thousands of points look the same and draw in a fraction of the time. For the screen
 * only: the files a run writes draw every point.
 */
final class ThinLineRenderer extends XYLineAndShapeRenderer {

    private static final long serialVersionUID = 1L;

    ThinLineRenderer() {
        super(true, false);
        setDrawSeriesLineAsPath(true);
    }

    @Override
    public XYItemRendererState initialise(
            Graphics2D g2, Rectangle2D dataArea, XYPlot plot, XYDataset dataset, PlotRenderingInfo info) {
        Thinned state = new Thinned(info, g2, dataArea, plot, dataset);
        state.seriesPath = new GeneralPath();
        return state;
    }

    @Override
    public void drawItem(
            Graphics2D g2,
            XYItemRendererState state,
            Rectangle2D dataArea,
            PlotRenderingInfo info,
            XYPlot plot,
            ValueAxis domainAxis,
            ValueAxis rangeAxis,
            XYDataset dataset,
            int series,
            int item,
            CrosshairState crosshairState,
            int pass) {
        if (state instanceof Thinned t && !t.drawn(item)) {
            return;
        }
        super.drawItem(
                g2, state, dataArea, info, plot, domainAxis, rangeAxis, dataset, series, item, crosshairState, pass);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof ThinLineRenderer && super.equals(o);
    }

    @Override
    public int hashCode() {
        return super.hashCode();
    }

    /** The state of one drawing: which items of the series being drawn are kept. */
    private static final class Thinned extends State {
        private final double scaleX;
        private final double translateX;
        private final boolean g2ShearsOrTurns;
        private final Rectangle2D dataArea;
        private final XYPlot plot;
        private final XYDataset dataset;
        private boolean[] kept;
        private int first;

        Thinned(PlotRenderingInfo info, Graphics2D g2, Rectangle2D dataArea, XYPlot plot, XYDataset dataset) {
            super(info);
            // the device's pixel columns: an image drawn at twice the size has twice as many
            this.scaleX = g2.getTransform().getScaleX();
            this.g2ShearsOrTurns =
                    g2.getTransform().getShearX() != 0 || g2.getTransform().getShearY() != 0;
            this.translateX = g2.getTransform().getTranslateX();
            this.dataArea = dataArea;
            this.plot = plot;
            this.dataset = dataset;
        }

        @Override
        public void startSeriesPass(XYDataset data, int series, int firstItem, int lastItem, int pass, int passCount) {
            super.startSeriesPass(data, series, firstItem, lastItem, pass, passCount);
            first = firstItem;
            kept = null;
            if (data != dataset
                    || plot.getOrientation() != PlotOrientation.VERTICAL
                    || scaleX <= 0
                    || g2ShearsOrTurns) {
                // turned, mirrored or sheared, the device columns are not along x: drawn whole
                return;
            }
            ValueAxis x = plot.getDomainAxisForDataset(plot.indexOf(data));
            int n = lastItem - firstItem + 1;
            double[] xPx = new double[n];
            double[] y = new double[n];
            for (int k = 0; k < n; k++) {
                xPx[k] = x.valueToJava2D(data.getXValue(series, firstItem + k), dataArea, plot.getDomainAxisEdge())
                                * scaleX
                        + translateX;
                y[k] = data.getYValue(series, firstItem + k);
            }
            kept = ColumnThinning.keep(xPx, y);
        }

        boolean drawn(int item) {
            return kept == null || kept[item - first];
        }
    }
}
