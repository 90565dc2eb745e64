package org.fresa.ui;

/**
 * Which points of a polyline a screen needs (an M4 decimation): of each run of consecutive points
 * that fall into one pixel column, the first, the last, the lowest and the highest (these two
 * with their neighbours, at most eight points per run). The polyline
 * through the points kept covers, in every column, exactly the rows the full one covers: inside
 * a run it passes through the run's lowest and highest points and never leaves the column, and
 * the segments from one run to the next join the same two points as before, so a spike of one
 * point stays drawn. A point with no value (NaN in x or y) breaks the line; the first of each
 * stretch of such points is kept, so the gaps stay where they were.
 *
 * <p>A chart of 6518 points across 400 columns thus draws at most 3200 of them per curve, and the
 * time of drawing follows the width of the screen rather than the length of the path.
 */
final class ColumnThinning {

    private ColumnThinning() {}

    /**
     * @param xPx each point's horizontal position on the device (pixels; its column is the floor),
     *     NaN where the point has no value
     * @param y each point's value (or its vertical position: only the order matters), NaN where it
     *     has none
     * @return for each point whether it is drawn; the first and the last point always are
     */
    static boolean[] keep(double[] xPx, double[] y) {
        if (xPx.length != y.length) {
            throw new IllegalArgumentException("x has " + xPx.length + " points, y " + y.length);
        }
        int n = y.length;
        boolean[] kept = new boolean[n];
        int i = 0;
        while (i < n) {
            if (Double.isNaN(xPx[i]) || Double.isNaN(y[i])) {
                // one point with no value breaks the line as well as many
                kept[i] = true;
                i++;
                while (i < n && (Double.isNaN(xPx[i]) || Double.isNaN(y[i]))) {
                    i++;
                }
                continue;
            }
            double column = Math.floor(xPx[i]);
            int first = i;
            int low = i;
            int high = i;
            i++;
            while (i < n && !Double.isNaN(y[i]) && Math.floor(xPx[i]) == column) {
                if (y[i] < y[low]) {
                    low = i;
                }
                if (y[i] > y[high]) {
                    high = i;
                }
                i++;
            }
            int last = i - 1;
            kept[first] = true;
            kept[last] = true;
            // the extremes with their neighbours: a spike's two flanks keep their slope, so its
            // anti-aliased edge into the next column is the one the full curve draws
            for (int e : new int[] {low, high}) {
                kept[Math.max(first, e - 1)] = true;
                kept[e] = true;
                kept[Math.min(last, e + 1)] = true;
            }
        }
        if (n > 0) {
            kept[0] = true;
            kept[n - 1] = true;
        }
        return kept;
    }
}
