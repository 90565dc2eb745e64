package org.fresa.chart;

import java.awt.Graphics2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import org.jfree.chart.JFreeChart;
import org.jfree.svg.SVGGraphics2D;

/** Charts as PNG or SVG bytes, for files written headless and for Export in the GUI. */
public final class ChartFiles {
    private ChartFiles() {}

    public static void writePng(JFreeChart chart, int widthPx, int heightPx, OutputStream out) throws IOException {
        BufferedImage img = new BufferedImage(widthPx, heightPx, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        try {
            g.setRenderingHint(java.awt.RenderingHints.KEY_ANTIALIASING, java.awt.RenderingHints.VALUE_ANTIALIAS_ON);
            chart.draw(g, new Rectangle2D.Double(0, 0, widthPx, heightPx));
        } finally {
            g.dispose();
        }
        PngEncoder.write(img, out);
    }

    public static void writeSvg(JFreeChart chart, int widthPx, int heightPx, OutputStream out) throws IOException {
        SVGGraphics2D g = new SVGGraphics2D(widthPx, heightPx);
        chart.draw(g, new Rectangle2D.Double(0, 0, widthPx, heightPx));
        out.write(g.getSVGDocument().getBytes(StandardCharsets.UTF_8));
    }
}
