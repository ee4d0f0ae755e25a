package io.github.jdem846.shadow;

/**
 * Settings of the sky-view factor ({@link SkyView}).
 *
 * @param directions  the number of azimuths whose horizons are averaged, evenly spaced from north (0°, 360°/D, …);
 *                    4 to 360, default {@value #DEFAULT_DIRECTIONS}. A multiple of 4 keeps the result symmetric
 *                    under quarter turns of the grid
 * @param heightScale heights are multiplied by it before horizons are measured (the z-factor); positive
 * @param radius      the search radius in ground metres: terrain farther from a cell along an azimuth does not
 *                    count for its horizon (the cell's own first step always does); positive, {@link #UNBOUNDED}
 *                    (the default) for the whole grid
 */
public record SkyViewOptions(int directions, double heightScale, double radius) {

    /** The default number of directions. */
    public static final int DEFAULT_DIRECTIONS = 32;
    /** Fewest directions accepted. */
    public static final int MIN_DIRECTIONS = 4;
    /** Most directions accepted. */
    public static final int MAX_DIRECTIONS = 360;
    /** The radius that searches the whole grid. */
    public static final double UNBOUNDED = Double.POSITIVE_INFINITY;

    /** 32 directions, true heights, no search radius. */
    public static final SkyViewOptions DEFAULTS = new SkyViewOptions(DEFAULT_DIRECTIONS, 1);

    /**
     * Checks the number of directions and that the height scale and the radius are positive.
     *
     * @param directions the number of azimuths whose horizons are averaged, evenly spaced from north (0°, 360°/D, …); 4
     *     to 360, default {@value #DEFAULT_DIRECTIONS}. A multiple of 4 keeps the result symmetric under quarter turns
     *     of the grid
     * @param heightScale heights are multiplied by it before horizons are measured (the z-factor); positive
     * @param radius the search radius in ground metres: terrain farther from a cell along an azimuth does not count
     *     for its horizon (the cell's own first step always does); positive, {@link #UNBOUNDED} for the whole grid
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
        if (!(radius > 0)) {
            throw new IllegalArgumentException("sky-view search radius must be a positive number of metres (or"
                    + " unbounded), got " + radius);
        }
    }

    /**
     * Options without a search radius.
     *
     * @param directions  the number of azimuths, 4 to 360
     * @param heightScale the z-factor, positive
     */
    public SkyViewOptions(int directions, double heightScale) {
        this(directions, heightScale, UNBOUNDED);
    }

    /**
     * {@return the same options with {@code d} directions}
     *
     * @param d the number of azimuths, 4 to 360
     */
    public SkyViewOptions withDirections(int d) {
        return new SkyViewOptions(d, heightScale, radius);
    }

    /**
     * {@return the same options with another height scale}
     *
     * @param scale factor on heights (the z-factor), positive
     */
    public SkyViewOptions withHeightScale(double scale) {
        return new SkyViewOptions(directions, scale, radius);
    }

    /**
     * {@return the same options with another search radius}
     *
     * @param metres the radius in ground metres, positive; {@link #UNBOUNDED} for the whole grid
     */
    public SkyViewOptions withRadius(double metres) {
        return new SkyViewOptions(directions, heightScale, metres);
    }

    /** {@return true when horizons are searched within a finite radius} */
    public boolean bounded() {
        return radius < UNBOUNDED;
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
