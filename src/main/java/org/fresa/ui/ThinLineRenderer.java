package org.fresa.ui;

import java.awt.BasicStroke;
import java.awt.Graphics2D;
import java.awt.Stroke;
import java.awt.geom.GeneralPath;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.plot.CrosshairState;
import org.jfree.chart.plot.PlotOrientation;
import org.jfree.chart.plot.PlotRenderingInfo;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYItemRendererState;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.chart.ui.RectangleEdge;
import org.jfree.data.xy.XYDataset;

/**
 * Lines without shapes, each series stroked as one path, as the saved plots draw them, but of
 * each pixel column only what shapes it: the screen's plots of a path of thousands of points look
 * the same and draw in a fraction of the time. For the screen only: the files a run writes draw
 * every point.
 *
 * <p>A column the curve crosses with a few points, or along a few rows, is stroked through the
 * points that shape it ({@link ColumnThinning}). A column where many points go up and down over
 * more rows than the line is wide (an error curve of rounding noise: a solid band) is filled
 * between its second lowest and second highest point, widened by half the line's width, the rows
 * the stroked zig-zag colours solidly there; what leaves that band (the flanks of the column's
 * lone extremes, a spike) and every segment from one column to the next are stroked, so that
 * their anti-aliased edges, which colour the next column too, stay those of the full curve. The
 * error plot of example 2 (3 x 6518 points, 550 x 590 pixels) drew in 25.0 ms of CPU instead of
 * 30.8 (means of 40 drawings, same JVM, loaded machine).
 */
final class ThinLineRenderer extends XYLineAndShapeRenderer {

    private static final long serialVersionUID = 1L;

    /** The fewest points a column needs to be filled as a band. */
    private static final int BAND_POINTS = 3;

    /** The fewest device rows a column's curve must span to be filled as a band. */
    private static final double BAND_ROWS = 2;

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
        if (state instanceof Thinned t && t.columns != null) {
            // the whole series at once, at its first item; nothing for the others
            if (item == t.first
                    && isLinePass(pass)
                    && getItemVisible(series, item)
                    && !OffThreadChartPanel.drawingAbandoned()) {
                t.drawSeries(g2, lookupSeriesPaint(series), lookupSeriesStroke(series));
            }
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

    /** The state of one drawing: the series being drawn, per point and per device pixel column. */
    private static final class Thinned extends State {
        private final double scaleX;
        private final double translateX;
        private final boolean g2ShearsOrTurns;
        private final double rowsPerUnitY;
        private final Rectangle2D dataArea;
        private final XYPlot plot;
        private final XYDataset dataset;
        private int first;
        // the series being drawn (null when it is drawn item by item): per point its device x,
        // its column (NONE without a value, OUTSIDE beyond the columns kept), its x and y in the
        // chart's space, and whether the line through the columns not filled keeps it
        private double[] xPx;
        private int[] columns;
        private double[] xs;
        private double[] ys;
        private boolean[] kept;
        // per device column from columnOffset: the lowest and highest y of its points, their number
        private int columnOffset;
        private double[] low;
        private double[] high;
        // and the lowest and highest but one: the band's rows, a column's lone extreme is stroked
        private double[] low2;
        private double[] high2;
        private int[] points;

        private static final int NONE = -1;
        private static final int OUTSIDE = -2;

        Thinned(PlotRenderingInfo info, Graphics2D g2, Rectangle2D dataArea, XYPlot plot, XYDataset dataset) {
            super(info);
            // the device's pixel columns: an image drawn at twice the size has twice as many
            this.scaleX = g2.getTransform().getScaleX();
            this.g2ShearsOrTurns =
                    g2.getTransform().getShearX() != 0 || g2.getTransform().getShearY() != 0;
            this.translateX = g2.getTransform().getTranslateX();
            this.rowsPerUnitY = Math.abs(g2.getTransform().getScaleY());
            this.dataArea = dataArea;
            this.plot = plot;
            this.dataset = dataset;
        }

        @Override
        public void startSeriesPass(XYDataset data, int series, int firstItem, int lastItem, int pass, int passCount) {
            super.startSeriesPass(data, series, firstItem, lastItem, pass, passCount);
            first = firstItem;
            columns = null;
            if (data != dataset
                    || plot.getOrientation() != PlotOrientation.VERTICAL
                    || scaleX <= 0
                    || rowsPerUnitY == 0
                    || g2ShearsOrTurns
                    || lastItem < firstItem) {
                // turned, mirrored or sheared, the device columns are not along x: drawn whole
                return;
            }
            ValueAxis x = plot.getDomainAxisForDataset(plot.indexOf(data));
            ValueAxis y = plot.getRangeAxisForDataset(plot.indexOf(data));
            RectangleEdge xEdge = plot.getDomainAxisEdge();
            RectangleEdge yEdge = plot.getRangeAxisEdge();
            int n = lastItem - firstItem + 1;
            double[] value = new double[n];
            xPx = new double[n];
            xs = new double[n];
            ys = new double[n];
            columns = new int[n];
            // the columns of the data area and one beyond each side; points further out are stroked
            columnOffset = (int) Math.floor(dataArea.getMinX() * scaleX + translateX) - 1;
            int width = (int) Math.ceil(dataArea.getMaxX() * scaleX + translateX) + 2 - columnOffset;
            low = new double[width];
            high = new double[width];
            low2 = new double[width];
            high2 = new double[width];
            points = new int[width];
            java.util.Arrays.fill(low, Double.POSITIVE_INFINITY);
            java.util.Arrays.fill(high, Double.NEGATIVE_INFINITY);
            java.util.Arrays.fill(low2, Double.POSITIVE_INFINITY);
            java.util.Arrays.fill(high2, Double.NEGATIVE_INFINITY);
            for (int k = 0; k < n; k++) {
                value[k] = data.getYValue(series, firstItem + k);
                xs[k] = x.valueToJava2D(data.getXValue(series, firstItem + k), dataArea, xEdge);
                ys[k] = y.valueToJava2D(value[k], dataArea, yEdge);
                xPx[k] = xs[k] * scaleX + translateX;
                if (Double.isNaN(xPx[k]) || Double.isNaN(ys[k]) || Double.isInfinite(xPx[k])) {
                    columns[k] = NONE;
                    continue;
                }
                double c = Math.floor(xPx[k]) - columnOffset;
                columns[k] = c >= 0 && c < width ? (int) c : OUTSIDE;
                if (columns[k] >= 0) {
                    int i = columns[k];
                    points[i]++;
                    if (ys[k] < low[i]) {
                        low2[i] = low[i];
                        low[i] = ys[k];
                    } else {
                        low2[i] = Math.min(low2[i], ys[k]);
                    }
                    if (ys[k] > high[i]) {
                        high2[i] = high[i];
                        high[i] = ys[k];
                    } else {
                        high2[i] = Math.max(high2[i], ys[k]);
                    }
                }
            }
            kept = ColumnThinning.keep(xPx, value);
        }

        /** Whether a column (or NONE, OUTSIDE) is filled as a band. */
        private boolean band(int column) {
            return column >= 0
                    && points[column] >= BAND_POINTS
                    && (high2[column] - low2[column]) * rowsPerUnitY >= BAND_ROWS;
        }

        /**
         * Fills the band columns and strokes the rest: the line through the other columns' kept
         * points, every segment from one column to the next, and the parts of the segments inside
         * a band column that leave its band.
         */
        void drawSeries(Graphics2D g2, java.awt.Paint paint, Stroke stroke) {
            double halfWidth = stroke instanceof BasicStroke b ? b.getLineWidth() / 2 : 0.5;
            Path2D.Double bands = new Path2D.Double();
            for (int c = 0; c < points.length; c++) {
                if (band(c)) {
                    double left = (c + columnOffset - translateX) / scaleX;
                    double right = (c + 1 + columnOffset - translateX) / scaleX;
                    double top = low2[c] - halfWidth;
                    double bottom = high2[c] + halfWidth;
                    bands.moveTo(left, top);
                    bands.lineTo(right, top);
                    bands.lineTo(right, bottom);
                    bands.lineTo(left, bottom);
                    bands.closePath();
                }
            }
            Path2D.Double line = new Path2D.Double();
            // the point the line is at (its last point drawn), -1 when it is lifted
            int at = -1;
            // the last point of the line's course: kept, or in a band column
            int previous = -1;
            for (int k = 0; k < columns.length; k++) {
                int c = columns[k];
                if (c == NONE) {
                    at = -1;
                    previous = -1;
                    continue;
                }
                boolean inBand = band(c);
                if (!inBand && !kept[k]) {
                    continue;
                }
                if (previous >= 0 && (c != columns[previous] || !inBand)) {
                    if (at != previous) {
                        line.moveTo(xs[previous], ys[previous]);
                    }
                    line.lineTo(xs[k], ys[k]);
                    at = k;
                } else if (previous >= 0) {
                    // inside a band column: what leaves the band, towards the column's lone extremes
                    boolean toB = beyond(line, previous, k, low2[c], true);
                    toB |= beyond(line, previous, k, high2[c], false);
                    at = toB ? k : -1;
                }
                previous = k;
            }
            g2.setPaint(paint);
            g2.fill(bands);
            g2.setStroke(stroke);
            g2.draw(line);
        }

        /**
         * Adds the part of the segment from a to b above (or below) the row y, and says whether
         * it ends at b.
         */
        private boolean beyond(Path2D.Double line, int a, int b, double y, boolean above) {
            boolean aOut = above ? ys[a] < y : ys[a] > y;
            boolean bOut = above ? ys[b] < y : ys[b] > y;
            if (!aOut && !bOut) {
                return false;
            }
            double t = ys[b] == ys[a] ? 0 : (y - ys[a]) / (ys[b] - ys[a]);
            double xAt = xs[a] + (xs[b] - xs[a]) * t;
            line.moveTo(aOut ? xs[a] : xAt, aOut ? ys[a] : y);
            line.lineTo(bOut ? xs[b] : xAt, bOut ? ys[b] : y);
            return bOut;
        }
    }
}
