package org.fresa.chart;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.SplittableRandom;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;

class PngEncoderTest {

    @Test
    void imageIoReadsBackEveryPixelOfRandomImages() throws IOException {
        SplittableRandom rnd = new SplittableRandom(3);
        // sizes around the 64 KiB chunk boundary and one-pixel images
        int[][] sizes = {{1, 1}, {1, 7}, {9, 1}, {37, 23}, {200, 150}, {513, 97}};
        for (int[] s : sizes) {
            BufferedImage img = new BufferedImage(s[0], s[1], BufferedImage.TYPE_INT_RGB);
            for (int y = 0; y < s[1]; y++) {
                for (int x = 0; x < s[0]; x++) {
                    img.setRGB(x, y, rnd.nextInt(4) == 0 ? 0xFFFFFF : rnd.nextInt());
                }
            }
            assertSamePixels(img, roundTrip(img));
        }
    }

    @Test
    void aChartLikePictureReadsBackAndIsNoLargerThanImageIosFile() throws IOException {
        BufferedImage img = new BufferedImage(1000, 520, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, 1000, 520);
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(Color.LIGHT_GRAY);
        for (int x = 50; x < 1000; x += 100) {
            g.drawLine(x, 20, x, 500);
        }
        g.setStroke(new BasicStroke(1.5f));
        g.setColor(Color.RED);
        java.awt.geom.Path2D.Double path = new java.awt.geom.Path2D.Double();
        path.moveTo(50, 260);
        for (int x = 50; x < 950; x++) {
            path.lineTo(x, 260 + 200 * Math.sin(x / 40.0));
        }
        g.draw(path);
        g.setColor(Color.BLACK);
        g.drawString("Joint values, IRB 140", 400, 15);
        g.dispose();
        byte[] ours = encode(img);
        assertSamePixels(img, ImageIO.read(new ByteArrayInputStream(ours)));
        ByteArrayOutputStream theirs = new ByteArrayOutputStream();
        ImageIO.write(img, "png", theirs);
        assertTrue(ours.length <= theirs.size() * 1.25, ours.length + " bytes against ImageIO's " + theirs.size());
    }

    @Test
    void refusesOtherPixelLayouts() {
        BufferedImage argb = new BufferedImage(4, 4, BufferedImage.TYPE_INT_ARGB);
        assertThrows(IllegalArgumentException.class, () -> PngEncoder.write(argb, new ByteArrayOutputStream()));
    }

    private static BufferedImage roundTrip(BufferedImage img) throws IOException {
        byte[] png = encode(img);
        assertEquals((byte) 0x89, png[0]);
        return ImageIO.read(new ByteArrayInputStream(png));
    }

    private static byte[] encode(BufferedImage img) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        PngEncoder.write(img, out);
        return out.toByteArray();
    }

    private static void assertSamePixels(BufferedImage expected, BufferedImage actual) {
        assertEquals(expected.getWidth(), actual.getWidth());
        assertEquals(expected.getHeight(), actual.getHeight());
        int w = expected.getWidth();
        int h = expected.getHeight();
        int[] e = expected.getRGB(0, 0, w, h, null, 0, w);
        int[] a = actual.getRGB(0, 0, w, h, null, 0, w);
        for (int i = 0; i < e.length; i++) {
            e[i] |= 0xFF000000;
            a[i] |= 0xFF000000;
        }
        assertArrayEquals(e, a);
    }
}
