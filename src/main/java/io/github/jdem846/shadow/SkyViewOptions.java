package io.github.jdem846.shadow;

/**
 * Settings of the sky-view factor ({@link SkyView}).
 *
 * @param directions  the number of azimuths whose horizons are averaged, evenly spaced from north (0°, 360°/D, …);
 *                    4 to 360, default {@value #DEFAULT_DIRECTIONS}. A multiple of 4 keeps the result symmetric
 *                    under quarter turns of the grid
 * @param heightScale heights are multiplied by it before horizons are measured (the z-factor); positive
 */
public record SkyViewOptions(int directions, double heightScale) {

    /** The default number of directions. */
    public static final int DEFAULT_DIRECTIONS = 32;
    /** Fewest directions accepted. */
    public static final int MIN_DIRECTIONS = 4;
    /** Most directions accepted. */
    public static final int MAX_DIRECTIONS = 360;

    /** 32 directions, true heights. */
    public static final SkyViewOptions DEFAULTS = new SkyViewOptions(DEFAULT_DIRECTIONS, 1);

    /**
     * Checks the number of directions and that the height scale is positive.
     *
     * @param directions the number of azimuths whose horizons are averaged, evenly spaced from north (0°, 360°/D, …); 4
     *     to 360, default {@value #DEFAULT_DIRECTIONS}. A multiple of 4 keeps the result symmetric under quarter turns
     *     of the grid
     * @param heightScale heights are multiplied by it before horizons are measured (the z-factor); positive
     */
    public SkyViewOptions {
        if (directions < MIN_DIRECTIONS || directions > MAX_DIRECTIONS) {
            throw new IllegalArgumentException("sky-view directions must be between " + MIN_DIRECTIONS + " and "
                    + MAX_DIRECTIONS + " (default " + DEFAULT_DIRECTIONS + "), got " + directions);
        }
        if (!(heightScale > 0 && heightScale < Double.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("sky-view height scale must be a positive number (1 = true heights),"
                    + " got " + heightScale);
        }
    }

    /**
     * {@return the same options with {@code d} directions}
     *
     * @param d the number of azimuths, 4 to 360
     */
    public SkyViewOptions withDirections(int d) {
        return new SkyViewOptions(d, heightScale);
    }

    /**
     * {@return the same options with another height scale}
     *
     * @param scale factor on heights (the z-factor), positive
     */
    public SkyViewOptions withHeightScale(double scale) {
        return new SkyViewOptions(directions, scale);
    }

    /**
     * {@return the azimuth of direction {@code index}, degrees clockwise from north}
     *
     * @param index 0 … directions − 1
     */
    public double azimuth(int index) {
        return 360.0 * index / directions;
    }
}
