package org.fresa.chart;

import java.util.List;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;
import org.jfree.chart.JFreeChart;

/**
 * The nested outlines of a graded size run: every size's outline, the base size drawn bold, each
 * labelled with its size at its toe (the point furthest along the length axis).
 */
public final class GradingChart {

    /** One size's outlines. */
    public record SizeOutline(String label, List<Contour> contours, boolean base) {
        public SizeOutline {
            contours = List.copyOf(contours);
        }
    }

    private GradingChart() {}

    /**
     * The scene of the nested outlines.
     *
     * @param lengthAxis unit vector from heel to toe, to place the labels
     */
    public static PlotScene scene(String title, List<SizeOutline> sizes, Vec2 lengthAxis) {
        PlotScene s = PlotScene.empty(title);
        for (SizeOutline o : sizes) {
            for (Contour c : o.contours()) {
                s = s.withContour("size " + o.label(), o.base() ? PlotScene.Style.OUTLINE : PlotScene.Style.FEED, c);
            }
            if (!o.contours().isEmpty()) {
                s = s.withLabel(toe(o.contours().get(0), lengthAxis).plus(lengthAxis.times(2)), o.label());
            }
        }
        return s;
    }

    /** The chart of {@link #scene}. */
    public static JFreeChart create(String title, List<SizeOutline> sizes, Vec2 lengthAxis) {
        return ToolpathChart.create(scene(title, sizes, lengthAxis));
    }

    /** The nested outlines as a PNG image at equal scale (via {@link ToolpathChart}), for headless runs. */
    public static void writePng(
            String title, List<SizeOutline> sizes, Vec2 lengthAxis, int widthPx, int heightPx, java.io.OutputStream out)
            throws java.io.IOException {
        ToolpathChart.writePng(scene(title, sizes, lengthAxis), widthPx, heightPx, out);
    }

    private static Vec2 toe(Contour c, Vec2 axis) {
        Vec2 best = c.get(0).start();
        for (Curve2 k : c.curves()) {
            for (int i = 0; i <= 16; i++) {
                Vec2 p = k.pointAt(i / 16.0);
                if (p.dot(axis) > best.dot(axis)) {
                    best = p;
                }
            }
        }
        return best;
    }
}
