package io.github.jdem846.view;

/**
 * How the terrain of a perspective view is drawn.
 *
 * @param exaggeration vertical exaggeration: elevations are multiplied by it, above 0 and at most 1000
 * @param skyTop       the background colour straight up (0xAARRGGBB); in globe mode, the colour of space
 * @param skyHorizon   the background colour at and below the horizon; in globe mode unused
 * @param bodyColor    in globe mode, the colour of the body's ellipsoid around the terrain
 * @param globe        true: the terrain lies on the body's ellipsoid at its latitudes and longitudes (radius + height
 *                     × exaggeration), the rest of the body drawn plain; false: on a plane, distances measured on
 *                     the ground in metres
 * @param base         on a plane, draw walls from the terrain's edges down to a base below its lowest point (a
 *                     tenth of its height range, and at least 1 m, lower), in the edge's colours darkened
 */
public record ViewOptions(double exaggeration, int skyTop, int skyHorizon, int bodyColor, boolean globe,
                          boolean base) {

    /** Default sky straight up: a clear blue. */
    public static final int SKY_TOP = 0xFF5B8CC6;
    /** Default sky at the horizon: pale haze. */
    public static final int SKY_HORIZON = 0xFFDCE6EE;
    /** Default space around a globe. */
    public static final int SPACE = 0xFF000000;
    /** Default plain body around a globe's terrain. */
    public static final int BODY = 0xFF3A5270;

    /**
     * Checks that the vertical exaggeration is above 0 and at most 1000.
     *
     * @param exaggeration vertical exaggeration: elevations are multiplied by it, above 0 and at most 1000
     * @param skyTop the background colour straight up (0xAARRGGBB); in globe mode, the colour of space
     * @param skyHorizon the background colour at and below the horizon; in globe mode unused
     * @param bodyColor in globe mode, the colour of the body's ellipsoid around the terrain
     * @param globe true: the terrain lies on the body's ellipsoid at its latitudes and longitudes (radius + height ×
     *     exaggeration), the rest of the body drawn plain; false: on a plane, distances measured on the ground in
     *     metres
     * @param base on a plane, draw walls from the terrain's edges down to a base below its lowest point (a tenth of its
     *     height range, and at least 1 m, lower), in the edge's colours darkened
     */
    public ViewOptions {
        if (!(exaggeration > 0 && exaggeration <= 1000)) {
            throw new IllegalArgumentException("vertical exaggeration must be above 0 and at most 1000, got "
                    + exaggeration);
        }
    }

    /**
     * A flat view: exaggeration 1, blue sky with a hazy horizon, a base under the terrain.
     *
     * @return the options
     */
    public static ViewOptions defaults() {
        return new ViewOptions(1, SKY_TOP, SKY_HORIZON, BODY, false, true);
    }

    /**
     * A copy with or without the base.
     *
     * @param value true for walls from the terrain's edges down to a base (on a plane)
     * @return the new options
     */
    public ViewOptions withBase(boolean value) {
        return new ViewOptions(exaggeration, skyTop, skyHorizon, bodyColor, globe, value);
    }

    /**
     * A copy with another vertical exaggeration.
     *
     * @param value above 0, at most 1000
     * @return the new options
     */
    public ViewOptions withExaggeration(double value) {
        return new ViewOptions(value, skyTop, skyHorizon, bodyColor, globe, base);
    }

    /**
     * A copy with another background: a gradient from {@code top} (straight up) to {@code horizon}.
     *
     * @param top     0xAARRGGBB straight up (space in globe mode)
     * @param horizon 0xAARRGGBB at and below the horizon
     * @return the new options
     */
    public ViewOptions withSky(int top, int horizon) {
        return new ViewOptions(exaggeration, top, horizon, bodyColor, globe, base);
    }

    /**
     * A copy in globe mode or not; switching it on also makes the background black space.
     *
     * @param value true for the terrain on the body's ellipsoid
     * @return the new options
     */
    public ViewOptions withGlobe(boolean value) {
        return value ? new ViewOptions(exaggeration, SPACE, SPACE, bodyColor, true, base)
                : new ViewOptions(exaggeration, skyTop, skyHorizon, bodyColor, false, base);
    }
}
