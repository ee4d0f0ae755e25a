package io.github.jdem846.internal;

/**
 * GeoTIFF tag and GeoKey numbers (OGC GeoTIFF 1.1) shared by the GeoTIFF reader and writer, and the EPSG unit codes
 * they use.
 */
public final class GeoKeys {

    public static final int GT_MODEL_TYPE = 1024;
    public static final int GT_RASTER_TYPE = 1025;
    public static final int GT_CITATION = 1026;
    public static final int GEOGRAPHIC_TYPE = 2048;
    public static final int GEOG_CITATION = 2049;
    public static final int GEOG_GEODETIC_DATUM = 2050;
    public static final int GEOG_ANGULAR_UNITS = 2054;
    public static final int GEOG_ELLIPSOID = 2056;
    public static final int GEOG_SEMI_MAJOR_AXIS = 2057;
    public static final int GEOG_SEMI_MINOR_AXIS = 2058;
    public static final int GEOG_INV_FLATTENING = 2059;
    public static final int PROJECTED_CS_TYPE = 3072;
    public static final int PCS_CITATION = 3073;
    public static final int PROJ_LINEAR_UNITS = 3076;
    public static final int PROJ_LINEAR_UNIT_SIZE = 3077;
    public static final int USER_DEFINED = 32767;
    public static final int TAG_GEO_KEY_DIRECTORY = 34735;
    public static final int TAG_GEO_DOUBLE_PARAMS = 34736;
    public static final int TAG_GEO_ASCII_PARAMS = 34737;
    public static final int MODEL_TYPE_PROJECTED = 1;
    public static final int MODEL_TYPE_GEOGRAPHIC = 2;
    public static final int RASTER_PIXEL_IS_AREA = 1;
    public static final int EPSG_METRE = 9001;
    public static final int EPSG_FOOT = 9002;
    public static final int EPSG_US_SURVEY_FOOT = 9003;
    public static final int EPSG_DEGREE = 9102;

    private GeoKeys() {
    }
}
