package io.github.jdem846.geo;

import java.util.Optional;

/**
 * A Universal Transverse Mercator zone named by an EPSG code of the families most DEMs use: WGS 84 north
 * (32601–32660) and south (32701–32760), NAD83 (26901–26923) and ETRS89 (25828–25837). Knowing the zone from its
 * code is all a reader and the hillshade need (metres, the ellipsoid), so such a GeoTIFF is read without starting
 * Apache SIS, which costs about 0.4 s of a one-shot command (docs/performance.md). The SIS CRS is resolved later,
 * only where latitude and longitude are needed ({@link CrsResolver#complete}). {@code UtmZoneTest} checks every code
 * against Apache SIS's definition.
 *
 * @param epsg   the EPSG code
 * @param datum  the datum's short name as EPSG writes it in the CRS name ("WGS 84", "NAD83", "ETRS89")
 * @param zone   the zone number, 1–60
 * @param south  true for the southern hemisphere's false northing of 10 000 km
 * @param ellipsoid the datum's ellipsoid, as Apache SIS names it
 */
public record UtmZone(int epsg, String datum, int zone, boolean south, Ellipsoid ellipsoid) {

    /** The scale factor on the central meridian, k₀. */
    public static final double CENTRAL_SCALE = 0.9996;

    /** The false easting of every zone, metres. */
    public static final double FALSE_EASTING = 500_000;

    private static final Ellipsoid WGS_1984 = new Ellipsoid("WGS 1984", 6378137.0, 298.257223563);
    private static final Ellipsoid GRS_1980 = new Ellipsoid("GRS 1980", 6378137.0, 298.257222101);

    /**
     * The zone of an EPSG code of the families above, or empty for any other code.
     *
     * @param code an EPSG code
     * @return the zone, or empty
     */
    public static Optional<UtmZone> ofEpsg(int code) {
        if (code >= 32601 && code <= 32660) {
            return Optional.of(new UtmZone(code, "WGS 84", code - 32600, false, WGS_1984));
        }
        if (code >= 32701 && code <= 32760) {
            return Optional.of(new UtmZone(code, "WGS 84", code - 32700, true, WGS_1984));
        }
        if (code >= 26901 && code <= 26923) {
            return Optional.of(new UtmZone(code, "NAD83", code - 26900, false, GRS_1980));
        }
        if (code >= 25828 && code <= 25837) {
            return Optional.of(new UtmZone(code, "ETRS89", code - 25800, false, GRS_1980));
        }
        return Optional.empty();
    }

    /** {@return the CRS's EPSG name, e.g. "WGS 84 / UTM zone 11N"} */
    public String name() {
        return datum + " / UTM zone " + zone + (south ? "S" : "N");
    }

    /** {@return the longitude of the zone's central meridian, degrees} */
    public double centralMeridian() {
        return -183.0 + 6.0 * zone;
    }

    /** {@return the CRS as a reader describes it: projected, in metres, on the datum's ellipsoid, no SIS object yet} */
    public CrsInfo crsInfo() {
        return CrsInfo.projected(name(), epsg, 1.0, ellipsoid);
    }

    /**
     * The projection's scale factor at an easting, from the spherical transverse Mercator: k = k₀·cosh(x/(k₀R)),
     * x the distance from the central meridian (easting − 500 000 m), R the ellipsoid's mean radius. It differs
     * from the ellipsoidal scale by about e²·(k − 1), i.e. less than 1 % of the departure from 1 (a few 10⁻⁵ within
     * a zone); enough to tell that a grid needs no scale notice, not to print one.
     *
     * @param easting the easting in metres, false easting included
     * @return the approximate scale factor, k₀ on the central meridian and growing away from it
     */
    public double scaleFactorAt(double easting) {
        double x = easting - FALSE_EASTING;
        return CENTRAL_SCALE * Math.cosh(x / (CENTRAL_SCALE * ellipsoid.meanRadius()));
    }
}
