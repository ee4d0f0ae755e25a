package io.github.jdem846.cli;

import io.github.jdem846.geo.CrsResolver;
import io.github.jdem846.io.DemReader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Reads the input's header on a daemon thread while picocli parses the command line, so that the reader's slow
 * first steps overlap with it: the TIFF decoder's classes and, only when the file needs them, Apache SIS's (about
 * 0.3 s on first use: a projected CRS, a {@code .prj}). A lat/lon GeoTIFF or a file without CRS never starts SIS,
 * which would otherwise take a core from the command for nothing (docs/performance.md, "Start-up"). The input is
 * the first argument that names an existing DEM file; without one (the bundled sample, a typo) SIS is warmed with a
 * geographic and a projected CRS as the sample needs. Any failure here is ignored: the command reads the file again
 * and reports its own errors.
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

    /** Starts the warm-up thread for the command line {@code args} and returns at once. */
    static void start(String[] args) {
        String[] copy = args.clone();
        Thread t = new Thread(() -> run(copy), "jdem846-crs-warm-up");
        t.setDaemon(true);
        t.start();
    }

    private static void run(String[] args) {
        try {
            if (readFirstDem(args).isEmpty()) {
                CrsResolver.fromEpsg(4326);
                CrsResolver.fromWkt(UTM_WKT);
            }
        } catch (RuntimeException | LinkageError e) {
            // ignored: see the class comment
        }
    }

    /**
     * Reads the header (and CRS) of the first argument that names an existing DEM file, as the command's reader
     * will: the warm-up itself. Options, missing files and files that are not DEMs (a colour table, an earlier
     * output) are skipped.
     *
     * @return that file, or empty when no argument names one
     */
    static Optional<Path> readFirstDem(String[] args) {
        for (String arg : args) {
            if (arg.startsWith("-") || !isFile(arg)) {
                continue;
            }
            try {
                DemReader.inspect(Path.of(arg));
                return Optional.of(Path.of(arg));
            } catch (IOException | RuntimeException e) {
                // not a DEM: try the next argument
            }
        }
        return Optional.empty();
    }

    private static boolean isFile(String arg) {
        try {
            return Files.isRegularFile(Path.of(arg));
        } catch (InvalidPathException e) {
            return false;
        }
    }
}
