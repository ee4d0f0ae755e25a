package io.github.jdem846.render;

/**
 * The size of the output picture relative to the DEM cells it covers: full resolution, a target width and/or height
 * (the other follows the aspect ratio), or a scale factor.
 *
 * @param width  target width in pixels, or 0 when not given
 * @param height target height in pixels, or 0 when not given
 * @param scale  pixels per DEM cell (0.5 = half size), or 0 when not given
 */
public record OutputSize(int width, int height, double scale) {

    /** One pixel per DEM cell. */
    public static final OutputSize FULL = new OutputSize(0, 0, 0);

    public OutputSize {
        if (width < 0 || height < 0) {
            throw new IllegalArgumentException("output width and height must be positive, got " + width + "×"
                    + height);
        }
        if (!(scale >= 0) || Double.isInfinite(scale)) {
            throw new IllegalArgumentException("scale must be a positive number, got " + scale);
        }
        if (scale > 0 && (width > 0 || height > 0)) {
            throw new IllegalArgumentException("give either a scale or a width/height, not both");
        }
    }

    /** A target width; the height follows the aspect ratio. */
    public static OutputSize width(int width) {
        return new OutputSize(requirePositive(width, "width"), 0, 0);
    }

    /** A target height; the width follows the aspect ratio. */
    public static OutputSize height(int height) {
        return new OutputSize(0, requirePositive(height, "height"), 0);
    }

    /** A scale factor: pixels per DEM cell. */
    public static OutputSize scale(double scale) {
        if (!(scale > 0) || Double.isInfinite(scale)) {
            throw new IllegalArgumentException("scale must be a positive number, got " + scale);
        }
        return new OutputSize(0, 0, scale);
    }

    /** The pixel size {w, h} for {@code cols × rows} DEM cells (each at least 1). */
    public int[] pixelsFor(int cols, int rows) {
        double sx;
        double sy;
        if (scale > 0) {
            sx = scale;
            sy = scale;
        } else if (width > 0 && height > 0) {
            sx = (double) width / cols;
            sy = (double) height / rows;
        } else if (width > 0) {
            sx = (double) width / cols;
            sy = sx;
        } else if (height > 0) {
            sy = (double) height / rows;
            sx = sy;
        } else {
            return new int[] {cols, rows};
        }
        long w = Math.max(1, Math.round(cols * sx));
        long h = Math.max(1, Math.round(rows * sy));
        if (w > 100_000 || h > 100_000) {
            throw new IllegalArgumentException("output of " + w + "×" + h + " pixels is too large (at most 100000 "
                    + "per side); choose a smaller width, height or scale");
        }
        return new int[] {(int) w, (int) h};
    }

    private static int requirePositive(int v, String what) {
        if (v < 1) {
            throw new IllegalArgumentException("output " + what + " must be at least 1 pixel, got " + v);
        }
        return v;
    }
}
