package io.github.jdem846.geo;

/**
 * A reference ellipsoid (or sphere) of revolution, with the radii of curvature needed to turn angular cell sizes
 * into metres.
 *
 * @param name              a human-readable name, e.g. "WGS 84"
 * @param semiMajorAxis     equatorial radius a, in metres; positive and finite
 * @param inverseFlattening 1/f; {@code Double.POSITIVE_INFINITY} (or 0, as EPSG writes it) for a sphere
 */
public record Ellipsoid(String name, double semiMajorAxis, double inverseFlattening) {

    /** WGS 84, the default when a geographic grid names no ellipsoid. */
    public static final Ellipsoid WGS84 = new Ellipsoid("WGS 84", 6378137.0, 298.257223563);
    /** GRS 1980 (NAD83, ETRS89, NZGD2000). */
    public static final Ellipsoid GRS80 = new Ellipsoid("GRS 1980", 6378137.0, 298.257222101);
    /** The Moon as a sphere of IAU mean radius 1737.4 km. */
    public static final Ellipsoid MOON = sphere("Moon", 1737400.0);
    /** Mars as a sphere of IAU mean radius 3389.5 km. */
    public static final Ellipsoid MARS = sphere("Mars", 3389500.0);

    /**
     * Checks the axis and the flattening; an inverse flattening of 0 is taken as infinite (a sphere).
     *
     * @param name a human-readable name, e.g. "WGS 84"
     * @param semiMajorAxis equatorial radius a, in metres; positive and finite
     * @param inverseFlattening 1/f; {@code Double.POSITIVE_INFINITY} (or 0, as EPSG writes it) for a sphere
     */
    public Ellipsoid {
        if (!(semiMajorAxis > 0) || Double.isInfinite(semiMajorAxis)) {
            throw new IllegalArgumentException("semi-major axis must be positive and finite: " + semiMajorAxis);
        }
        if (inverseFlattening == 0) {
            inverseFlattening = Double.POSITIVE_INFINITY;
        }
        if (!(inverseFlattening > 1)) {
            throw new IllegalArgumentException("inverse flattening must be > 1 (or infinite): " + inverseFlattening);
        }
    }

    /**
     * Equal name, axis and inverse flattening, as a record's own {@code equals} compares them (the doubles by
     * {@link Double#compare}). Written out: the record's is linked on its first call at run time
     * ({@code ObjectMethods.bootstrap}), which took about 10 ms of every command that checks a UTM grid's ellipsoid.
     */
    @Override
    public boolean equals(Object o) {
        return o instanceof Ellipsoid e && java.util.Objects.equals(name, e.name)
                && Double.compare(semiMajorAxis, e.semiMajorAxis) == 0
                && Double.compare(inverseFlattening, e.inverseFlattening) == 0;
    }

    /** Consistent with {@link #equals(Object)}; written out for the same reason. */
    @Override
    public int hashCode() {
        return (31 * java.util.Objects.hashCode(name) + Double.hashCode(semiMajorAxis)) * 31
                + Double.hashCode(inverseFlattening);
    }

    /**
     * A sphere of the given radius in metres.
     *
     * @param name the name for messages
     * @param radius the radius in metres, positive and finite
     * @return an ellipsoid of infinite inverse flattening
     */
    public static Ellipsoid sphere(String name, double radius) {
        return new Ellipsoid(name, radius, Double.POSITIVE_INFINITY);
    }

    /** {@return the flattening f = (a − b)/a; 0 for a sphere} */
    public double flattening() {
        return Double.isInfinite(inverseFlattening) ? 0 : 1 / inverseFlattening;
    }

    /** {@return the first eccentricity squared e² = f(2 − f)} */
    public double eccentricitySquared() {
        double f = flattening();
        return f * (2 - f);
    }

    /** {@return the polar radius b, in metres} */
    public double semiMinorAxis() {
        return semiMajorAxis * (1 - flattening());
    }

    /** {@return the mean radius (2a + b)/3, in metres (IUGG R1)} */
    public double meanRadius() {
        return (2 * semiMajorAxis + semiMinorAxis()) / 3;
    }

    /**
     * Radius of curvature in the prime vertical, N(φ) = a/√(1 − e² sin²φ), in metres. The length of one radian
     * of longitude along the parallel at φ is N(φ)·cos φ.
     *
     * @param latitudeRadians the geodetic latitude φ in radians
     * @return N(φ) in metres
     */
    public double primeVerticalRadius(double latitudeRadians) {
        double s = Math.sin(latitudeRadians);
        return semiMajorAxis / Math.sqrt(1 - eccentricitySquared() * s * s);
    }

    /**
     * Radius of curvature in the meridian, M(φ) = a(1 − e²)/(1 − e² sin²φ)^1.5, in metres.
     *
     * @param latitudeRadians the geodetic latitude φ in radians
     * @return M(φ) in metres
     */
    public double meridionalRadius(double latitudeRadians) {
        double e2 = eccentricitySquared();
        double s = Math.sin(latitudeRadians);
        double w = 1 - e2 * s * s;
        return semiMajorAxis * (1 - e2) / (w * Math.sqrt(w));
    }

    /**
     * Length in metres of an arc of longitude {@code deltaLonDegrees} along the parallel at
     * {@code latitudeDegrees}. Exactly 0 at the poles (cos 90° is clamped so no negative length appears).
     *
     * @param latitudeDegrees the parallel's geodetic latitude in degrees
     * @param deltaLonDegrees the arc's extent in degrees of longitude, either sign
     * @return the length in metres, ≥ 0
     */
    public double parallelArcLength(double latitudeDegrees, double deltaLonDegrees) {
        double phi = Math.toRadians(clampLatitude(latitudeDegrees));
        double cos = Math.max(0, Math.cos(phi));
        return primeVerticalRadius(phi) * cos * Math.toRadians(Math.abs(deltaLonDegrees));
    }

    /**
     * Length in metres of the meridian arc between two latitudes (degrees), by Simpson's rule on M(φ), which is
     * exact to well under a millimetre for any DEM cell.
     *
     * @param latitude1Degrees one end's geodetic latitude
     * @param latitude2Degrees the other end's geodetic latitude
     * @return the length in metres, ≥ 0, in either order
     */
    public double meridianArcLength(double latitude1Degrees, double latitude2Degrees) {
        double p1 = Math.toRadians(clampLatitude(latitude1Degrees));
        double p2 = Math.toRadians(clampLatitude(latitude2Degrees));
        double mid = 0.5 * (p1 + p2);
        double m = (meridionalRadius(p1) + 4 * meridionalRadius(mid) + meridionalRadius(p2)) / 6;
        return m * Math.abs(p2 - p1);
    }

    private static double clampLatitude(double latitudeDegrees) {
        return Math.max(-90, Math.min(90, latitudeDegrees));
    }
}
