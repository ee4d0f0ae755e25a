package io.github.jdem846.output;

import static io.github.jdem846.internal.GeoKeys.*;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The GeoKeys to write into a GeoTIFF: its GeoKeyDirectory (tag 34735) with GeoDoubleParams (34736) and
 * GeoAsciiParams (34737), for a north-up image whose raster space is PixelIsArea (OGC GeoTIFF 1.1, sections 7.1
 * and 8). {@code io.geotiff.GeoKeyReader} is its counterpart for reading.
 *
 * <p>Keys written: GTModelTypeGeoKey (projected or geographic; omitted when the CRS is unknown),
 * GTRasterTypeGeoKey = PixelIsArea, and either ProjectedCSTypeGeoKey with ProjLinearUnitsGeoKey or
 * GeographicTypeGeoKey with GeogAngularUnitsGeoKey. Without an EPSG code the CRS is "user-defined" (32767): a
 * projected CRS then keeps only its name (GTCitationGeoKey) and linear unit, a geographic one its ellipsoid, so
 * readers know the units but not the projection.
 *
 * @param directory    the SHORT values of tag 34735: header and one 4-entry record per key, keys ascending
 * @param doubleParams the DOUBLE values of tag 34736 (empty when no key needs them)
 * @param asciiParams  the ASCII value of tag 34737, each string ended by '|' (empty when none)
 */
record GeoKeyWriter(char[] directory, double[] doubleParams, String asciiParams) {




    /** The keys describing {@code crs}. */
    static GeoKeyWriter of(CrsInfo crs) {
        Builder b = new Builder();
        b.shortKey(GT_RASTER_TYPE, RASTER_PIXEL_IS_AREA);
        switch (crs.kind()) {
            case PROJECTED -> {
                b.shortKey(GT_MODEL_TYPE, MODEL_TYPE_PROJECTED);
                if (crs.epsg() != null && crs.epsg() > 0 && crs.epsg() < USER_DEFINED) {
                    b.shortKey(PROJECTED_CS_TYPE, crs.epsg());
                } else {
                    b.shortKey(PROJECTED_CS_TYPE, USER_DEFINED);
                    if (crs.name() != null) {
                        b.asciiKey(GT_CITATION, crs.name());
                    }
                }
                int unit = linearUnitCode(crs.linearUnitMeters());
                b.shortKey(PROJ_LINEAR_UNITS, unit);
                if (unit == USER_DEFINED) {
                    b.doubleKey(PROJ_LINEAR_UNIT_SIZE, crs.linearUnitMeters());
                }
            }
            case GEOGRAPHIC -> {
                b.shortKey(GT_MODEL_TYPE, MODEL_TYPE_GEOGRAPHIC);
                if (crs.epsg() != null && crs.epsg() > 0 && crs.epsg() < USER_DEFINED) {
                    b.shortKey(GEOGRAPHIC_TYPE, crs.epsg());
                } else {
                    Ellipsoid ellipsoid = crs.ellipsoidOrWgs84();
                    b.shortKey(GEOGRAPHIC_TYPE, USER_DEFINED);
                    if (crs.name() != null) {
                        b.asciiKey(GEOG_CITATION, crs.name());
                    }
                    b.shortKey(GEOG_GEODETIC_DATUM, USER_DEFINED);
                    b.shortKey(GEOG_ELLIPSOID, USER_DEFINED);
                    b.doubleKey(GEOG_SEMI_MAJOR_AXIS, ellipsoid.semiMajorAxis());
                    if (Double.isInfinite(ellipsoid.inverseFlattening())) {
                        b.doubleKey(GEOG_SEMI_MINOR_AXIS, ellipsoid.semiMajorAxis()); // a sphere
                    } else {
                        b.doubleKey(GEOG_INV_FLATTENING, ellipsoid.inverseFlattening());
                    }
                }
                b.shortKey(GEOG_ANGULAR_UNITS, EPSG_DEGREE);
            }
            case UNKNOWN -> {
                // Only the raster type: readers get the geotransform and no CRS.
            }
        }
        return b.build();
    }

    /** EPSG unit code of a linear unit given in metres, or {@link #USER_DEFINED}. */
    static int linearUnitCode(double metres) {
        if (metres == 1.0) {
            return EPSG_METRE;
        }
        if (Math.abs(metres - 0.3048) < 1e-12) {
            return EPSG_FOOT;
        }
        if (Math.abs(metres - 1200.0 / 3937.0) < 1e-12) {
            return EPSG_US_SURVEY_FOOT;
        }
        return USER_DEFINED;
    }

    /** Collects keys in any order and lays them out sorted, as the specification requires. */
    private static final class Builder {
        private final Map<Integer, Object> keys = new TreeMap<>();

        void shortKey(int key, int value) {
            keys.put(key, value);
        }

        void doubleKey(int key, double value) {
            keys.put(key, value);
        }

        void asciiKey(int key, String value) {
            keys.put(key, value.replace('|', '/'));
        }

        GeoKeyWriter build() {
            List<Character> dir = new ArrayList<>();
            List<Double> doubles = new ArrayList<>();
            StringBuilder ascii = new StringBuilder();
            addAll(dir, 1, 1, 0, keys.size()); // KeyDirectoryVersion, KeyRevision, MinorRevision, NumberOfKeys
            for (Map.Entry<Integer, Object> e : keys.entrySet()) {
                if (e.getValue() instanceof Integer v) {
                    addAll(dir, e.getKey(), 0, 1, v);
                } else if (e.getValue() instanceof Double v) {
                    addAll(dir, e.getKey(), TAG_GEO_DOUBLE_PARAMS, 1, doubles.size());
                    doubles.add(v);
                } else {
                    String s = (String) e.getValue() + '|';
                    addAll(dir, e.getKey(), TAG_GEO_ASCII_PARAMS, s.length(), ascii.length());
                    ascii.append(s);
                }
            }
            char[] d = new char[dir.size()];
            for (int i = 0; i < d.length; i++) {
                d[i] = dir.get(i);
            }
            return new GeoKeyWriter(d, doubles.stream().mapToDouble(Double::doubleValue).toArray(),
                    ascii.toString());
        }

        private static void addAll(List<Character> dir, int... values) {
            for (int v : values) {
                dir.add((char) v);
            }
        }
    }
}
