package io.github.jdem846.io.geotiff;

import io.github.jdem846.internal.GeoKeys;
import static io.github.jdem846.internal.GeoKeys.GEOGRAPHIC_TYPE;
import static io.github.jdem846.internal.GeoKeys.GEOG_ANGULAR_UNITS;
import static io.github.jdem846.internal.GeoKeys.GEOG_CITATION;
import static io.github.jdem846.internal.GeoKeys.GEOG_ELLIPSOID;
import static io.github.jdem846.internal.GeoKeys.GEOG_GEODETIC_DATUM;
import static io.github.jdem846.internal.GeoKeys.GEOG_INV_FLATTENING;
import static io.github.jdem846.internal.GeoKeys.GEOG_SEMI_MAJOR_AXIS;
import static io.github.jdem846.internal.GeoKeys.GEOG_SEMI_MINOR_AXIS;
import static io.github.jdem846.internal.GeoKeys.GT_CITATION;
import static io.github.jdem846.internal.GeoKeys.GT_MODEL_TYPE;
import static io.github.jdem846.internal.GeoKeys.PCS_CITATION;
import static io.github.jdem846.internal.GeoKeys.PROJECTED_CS_TYPE;
import static io.github.jdem846.internal.GeoKeys.PROJ_LINEAR_UNITS;
import static io.github.jdem846.internal.GeoKeys.PROJ_LINEAR_UNIT_SIZE;
import static io.github.jdem846.internal.GeoKeys.USER_DEFINED;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.CrsResolver;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.geo.UtmZone;
import java.util.List;
import java.util.Optional;

/**
 * The CRS of a GeoTIFF from its GeoKeys: the EPSG code of {@code ProjectedCSTypeGeoKey} or
 * {@code GeographicTypeGeoKey} resolved by Apache SIS when it can do so offline (without SIS for a UTM zone of the
 * common datums, {@link UtmZone}, and for a lat/lon code given with its ellipsoid's axes, {@link #axesEllipsoid});
 * otherwise what the keys say on their own (model type, {@code ProjLinearUnitsGeoKey}, ellipsoid or datum code or
 * axes, citations), which is enough for metric cell sizes but not for latitude/longitude of a projected grid. Never
 * fails: what cannot be known is reported in the notices.
 */
final class GeoTiffCrs {

    private static final int MODEL_PROJECTED = 1;
    private static final int MODEL_GEOGRAPHIC = 2;
    private static final int MODEL_GEOCENTRIC = 3;
    private static final int ANGULAR_DEGREE = 9102;

    private GeoTiffCrs() {
    }

    static CrsInfo resolve(GeoKeyReader keys, List<String> notices) {
        int model = keys.code(GT_MODEL_TYPE).orElse(keys.has(PROJECTED_CS_TYPE) ? MODEL_PROJECTED
                : keys.has(GEOGRAPHIC_TYPE) ? MODEL_GEOGRAPHIC : 0);
        return switch (model) {
            case MODEL_PROJECTED -> projected(keys, notices);
            case MODEL_GEOGRAPHIC -> geographic(keys, notices);
            case MODEL_GEOCENTRIC -> {
                notices.add("the GeoKeys declare a geocentric model, which a DEM grid cannot use: CRS unknown");
                yield CrsInfo.UNKNOWN;
            }
            default -> {
                notices.add("the GeoKeys name no model type or CRS: CRS unknown, cell sizes in metres unknown");
                yield CrsInfo.UNKNOWN;
            }
        };
    }

    private static CrsInfo projected(GeoKeyReader keys, List<String> notices) {
        Integer code = keys.code(PROJECTED_CS_TYPE).filter(c -> c > 0 && c != USER_DEFINED).orElse(null);
        if (code != null) {
            Optional<UtmZone> utm = UtmZone.ofEpsg(code);
            if (utm.isPresent()) {
                // a UTM zone: metres on a known ellipsoid, without starting Apache SIS (~0.4 s on a cold JVM);
                // latitude/longitude resolve the code when asked for (GridGeometry.geoLocator)
                return utm.get().crsInfo();
            }
            Optional<CrsInfo> sis = CrsResolver.fromEpsg(code);
            if (sis.isPresent() && sis.get().kind() == CrsInfo.Kind.PROJECTED) {
                return sis.get();
            }
        }
        String name = keys.text(PCS_CITATION).or(() -> keys.text(GT_CITATION)).orElse(null);
        String what = code != null ? "EPSG:" + code : "a user-defined projected CRS";
        Ellipsoid ellipsoid = ellipsoid(keys).orElse(null);
        double unit = Double.NaN;
        String unitName = null;
        Optional<Integer> unitCode = keys.code(PROJ_LINEAR_UNITS);
        if (unitCode.isPresent() && unitCode.get() == USER_DEFINED) {
            unit = keys.number(PROJ_LINEAR_UNIT_SIZE).orElse(Double.NaN);
            unitName = unit + " m (ProjLinearUnitSizeGeoKey)";
        } else if (unitCode.isPresent()) {
            unit = CrsResolver.linearUnitMetres(unitCode.get());
            unitName = CrsResolver.linearUnitName(unitCode.get());
        }
        if (!(unit > 0)) {
            notices.add(what + " is not known to Apache SIS offline and the GeoKeys give no usable linear unit: "
                    + "cell sizes in metres unknown, no latitude/longitude");
            return new CrsInfo(name, code, CrsInfo.Kind.UNKNOWN, Double.NaN, ellipsoid, null, false);
        }
        notices.add(what + " is not known to Apache SIS offline: projected CRS taken from the GeoKeys (unit "
                + unitName + "); latitude/longitude unavailable");
        return new CrsInfo(name, code, CrsInfo.Kind.PROJECTED, unit, ellipsoid, null, false);
    }

    private static CrsInfo geographic(GeoKeyReader keys, List<String> notices) {
        Integer code = keys.code(GEOGRAPHIC_TYPE).filter(c -> c > 0 && c != USER_DEFINED).orElse(null);
        Optional<Ellipsoid> axes = axesEllipsoid(keys);
        boolean degrees = keys.code(GEOG_ANGULAR_UNITS).orElse(ANGULAR_DEGREE) == ANGULAR_DEGREE;
        if (code != null && axes.isPresent() && degrees) {
            // Degrees on a stated ellipsoid (GDAL writes the axes with the code): all that metric cell sizes need,
            // without starting Apache SIS (~0.3 s on a cold JVM); a .prj, if asked for, is built from the code.
            String name = keys.text(GEOG_CITATION).or(() -> keys.text(GT_CITATION)).orElse("EPSG:" + code);
            return CrsInfo.geographic(name, code, axes.get());
        }
        if (code != null) {
            Optional<CrsInfo> sis = CrsResolver.fromEpsg(code);
            if (sis.isPresent() && sis.get().kind() == CrsInfo.Kind.GEOGRAPHIC) {
                return sis.get();
            }
        }
        String name = keys.text(GEOG_CITATION).or(() -> keys.text(GT_CITATION)).orElse(null);
        String what = code != null ? "EPSG:" + code : "a user-defined geographic CRS";
        int angular = keys.code(GEOG_ANGULAR_UNITS).orElse(ANGULAR_DEGREE);
        if (angular != ANGULAR_DEGREE) {
            notices.add(what + " uses angular unit EPSG " + angular + ", not degrees: CRS treated as unknown");
            return new CrsInfo(name, code, CrsInfo.Kind.UNKNOWN, Double.NaN, null, null, false);
        }
        Optional<Ellipsoid> ellipsoid = ellipsoid(keys);
        notices.add(what + " is not known to Apache SIS offline: geographic CRS taken from the GeoKeys"
                + (ellipsoid.isPresent() ? " (ellipsoid " + ellipsoid.get().name() + ")"
                : " (no ellipsoid given: WGS 84 used for metric sizes)"));
        return CrsInfo.geographic(name, code, ellipsoid.orElse(null));
    }

    /** The ellipsoid from its code, its axes, the datum code or the geographic CRS code, in that order. */
    static Optional<Ellipsoid> ellipsoid(GeoKeyReader keys) {
        Optional<Ellipsoid> byCode = keys.code(GEOG_ELLIPSOID).filter(c -> c != USER_DEFINED)
                .flatMap(CrsResolver::ellipsoidFromEpsg);
        if (byCode.isPresent()) {
            return byCode;
        }
        Optional<Ellipsoid> byAxes = axesEllipsoid(keys);
        if (byAxes.isPresent()) {
            return byAxes;
        }
        Optional<Ellipsoid> byDatum = keys.code(GEOG_GEODETIC_DATUM).filter(c -> c != USER_DEFINED)
                .flatMap(CrsResolver::ellipsoidOfDatumEpsg);
        if (byDatum.isPresent()) {
            return byDatum;
        }
        return keys.code(GEOGRAPHIC_TYPE).filter(c -> c != USER_DEFINED).flatMap(CrsResolver::fromEpsg)
                .map(CrsInfo::ellipsoid);
    }

    /**
     * The ellipsoid of GeogSemiMajorAxisGeoKey with GeogInvFlatteningGeoKey or GeogSemiMinorAxisGeoKey (metres, as
     * GDAL writes them), named WGS 84 or GRS 1980 when it is one of those; empty when the keys do not give it.
     */
    static Optional<Ellipsoid> axesEllipsoid(GeoKeyReader keys) {
        Optional<Double> a = keys.number(GEOG_SEMI_MAJOR_AXIS);
        if (a.isEmpty() || !(a.get() > 0)) {
            return Optional.empty();
        }
        Optional<Double> invF = keys.number(GEOG_INV_FLATTENING);
        Optional<Double> b = keys.number(GEOG_SEMI_MINOR_AXIS);
        double inverseFlattening = invF.orElseGet(() -> b.map(bb -> bb >= a.get() ? 0 : a.get() / (a.get() - bb))
                .orElse(Double.NaN));
        if (!(inverseFlattening == 0 || inverseFlattening > 1)) {
            return Optional.empty();
        }
        for (Ellipsoid known : new Ellipsoid[] {Ellipsoid.WGS84, Ellipsoid.GRS80}) {
            if (known.semiMajorAxis() == a.get() && known.inverseFlattening() == inverseFlattening) {
                return Optional.of(known);
            }
        }
        return Optional.of(new Ellipsoid("from GeoKeys", a.get(), inverseFlattening));
    }
}
