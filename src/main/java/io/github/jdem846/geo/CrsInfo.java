package io.github.jdem846.geo;

import java.util.Objects;
import java.util.Optional;
import org.opengis.referencing.crs.CoordinateReferenceSystem;

/**
 * What the renderer needs to know about a grid's coordinate reference system: its kind, the size of its units in
 * metres and its ellipsoid. The Apache SIS CRS is kept when it could be resolved offline; an unresolved CRS is
 * allowed ({@link Kind#UNKNOWN} or a kind known from GeoKeys without a full definition).
 *
 * @param name               a human-readable name, or {@code null} when unknown
 * @param epsg               the EPSG code, or {@code null}
 * @param kind               geographic (axes in degrees), projected (axes in a linear unit) or unknown
 * @param linearUnitMeters   metres per axis unit for projected CRSs (1, 0.3048, 1200/3937); NaN otherwise
 * @param ellipsoid          the ellipsoid, or {@code null} when unknown (geographic grids then use WGS 84)
 * @param sisCrs             the Apache SIS CRS, or {@code null} when it could not be resolved or was not needed
 *                           (a GeoTIFF's lat/lon CRS read from its GeoKeys alone, a UTM zone known by its EPSG
 *                           code ({@link UtmZone}), an implied WGS 84: {@link CrsResolver#complete} resolves it
 *                           from the EPSG code)
 * @param assumed            true when nothing in the file named the CRS and it was inferred (e.g. degrees from the
 *                           extent); the CLI reports this
 */
public record CrsInfo(String name, Integer epsg, Kind kind, double linearUnitMeters, Ellipsoid ellipsoid,
                      CoordinateReferenceSystem sisCrs, boolean assumed) {

    /** The kind of axes a CRS has. */
    public enum Kind {
        /** Longitude/latitude in degrees. */
        GEOGRAPHIC,
        /** Easting/northing in a linear unit. */
        PROJECTED,
        /** Nothing is known about the axes. */
        UNKNOWN
    }

    /** Nothing known. */
    public static final CrsInfo UNKNOWN = new CrsInfo(null, null, Kind.UNKNOWN, Double.NaN, null, null, false);

    /**
     * Geographic WGS 84 (EPSG:4326) without a SIS object, for formats that imply it (SRTM .hgt, a grid assumed to
     * be in degrees); {@link CrsResolver#complete} gives Apache SIS's definition when one is needed.
     */
    public static final CrsInfo WGS84 = geographic("WGS 84", 4326, Ellipsoid.WGS84);

    /**
     * Checks that the kind is given and that a projected CRS has a positive linear unit.
     *
     * @param name a human-readable name, or {@code null} when unknown
     * @param epsg the EPSG code, or {@code null}
     * @param kind geographic (axes in degrees), projected (axes in a linear unit) or unknown
     * @param linearUnitMeters metres per axis unit for projected CRSs (1, 0.3048, 1200/3937); NaN otherwise
     * @param ellipsoid the ellipsoid, or {@code null} when unknown (geographic grids then use WGS 84)
     * @param sisCrs the Apache SIS CRS, or {@code null} when it could not be resolved or was not needed (a GeoTIFF's
     *     lat/lon CRS read from its GeoKeys alone, a UTM zone known by its EPSG code ({@link UtmZone}), an implied WGS
     *     84: {@link CrsResolver#complete} resolves it from the EPSG code)
     * @param assumed true when nothing in the file named the CRS and it was inferred (e.g. degrees from the extent);
     *     the CLI reports this
     */
    public CrsInfo {
        Objects.requireNonNull(kind, "kind");
        if (kind == Kind.PROJECTED && !(linearUnitMeters > 0)) {
            throw new IllegalArgumentException("a projected CRS needs a positive linear unit, got " + linearUnitMeters);
        }
    }

    /**
     * A geographic CRS on the given ellipsoid (WGS 84 when {@code null}), with no SIS object.
     *
     * @param name a human-readable name, or {@code null} when unknown
     * @param epsg the EPSG code, or {@code null}
     * @param ellipsoid the ellipsoid, or {@code null} for WGS 84
     * @return a geographic CRS, not assumed
     */
    public static CrsInfo geographic(String name, Integer epsg, Ellipsoid ellipsoid) {
        return new CrsInfo(name, epsg, Kind.GEOGRAPHIC, Double.NaN, ellipsoid, null, false);
    }

    /**
     * A projected CRS in a unit of the given length in metres, with no SIS object.
     *
     * @param name a human-readable name, or {@code null} when unknown
     * @param epsg the EPSG code, or {@code null}
     * @param linearUnitMeters metres per axis unit, positive (0.3048 for the international foot)
     * @param ellipsoid the ellipsoid, or {@code null} when unknown
     * @return a projected CRS, not assumed
     */
    public static CrsInfo projected(String name, Integer epsg, double linearUnitMeters, Ellipsoid ellipsoid) {
        return new CrsInfo(name, epsg, Kind.PROJECTED, linearUnitMeters, ellipsoid, null, false);
    }

    /** {@return the same CRS flagged as inferred rather than read from the file} */
    public CrsInfo asAssumed() {
        return new CrsInfo(name, epsg, kind, linearUnitMeters, ellipsoid, sisCrs, true);
    }

    /** {@return the ellipsoid to use for metric sizes: the CRS's own, or WGS 84 when it names none} */
    public Ellipsoid ellipsoidOrWgs84() {
        return ellipsoid != null ? ellipsoid : Ellipsoid.WGS84;
    }

    /** {@return true when the axes are degrees of longitude and latitude} */
    public boolean isGeographic() {
        return kind == Kind.GEOGRAPHIC;
    }

    /**
     * The Apache SIS CRS when one was resolved ({@link CrsResolver#complete} resolves one from the EPSG code).
     *
     * @return the SIS CRS, or empty
     */
    public Optional<CoordinateReferenceSystem> sis() {
        return Optional.ofNullable(sisCrs);
    }
}
