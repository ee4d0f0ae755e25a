package io.github.jdem846.tiles;

/**
 * The zoom levels of a tile pyramid, {@code min} to {@code max} inclusive.
 *
 * @param min the first zoom, 0 to {@link WebMercatorTile#MAX_ZOOM}
 * @param max the last zoom, {@code min} to {@link WebMercatorTile#MAX_ZOOM}
 */
public record ZoomRange(int min, int max) {

    /**
     * Checks that 0 ≤ min ≤ max ≤ {@link WebMercatorTile#MAX_ZOOM}.
     *
     * @param min the first zoom, 0 to {@link WebMercatorTile#MAX_ZOOM}
     * @param max the last zoom, {@code min} to {@link WebMercatorTile#MAX_ZOOM}
     */
    public ZoomRange {
        if (min < 0 || max > WebMercatorTile.MAX_ZOOM || min > max) {
            throw new IllegalArgumentException("zoom levels must be 0 to " + WebMercatorTile.MAX_ZOOM
                    + " with the first not above the last, got " + min + "-" + max);
        }
    }

    /**
     * Parses {@code "MIN-MAX"} or a single level {@code "Z"}.
     *
     * @param text the text, e.g. {@code "8-12"} or {@code "10"}
     * @return the range
     * @throws IllegalArgumentException naming what is wrong
     */
    public static ZoomRange parse(String text) {
        String t = text.strip();
        int dash = t.indexOf('-', 1);
        try {
            if (dash < 0) {
                int z = Integer.parseInt(t);
                return new ZoomRange(z, z);
            }
            return new ZoomRange(Integer.parseInt(t.substring(0, dash).strip()),
                    Integer.parseInt(t.substring(dash + 1).strip()));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("'" + text + "' is not a zoom level or range: give e.g. 0-12 or 10");
        }
    }

    /** {@return how many levels} */
    public int count() {
        return max - min + 1;
    }

    @Override
    public String toString() {
        return min == max ? Integer.toString(min) : min + "-" + max;
    }
}
