package io.github.jdem846.cli;

import io.github.jdem846.geo.CrsResolver;

/**
 * Initialises Apache SIS (its classes, units and EPSG objects, about 0.3 s on first use) on a daemon thread while
 * picocli parses the command line and the command opens its file, so that the first CRS a reader resolves does not
 * wait for all of it (docs/performance.md, "Whole commands vs gdaldem"). Any failure here is ignored: the reader
 * resolves the CRS again and reports its own errors.
 */
final class CrsWarmUp {

    /** A projected CRS in ESRI WKT, as in a GridFloat {@code .prj}. */
    private static final String UTM_WKT = "PROJCS[\"WGS_1984_UTM_Zone_11N\",GEOGCS[\"GCS_WGS_1984\","
            + "DATUM[\"D_WGS_1984\",SPHEROID[\"WGS_1984\",6378137.0,298.257223563]],PRIMEM[\"Greenwich\",0.0],"
            + "UNIT[\"Degree\",0.0174532925199433]],PROJECTION[\"Transverse_Mercator\"],"
            + "PARAMETER[\"False_Easting\",500000.0],PARAMETER[\"False_Northing\",0.0],"
            + "PARAMETER[\"Central_Meridian\",-117.0],PARAMETER[\"Scale_Factor\",0.9996],"
            + "PARAMETER[\"Latitude_Of_Origin\",0.0],UNIT[\"Meter\",1.0]]";

    private CrsWarmUp() {
    }

    /** Starts the warm-up thread and returns at once. */
    static void start() {
        Thread t = new Thread(CrsWarmUp::run, "jdem846-crs-warm-up");
        t.setDaemon(true);
        t.start();
    }

    private static void run() {
        try {
            CrsResolver.fromEpsg(4326);
            CrsResolver.fromWkt(UTM_WKT);
        } catch (RuntimeException | LinkageError e) {
            // ignored: see the class comment
        }
    }
}
