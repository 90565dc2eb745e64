package org.fresa.testing;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;

/** Measures on pictures the program drew (plots written as PNG, screenshots). */
public final class Pictures {

    private Pictures() {}

    /**
     * Width over height of a disc filled in one colour: its widest row over its tallest column of
     * exactly that colour, 1 for a disc drawn round. Smaller marks of the colour (a legend's
     * swatch) do not count as long as they are narrower and shorter than the disc.
     */
    public static double roundness(BufferedImage img, int rgb) {
        int widest = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            int n = 0;
            for (int x = 0; x < img.getWidth(); x++) {
                n += (img.getRGB(x, y) & 0xFFFFFF) == rgb ? 1 : 0;
            }
            widest = Math.max(widest, n);
        }
        int tallest = 0;
        for (int x = 0; x < img.getWidth(); x++) {
            int n = 0;
            for (int y = 0; y < img.getHeight(); y++) {
                n += (img.getRGB(x, y) & 0xFFFFFF) == rgb ? 1 : 0;
            }
            tallest = Math.max(tallest, n);
        }
        assertTrue(
                widest > 20 && tallest > 20, "the disc is drawn large enough to measure: " + widest + " x " + tallest);
        return (double) widest / tallest;
    }
}
