package io.github.jdem846.tint;

/** Packing of non-premultiplied 0xAARRGGBB colours. */
final class Argb {

    /** Fully transparent black, the colour of no-data unless a ramp names another. */
    static final int TRANSPARENT = 0;

    private Argb() {
    }

    static int of(int red, int green, int blue, int alpha) {
        return alpha << 24 | red << 16 | green << 8 | blue;
    }

    /** An opaque colour from 0xRRGGBB. */
    static int opaque(int rgb) {
        return 0xFF000000 | rgb;
    }

    static int alpha(int argb) {
        return argb >>> 24;
    }

    static int red(int argb) {
        return argb >> 16 & 0xFF;
    }

    static int green(int argb) {
        return argb >> 8 & 0xFF;
    }

    static int blue(int argb) {
        return argb & 0xFF;
    }

    /** {@code #RRGGBB} or {@code #RRGGBBAA} when not opaque, for messages and docs. */
    static String format(int argb) {
        return alpha(argb) == 0xFF ? String.format("#%06X", argb & 0xFFFFFF)
                : String.format("#%06X%02X", argb & 0xFFFFFF, alpha(argb));
    }
}
