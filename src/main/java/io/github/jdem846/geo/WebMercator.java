package io.github.jdem846.geo;

import java.util.Locale;
import org.apache.sis.measure.Units;
import org.opengis.parameter.GeneralParameterValue;
import org.opengis.parameter.ParameterValue;
import org.opengis.referencing.crs.ProjectedCRS;
import org.opengis.referencing.operation.Conversion;

/**
 * Web Mercator (EPSG:3857, "WGS 84 / Pseudo-Mercator"), the projection of web-map tiles: WGS 84 longitude and
 * latitude put through the spherical Mercator formulas on a sphere of radius {@value #RADIUS} m, x east and y north
 * in metres, x = R·λ, y = R·ln tan(π/4 + φ/2). The world is the square ±{@link #HALF_WORLD} on both axes, which
 * ends at latitude ±{@link #MAX_LATITUDE}.
 */
public final class WebMercator {

    /** The sphere's radius, the semi-major axis of WGS 84, in metres. */
    public static final double RADIUS = 6378137.0;

    /** Half the width of the world in metres, π·R: x and y run from −HALF_WORLD to +HALF_WORLD. */
    public static final double HALF_WORLD = Math.PI * RADIUS;

    /** The latitude where y = HALF_WORLD, 2·atan(e^π) − π/2 in degrees (85.0511287798…°). */
    public static final double MAX_LATITUDE = Math.toDegrees(2 * Math.atan(Math.exp(Math.PI)) - Math.PI / 2);

    /** The EPSG code. */
    public static final int EPSG = 3857;

    /** The CRS as this library describes it, on WGS 84, in metres. */
    public static final CrsInfo CRS = CrsInfo.projected("WGS 84 / Pseudo-Mercator", EPSG, 1.0, Ellipsoid.WGS84);

    private WebMercator() {
    }

    /**
     * {@return x in metres of {@code longitude} degrees (not wrapped: 180° gives HALF_WORLD)}
     *
     * @param longitude degrees east
     */
    public static double x(double longitude) {
        return RADIUS * Math.toRadians(longitude);
    }

    /**
     * {@return y in metres of {@code latitude} degrees, the latitude clamped to ±{@link #MAX_LATITUDE} first (so the
     * poles map to the edges of the world, not to infinity)}
     *
     * @param latitude degrees north
     */
    public static double y(double latitude) {
        double phi = Math.toRadians(Math.max(-MAX_LATITUDE, Math.min(MAX_LATITUDE, latitude)));
        return RADIUS * Math.log(Math.tan(Math.PI / 4 + phi / 2));
    }

    /**
     * {@return the longitude in degrees of {@code x} metres (not wrapped)}
     *
     * @param x metres east of the central meridian
     */
    public static double longitude(double x) {
        return Math.toDegrees(x / RADIUS);
    }

    /**
     * {@return the latitude in degrees of {@code y} metres: atan(sinh(y/R))}
     *
     * @param y metres north of the equator
     */
    public static double latitude(double y) {
        return Math.toDegrees(Math.atan(Math.sinh(y / RADIUS)));
    }

    /**
     * {@return the degrees of longitude that {@code dx} metres of x span}
     *
     * @param dx a distance along x in metres
     */
    public static double longitudeSpan(double dx) {
        return Math.toDegrees(dx / RADIUS);
    }

    /**
     * True for a projected CRS in metres that is Web Mercator: EPSG 3857 (or its older codes 3785 and 900913, or
     * ESRI's 102100 and 102113), or, without a code, an Apache SIS definition of it under another name: EPSG's
     * "Popular Visualisation Pseudo Mercator" method, or ESRI's {@code Mercator_Auxiliary_Sphere} with
     * {@code Auxiliary_Sphere_Type} 0 (what GDAL writes in an ESRI {@code .prj} for EPSG:3857), every other
     * parameter 0, on an ellipsoid of semi-major axis {@value #RADIUS} m.
     *
     * @param crs the CRS, not null
     * @return whether it is Web Mercator
     */
    public static boolean isWebMercator(CrsInfo crs) {
        if (crs.kind() != CrsInfo.Kind.PROJECTED || crs.linearUnitMeters() != 1.0) {
            return false;
        }
        Integer code = crs.epsg();
        if (code != null) {
            return code == EPSG || code == 3785 || code == 900913 || code == 102100 || code == 102113;
        }
        return crs.sisCrs() instanceof ProjectedCRS p && definesWebMercator(p);
    }

    /** True when {@code p}'s projection is Web Mercator under another name (see {@link #isWebMercator}). */
    private static boolean definesWebMercator(ProjectedCRS p) {
        Conversion conversion = p.getConversionFromBase();
        if (conversion == null || p.getDatum() == null
                || p.getDatum().getEllipsoid().getSemiMajorAxis() != RADIUS
                || !p.getDatum().getEllipsoid().getAxisUnit().equals(Units.METRE)) {
            return false;
        }
        String method = conversion.getMethod().getName().getCode().replaceAll("[^A-Za-z]", "")
                .toLowerCase(Locale.ROOT);
        boolean auxiliarySphere = method.equals("mercatorauxiliarysphere");
        if (!auxiliarySphere && !method.equals("popularvisualisationpseudomercator")) {
            return false;
        }
        try {
            for (GeneralParameterValue value : conversion.getParameterValues().values()) {
                if (!(value instanceof ParameterValue<?> v)) {
                    return false;
                }
                String name = v.getDescriptor().getName().getCode();
                boolean axis = name.equals("semi_major") || name.equals("semi_minor");
                if (!axis && v.doubleValue() != 0) {
                    return false;   // Auxiliary_Sphere_Type 1 to 3, an origin, a false easting or northing
                }
            }
        } catch (RuntimeException notANumber) {
            return false;
        }
        return true;
    }
}
