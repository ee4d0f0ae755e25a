package io.github.jdem846.light;

/**
 * The direction toward a distant light source (the sun), as azimuth clockwise from north and elevation above the
 * horizon, both in degrees, with its unit vector.
 *
 * <p>The azimuth is normalised once, here, into [0, 360): −720 → 0, −0.0 → 0, 1e6 → 280, 360 → 0. The elevation
 * must lie in [−90, 90]; a light at or below the horizon ({@link #isBelowHorizon()}) gives no direct light.
 * The unit vector is computed straight from sine and cosine (never the article's chain of square roots, eq. 10,
 * which cancels near 90° and 270°): east = cos e·sin a, north = cos e·cos a, up = sin e. This is the vector of
 * eq. 4, (cos e·sin a, sin e, −cos e·cos a) in the original's (x = east, y = up, z = south) frame.
 *
 * @param azimuthDegrees   clockwise from north, normalised into [0, 360)
 * @param elevationDegrees above the horizon, in [−90, 90]
 */
public record LightDirection(double azimuthDegrees, double elevationDegrees) {

    /** The original jDem846's default light: azimuth 320°, elevation 25°. */
    public static final LightDirection ORIGINAL_DEFAULT = new LightDirection(320, 25);

    /**
     * Checks the ranges and brings the azimuth into [0, 360).
     *
     * @param azimuthDegrees clockwise from north, normalised into [0, 360)
     * @param elevationDegrees above the horizon, in [−90, 90]
     */
    public LightDirection {
        if (!Double.isFinite(azimuthDegrees)) {
            throw new IllegalArgumentException("sun azimuth must be a finite number of degrees, got "
                    + azimuthDegrees);
        }
        if (!(elevationDegrees >= -90 && elevationDegrees <= 90)) {
            throw new IllegalArgumentException("sun elevation must be between -90 and 90 degrees, got "
                    + elevationDegrees);
        }
        azimuthDegrees = normalizeAzimuth(azimuthDegrees);
    }

    /**
     * An azimuth reduced into [0, 360).
     *
     * @param degrees any finite azimuth
     * @return the same direction in [0, 360), with −0.0 and values that round to 360 mapped to 0
     */
    public static double normalizeAzimuth(double degrees) {
        double a = degrees % 360.0;
        if (a < 0) {
            a += 360.0;
        }
        if (a >= 360.0 || a == 0) {
            a = 0.0; // also turns −0.0 into +0.0
        }
        return a;
    }

    /**
     * The light as terrain with heights multiplied by {@code k} sees it, for shading the unexaggerated heights:
     * the same azimuth and tan(elevation′) = tan(elevation)/k, so a ray's rise per metre compared with true heights
     * equals its rise compared with exaggerated ones. A sun at or below the horizon or at the zenith is unchanged.
     *
     * @param k the height scale (the z-factor)
     * @return the light for the unexaggerated heights
     * @throws IllegalArgumentException unless {@code k} is a finite number &gt; 0
     */
    public LightDirection forHeightsScaledBy(double k) {
        if (!(k > 0) || Double.isInfinite(k)) {
            throw new IllegalArgumentException("height scale must be a finite number > 0, got " + k);
        }
        if (k == 1 || isBelowHorizon() || isAtZenith()) {
            return this;
        }
        double e = Math.toRadians(elevationDegrees);
        return new LightDirection(azimuthDegrees, Math.toDegrees(Math.atan2(Math.sin(e), k * Math.cos(e))));
    }

    /** {@return the east component of the unit vector toward the light} */
    public double east() {
        return Math.cos(Math.toRadians(elevationDegrees)) * Math.sin(Math.toRadians(azimuthDegrees));
    }

    /** {@return the north component of the unit vector toward the light} */
    public double north() {
        return Math.cos(Math.toRadians(elevationDegrees)) * Math.cos(Math.toRadians(azimuthDegrees));
    }

    /** {@return the up component of the unit vector toward the light (sin of the elevation)} */
    public double up() {
        return Math.sin(Math.toRadians(elevationDegrees));
    }

    /** {@return true when the light is at or below the horizon: no direct light reaches any cell} */
    public boolean isBelowHorizon() {
        return elevationDegrees <= 0;
    }

    /** {@return true when the light is at the zenith: nothing casts a shadow} */
    public boolean isAtZenith() {
        return elevationDegrees >= 90;
    }
}
