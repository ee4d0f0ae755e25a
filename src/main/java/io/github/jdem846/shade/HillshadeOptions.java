package io.github.jdem846.shade;

import io.github.jdem846.internal.Brightness;

/**
 * The knobs of the hillshade methods, immutable, with the original jDem846's defaults ({@link #DEFAULTS}).
 *
 * <p>Which method reads which field:
 * <ul>
 *   <li>{@code zFactor} (vertical exaggeration) and {@code horizontalScale}: every method;</li>
 *   <li>{@code lightMultiple}: {@link HillshadeMethod#JDEM846} only, when building the normals;</li>
 *   <li>{@code relativeLightIntensity}, {@code relativeDarkIntensity}, {@code spotExponent}: the jDem846 tone
 *       ({@link #tone(double)}), applied after illumination (and after any cast shadow), before eq. 8.</li>
 * </ul>
 *
 * @param zFactor                vertical exaggeration: heights are multiplied by it before any normal or gradient
 *                               is computed (gdaldem {@code -z}); positive, at most 1e6
 * @param lightMultiple          the original's {@code lightingMultiple}: a second height factor used only for the
 *                               jDem846 normals (0.75 flattens them a little); 0 to 1e6
 * @param relativeLightIntensity factor for a positive illumination (the original's {@code relativeLightIntensity},
 *                               0.75); 0 to 1
 * @param relativeDarkIntensity  factor for a negative illumination ({@code relativeDarkIntensity}, 1.0); 0 to 1
 * @param spotExponent           sign-preserving exponent, sign(d)·|d|^spot ({@code spotExponent}, 1); 0.01 to 128
 * @param horizontalScale        NaN (the default): horizontal cell sizes are the metric sizes of the DEM's geometry,
 *                               per row ({@code cellWidthMeters(row)}, {@code cellHeightMeters(row)}). A positive
 *                               number s: the cell sizes are the grid's cell size in CRS units times s, exactly as
 *                               gdaldem's {@code -s s} (e.g. 111120 for degrees → metres at every latitude)
 */
public record HillshadeOptions(double zFactor, double lightMultiple, double relativeLightIntensity,
                               double relativeDarkIntensity, double spotExponent, double horizontalScale) {

    /** Largest accepted z-factor and light multiple: keeps every intermediate product far from overflow. */
    public static final double MAX_HEIGHT_FACTOR = 1e6;

    /**
     * The original's defaults (era B {@code lightingContext.*}): z-factor 1, light multiple 0.75, light 0.75,
     * dark 1.0, spot 1, metric cell sizes.
     */
    public static final HillshadeOptions DEFAULTS = new HillshadeOptions(1.0, 0.75, 0.75, 1.0, 1.0, Double.NaN);

    /**
     * Validates every field, naming what is wrong and what would be right.
     *
     * @param zFactor vertical exaggeration: heights are multiplied by it before any normal or gradient is computed
     *     (gdaldem {@code -z}); positive, at most 1e6
     * @param lightMultiple the original's {@code lightingMultiple}: a second height factor used only for the jDem846
     *     normals (0.75 flattens them a little); 0 to 1e6
     * @param relativeLightIntensity factor for a positive illumination (the original's {@code relativeLightIntensity},
     *     0.75); 0 to 1
     * @param relativeDarkIntensity factor for a negative illumination ({@code relativeDarkIntensity}, 1.0); 0 to 1
     * @param spotExponent sign-preserving exponent, sign(d)·|d|^spot ({@code spotExponent}, 1); 0.01 to 128
     * @param horizontalScale NaN (the default): horizontal cell sizes are the metric sizes of the DEM's geometry, per
     *     row ({@code cellWidthMeters(row)}, {@code cellHeightMeters(row)}). A positive number s: the cell sizes are
     *     the grid's cell size in CRS units times s, exactly as gdaldem's {@code -s s} (e.g. 111120 for degrees →
     *     metres at every latitude)
     */
    public HillshadeOptions {
        if (!(zFactor > 0 && zFactor <= MAX_HEIGHT_FACTOR)) {
            throw new IllegalArgumentException("z-factor must be a number > 0 and ≤ " + MAX_HEIGHT_FACTOR
                    + " (1 = true heights), got " + zFactor);
        }
        if (!(lightMultiple >= 0 && lightMultiple <= MAX_HEIGHT_FACTOR)) {
            throw new IllegalArgumentException("light multiple must be between 0 and " + MAX_HEIGHT_FACTOR
                    + " (the original used 0.75), got " + lightMultiple);
        }
        if (!(relativeLightIntensity >= 0 && relativeLightIntensity <= 1)) {
            throw new IllegalArgumentException("relative light intensity must be between 0 and 1 (default 0.75), got "
                    + relativeLightIntensity);
        }
        if (!(relativeDarkIntensity >= 0 && relativeDarkIntensity <= 1)) {
            throw new IllegalArgumentException("relative dark intensity must be between 0 and 1 (default 1.0), got "
                    + relativeDarkIntensity);
        }
        if (!(spotExponent >= 0.01 && spotExponent <= 128)) {
            throw new IllegalArgumentException("spot exponent must be between 0.01 and 128 (default 1), got "
                    + spotExponent);
        }
        if (!Double.isNaN(horizontalScale) && !(horizontalScale > 0 && horizontalScale < Double.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("horizontal scale must be a positive number (e.g. 111120 for a grid in"
                    + " degrees), or NaN for the DEM's metric cell size; got " + horizontalScale);
        }
    }

    /**
     * The same options with another vertical exaggeration.
     *
     * @param z the z-factor, positive, at most 1e6
     * @return a new options record; this one is unchanged
     */
    public HillshadeOptions withZFactor(double z) {
        return new HillshadeOptions(z, lightMultiple, relativeLightIntensity, relativeDarkIntensity, spotExponent,
                horizontalScale);
    }

    /**
     * The same options with another light multiple (jDem846 normals only).
     *
     * @param m the light multiple, 0 to 1e6
     * @return a new options record; this one is unchanged
     */
    public HillshadeOptions withLightMultiple(double m) {
        return new HillshadeOptions(zFactor, m, relativeLightIntensity, relativeDarkIntensity, spotExponent,
                horizontalScale);
    }

    /**
     * The same options with other relative light and dark intensities.
     *
     * @param light the relative light intensity, 0 to 1
     * @param dark the relative dark intensity, 0 to 1
     * @return a new options record; this one is unchanged
     */
    public HillshadeOptions withIntensities(double light, double dark) {
        return new HillshadeOptions(zFactor, lightMultiple, light, dark, spotExponent, horizontalScale);
    }

    /**
     * The same options with another spot exponent.
     *
     * @param spot the spot exponent, 0.01 to 128
     * @return a new options record; this one is unchanged
     */
    public HillshadeOptions withSpotExponent(double spot) {
        return new HillshadeOptions(zFactor, lightMultiple, relativeLightIntensity, relativeDarkIntensity, spot,
                horizontalScale);
    }

    /**
     * The same options with gdaldem's {@code -s} semantic: cell size in CRS units × {@code scale}.
     *
     * @param scale CRS units to metres, positive, or NaN for the geometry's metric cell sizes
     * @return a new options record; this one is unchanged
     */
    public HillshadeOptions withHorizontalScale(double scale) {
        return new HillshadeOptions(zFactor, lightMultiple, relativeLightIntensity, relativeDarkIntensity,
                spotExponent, scale);
    }

    /** {@return the same options with metric cell sizes from the DEM's geometry (no scale override)} */
    public HillshadeOptions withMetricCellSize() {
        return withHorizontalScale(Double.NaN);
    }

    /** {@return true when the cell sizes come from a {@link #horizontalScale()} override rather than the geometry} */
    public boolean hasHorizontalScale() {
        return !Double.isNaN(horizontalScale);
    }

    /**
     * The jDem846 tone of an illumination {@code d} in [−1, 1]: the light/dark intensity step, then the
     * sign-preserving spot exponent ({@link Brightness#intensity}, {@link Brightness#spot}). NaN stays NaN.
     *
     * @param d the illumination, in [−1, 1], or NaN
     * @return the tone, or NaN
     */
    public double tone(double d) {
        return Brightness.spot(Brightness.intensity(d, relativeLightIntensity, relativeDarkIntensity), spotExponent);
    }
}
