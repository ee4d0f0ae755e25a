package io.github.jdem846.shadow;

import java.util.Objects;

/**
 * Settings of a shadow computation. {@link #DEFAULTS} gives hard shadows, the article's step and sampling for
 * {@code march}, bilinear sampling for {@code sweep}, no Earth curvature.
 *
 * @param step                  ray step of {@code march} ({@link StepSize#ARTICLE} = eq. 9); ignored by the others
 * @param sampling              terrain sampling; {@link Sampling#AUTO} = nearest for {@code march}, bilinear for
 *                              {@code sweep}; {@code exact} is always bilinear
 * @param firstCellTest         {@code sweep} with bilinear sampling only: test the first cell of each ray on the
 *                              bilinear surface in eighth-cell steps, as {@code exact} does (true by default; false
 *                              only for the accuracy study). A nearest-sampling sweep never does it: on block
 *                              terrain it would see the next cell half a cell too close
 * @param softShadows           shadowed fraction of the sun's disk instead of 0/1
 * @param sunDiameterDegrees    apparent diameter of the sun's disk for soft shadows, 0.53° by default
 * @param earthCurvature        lower distant terrain by (1 − k)·d²/(2R) (curvature less refraction)
 * @param refractionCoefficient k, 0.13 by default
 * @param earthRadiusMeters     R; NaN = the mean radius of the grid's ellipsoid
 * @param terrainMinimum        {@code sweep} only: the lowest elevation of the whole file the grid was read from;
 *                              NaN = the grid's own. A grid read as a window of a file, with the halo of {@link
 *                              ShadowHalo#window}, gives exactly the whole file's mask in that window when this is
 *                              the file's minimum (the sweep ignores line heights below it, see {@code SunSweep})
 * @param thinFeatures          {@code sweep} only: also test each cell's own ray at the steepest terrain of its
 *                              strip, so that features one or two cells wide (a pole, a tree, a narrow ridge
 *                              across the sun) cast their whole shadow off the grid axes, as the marches see them;
 *                              off by default: it costs 1.6–2.5 times the sweep's time (docs/accuracy.md)
 */
public record ShadowOptions(StepSize step, Sampling sampling, boolean firstCellTest, boolean softShadows,
                            double sunDiameterDegrees, boolean earthCurvature, double refractionCoefficient,
                            double earthRadiusMeters, double terrainMinimum, boolean thinFeatures) {

    /** Apparent diameter of the sun, degrees. */
    public static final double SUN_DIAMETER_DEGREES = 0.53;
    /** The usual terrestrial refraction coefficient. */
    public static final double REFRACTION_COEFFICIENT = 0.13;

    /** Hard shadows, article step, automatic sampling, first-cell test on, no curvature. */
    public static final ShadowOptions DEFAULTS = new ShadowOptions(StepSize.ARTICLE, Sampling.AUTO, true, false,
            SUN_DIAMETER_DEGREES, false, REFRACTION_COEFFICIENT, Double.NaN, Double.NaN, false);

    /**
     * Checks that step and sampling are given and that the numbers are in range.
     *
     * @param step ray step of {@code march} ({@link StepSize#ARTICLE} = eq. 9); ignored by the others
     * @param sampling terrain sampling; {@link Sampling#AUTO} = nearest for {@code march}, bilinear for {@code sweep};
     *     {@code exact} is always bilinear
     * @param firstCellTest {@code sweep} with bilinear sampling only: test the first cell of each ray on the bilinear
     *     surface in eighth-cell steps, as {@code exact} does (true by default; false only for the accuracy study). A
     *     nearest-sampling sweep never does it: on block terrain it would see the next cell half a cell too close
     * @param softShadows shadowed fraction of the sun's disk instead of 0/1
     * @param sunDiameterDegrees apparent diameter of the sun's disk for soft shadows, 0.53° by default
     * @param earthCurvature lower distant terrain by (1 − k)·d²/(2R) (curvature less refraction)
     * @param refractionCoefficient k, 0.13 by default
     * @param earthRadiusMeters R; NaN = the mean radius of the grid's ellipsoid
     * @param terrainMinimum {@code sweep} only: the lowest elevation of the whole file the grid was read from; NaN =
     *     the grid's own. A grid read as a window of a file, with the halo of {@link ShadowHalo#window}, gives exactly
     *     the whole file's mask in that window when this is the file's minimum (the sweep ignores line heights below
     *     it, see {@code SunSweep})
     * @param thinFeatures {@code sweep} only: also test each cell's own ray at the steepest terrain of its strip, so
     *     that features one or two cells wide (a pole, a tree, a narrow ridge across the sun) cast their whole shadow
     *     off the grid axes, as the marches see them; off by default: it costs 1.6–2.5 times the sweep's time
     *     (docs/accuracy.md)
     */
    public ShadowOptions {
        Objects.requireNonNull(step, "step");
        Objects.requireNonNull(sampling, "sampling");
        if (!(sunDiameterDegrees >= 0 && sunDiameterDegrees <= 10)) {
            throw new IllegalArgumentException("sun diameter must be between 0 and 10 degrees, got "
                    + sunDiameterDegrees);
        }
        if (!(refractionCoefficient >= -1 && refractionCoefficient <= 1)) {
            throw new IllegalArgumentException("refraction coefficient must be between -1 and 1 (0.13 is usual),"
                    + " got " + refractionCoefficient);
        }
        if (!Double.isNaN(earthRadiusMeters) && !(earthRadiusMeters > 0 && earthRadiusMeters < 1e12)) {
            throw new IllegalArgumentException("planet radius must be a positive number of metres (or unset to use"
                    + " the grid's ellipsoid), got " + earthRadiusMeters);
        }
        if (Double.isInfinite(terrainMinimum)) {
            throw new IllegalArgumentException("terrain minimum must be a finite elevation (or NaN for the grid's"
                    + " own), got " + terrainMinimum);
        }
    }

    /**
     * A copy with another ray step for {@code march}.
     *
     * @param s the step
     * @return a new options record; this one is unchanged
     */
    public ShadowOptions withStep(StepSize s) {
        return new ShadowOptions(s, sampling, firstCellTest, softShadows, sunDiameterDegrees, earthCurvature,
                refractionCoefficient, earthRadiusMeters, terrainMinimum, thinFeatures);
    }

    /**
     * A copy with another terrain sampling.
     *
     * @param s the sampling
     * @return a new options record; this one is unchanged
     */
    public ShadowOptions withSampling(Sampling s) {
        return new ShadowOptions(step, s, firstCellTest, softShadows, sunDiameterDegrees, earthCurvature,
                refractionCoefficient, earthRadiusMeters, terrainMinimum, thinFeatures);
    }

    /**
     * A copy with the sweep's bilinear first-cell test on or off ({@link #firstCellTest()}).
     *
     * @param on true to test the first cell
     * @return a new options record; this one is unchanged
     */
    public ShadowOptions withFirstCellTest(boolean on) {
        return new ShadowOptions(step, sampling, on, softShadows, sunDiameterDegrees, earthCurvature,
                refractionCoefficient, earthRadiusMeters, terrainMinimum, thinFeatures);
    }

    /**
     * Soft shadows from a sun disk of {@link #sunDiameterDegrees()}.
     *
     * @param on true for soft shadows, false for 0/1 shadows
     * @return a new options record; this one is unchanged
     */
    public ShadowOptions withSoftShadows(boolean on) {
        return new ShadowOptions(step, sampling, firstCellTest, on, sunDiameterDegrees, earthCurvature,
                refractionCoefficient, earthRadiusMeters, terrainMinimum, thinFeatures);
    }

    /**
     * A copy with another apparent diameter of the sun's disk, for soft shadows.
     *
     * @param degrees the diameter in degrees, 0 to 10
     * @return a new options record; this one is unchanged
     */
    public ShadowOptions withSunDiameter(double degrees) {
        return new ShadowOptions(step, sampling, firstCellTest, softShadows, degrees, earthCurvature,
                refractionCoefficient, earthRadiusMeters, terrainMinimum, thinFeatures);
    }

    /**
     * Curvature and refraction on or off, with the given k and radius (NaN = the grid's ellipsoid).
     *
     * @param on true to lower distant terrain for curvature and refraction
     * @param k the refraction coefficient, −1 to 1
     * @param radiusMeters the planet's radius in metres, or NaN for the grid's ellipsoid
     * @return a new options record; this one is unchanged
     */
    public ShadowOptions withEarthCurvature(boolean on, double k, double radiusMeters) {
        return new ShadowOptions(step, sampling, firstCellTest, softShadows, sunDiameterDegrees, on, k,
                radiusMeters, terrainMinimum, thinFeatures);
    }

    /**
     * Curvature and refraction on or off with k = 0.13 and the grid's ellipsoid.
     *
     * @param on true to lower distant terrain for curvature and refraction
     * @return a new options record; this one is unchanged
     */
    public ShadowOptions withEarthCurvature(boolean on) {
        return withEarthCurvature(on, REFRACTION_COEFFICIENT, Double.NaN);
    }

    /**
     * The lowest elevation of the whole file a windowed grid was read from ({@link #terrainMinimum()}); NaN = the
     * grid's own.
     *
     * @param z the elevation, finite, or NaN
     * @return a new options record; this one is unchanged
     */
    public ShadowOptions withTerrainMinimum(double z) {
        return new ShadowOptions(step, sampling, firstCellTest, softShadows, sunDiameterDegrees, earthCurvature,
                refractionCoefficient, earthRadiusMeters, z, thinFeatures);
    }

    /**
     * The sweep's own-ray test for thin features ({@link #thinFeatures()}) on or off.
     *
     * @param on true to test the thin features
     * @return a new options record; this one is unchanged
     */
    public ShadowOptions withThinFeatures(boolean on) {
        return new ShadowOptions(step, sampling, firstCellTest, softShadows, sunDiameterDegrees, earthCurvature,
                refractionCoefficient, earthRadiusMeters, terrainMinimum, on);
    }
}
