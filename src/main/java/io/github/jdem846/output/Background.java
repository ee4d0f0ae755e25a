package io.github.jdem846.output;

/** Lays non-premultiplied ARGB pixels on a background colour (Porter–Duff "over", straight alpha, rounded). */
final class Background {

    private Background() {
    }

    /**
     * @param argb       the pixels (not modified)
     * @param length     how many of them to lay
     * @param background non-premultiplied 0xAARRGGBB under them
     * @return a new array of {@code length} pixels: each pixel over the background
     */
    static int[] under(int[] argb, int length, int background) {
        int[] out = new int[length];
        for (int i = 0; i < length; i++) {
            out[i] = over(argb[i], background);
        }
        return out;
    }

    /** One pixel over the background. */
    static int over(int top, int background) {
        int a = top >>> 24;
        if (a == 255) {
            return top;
        }
        int b = background >>> 24;
        // Output alpha in 255² units: a·255 + b·(255 − a).
        int alpha2 = a * 255 + b * (255 - a);
        if (alpha2 == 0) {
            return 0;
        }
        int r = channel(top >>> 16 & 0xff, a, background >>> 16 & 0xff, b, alpha2);
        int g = channel(top >>> 8 & 0xff, a, background >>> 8 & 0xff, b, alpha2);
        int bl = channel(top & 0xff, a, background & 0xff, b, alpha2);
        int alpha = (alpha2 + 127) / 255;
        return alpha << 24 | r << 16 | g << 8 | bl;
    }

    private static int channel(int c, int a, int cb, int b, int alpha2) {
        long num = (long) c * a * 255 + (long) cb * b * (255 - a);
        return (int) ((num + alpha2 / 2) / alpha2);
    }
}
