package io.github.jdem846.render;

import io.github.jdem846.raster.GridRequestException;
import java.util.Locale;

/**
 * The size of the output picture relative to the DEM cells it covers: full resolution, a target width and/or height
 * (the other follows the aspect ratio), or a scale factor.
 *
 * <p>A size asked for has at most {@link #MAX_SIDE} pixels on a side and {@link #MAX_PIXELS} in all (one Java
 * array of ARGB pixels); a scale must leave at least one pixel on each side. The constructor and factories check
 * what is known without the grid, {@link #pixelsFor} the rest.
 *
 * @param width  target width in pixels (1 to {@link #MAX_SIDE}), or 0 when not given
 * @param height target height in pixels (1 to {@link #MAX_SIDE}), or 0 when not given
 * @param scale  pixels per DEM cell (0.5 = half size; above 0, at most {@link #MAX_SIDE}), or 0 when not given
 */
public record OutputSize(int width, int height, double scale) {

    /** One pixel per DEM cell. */
    public static final OutputSize FULL = new OutputSize(0, 0, 0);

    /** Most pixels on a side of a picture whose size is asked for. */
    public static final int MAX_SIDE = 100_000;

    /** Most pixels in a picture: the longest Java array, which holds them (one int per ARGB pixel). */
    public static final long MAX_PIXELS = Integer.MAX_VALUE - 8L;

    /**
     * Checks the sides and the scale, and that a scale is not given with a width or height.
     *
     * @param width target width in pixels (1 to {@link #MAX_SIDE}), or 0 when not given
     * @param height target height in pixels (1 to {@link #MAX_SIDE}), or 0 when not given
     * @param scale pixels per DEM cell (0.5 = half size; above 0, at most {@link #MAX_SIDE}), or 0 when not given
     */
    public OutputSize {
        requireSide(width, "width", true);
        requireSide(height, "height", true);
        if (scale != 0) {
            requireScale(scale);
        }
        if (scale > 0 && (width > 0 || height > 0)) {
            throw new IllegalArgumentException("give either a scale or a width/height, not both");
        }
        if ((long) width * height > MAX_PIXELS) {
            throw new IllegalArgumentException("output of " + width + "×" + height + " = " + (long) width * height
                    + " pixels is more than a picture can hold (at most " + MAX_PIXELS + " pixels)");
        }
    }

    /**
     * A target width; the height follows the aspect ratio.
     *
     * @param width pixels across, 1 to {@link #MAX_SIDE}
     * @return the size
     */
    public static OutputSize width(int width) {
        return new OutputSize(requireSide(width, "width", false), 0, 0);
    }

    /**
     * A target height; the width follows the aspect ratio.
     *
     * @param height pixels down, 1 to {@link #MAX_SIDE}
     * @return the size
     */
    public static OutputSize height(int height) {
        return new OutputSize(0, requireSide(height, "height", false), 0);
    }

    /**
     * A scale factor.
     *
     * @param scale pixels per DEM cell, above 0
     * @return the size
     */
    public static OutputSize scale(double scale) {
        return new OutputSize(0, 0, requireScale(scale));
    }

    /**
     * The pixel size {w, h} for {@code cols × rows} DEM cells (each at least 1; the whole grid when no size was
     * asked for).
     *
     * @throws GridRequestException when the size asked for gives more than {@link #MAX_SIDE} pixels on a side or
     *                              {@link #MAX_PIXELS} in all, or a scale leaves less than one pixel on a side
     * @param cols the grid's columns
     * @param rows the grid's rows
     * @return {width, height} in pixels
     */
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
        long w = Math.round(cols * sx);
        long h = Math.round(rows * sy);
        if (scale > 0 && (w < 1 || h < 1)) {
            throw new GridRequestException(GridRequestException.Part.SIZE, String.format(Locale.ROOT,
                    "scale %s makes the %d×%d cells less than one pixel %s; the smallest scale for them is %s",
                    scale, cols, rows, w < 1 ? "wide" : "high", roundUp(0.5 / Math.min(cols, rows))));
        }
        w = Math.max(1, w);
        h = Math.max(1, h);
        if (w > MAX_SIDE || h > MAX_SIDE || w * h > MAX_PIXELS) {
            throw new GridRequestException(GridRequestException.Part.SIZE, "output of " + w + "×" + h + " pixels"
                    + " for " + cols + "×" + rows + " cells is too large: at most " + MAX_SIDE + " pixels per side"
                    + " and " + MAX_PIXELS + " in all");
        }
        return new int[] {(int) w, (int) h};
    }

    /** {@code v} when it is a side in pixels: 1 to {@link #MAX_SIDE}, or 0 (not given) when {@code zeroAllowed}. */
    private static int requireSide(int v, String what, boolean zeroAllowed) {
        if (v > MAX_SIDE || v < (zeroAllowed ? 0 : 1)) {
            throw new IllegalArgumentException("output " + what + " must be 1 to " + MAX_SIDE + " pixels, got " + v);
        }
        return v;
    }

    /** {@code s} when it is a scale: above 0 and at most {@link #MAX_SIDE}. */
    private static double requireScale(double s) {
        if (!(s > 0 && s <= MAX_SIDE)) {
            throw new IllegalArgumentException("scale must be a number of pixels per cell above 0 and at most "
                    + MAX_SIDE + ", got " + s);
        }
        return s;
    }

    /** {@code v} rounded up to three significant digits, for a message. */
    private static String roundUp(double v) {
        java.math.BigDecimal d = new java.math.BigDecimal(v).round(new java.math.MathContext(3,
                java.math.RoundingMode.CEILING));
        return d.stripTrailingZeros().toPlainString();
    }
}
