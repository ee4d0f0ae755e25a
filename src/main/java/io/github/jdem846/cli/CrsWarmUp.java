package io.github.jdem846.cli;

import io.github.jdem846.io.DemReader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Reads the input's header on a daemon thread while picocli parses the command line, so that the reader's slow
 * first steps overlap with it: the TIFF decoder's classes and, only when the file needs them, Apache SIS's (about
 * 0.3 s on first use: a {@code .prj}, a projected GeoTIFF other than a UTM zone of {@link
 * io.github.jdem846.geo.UtmZone}). A lat/lon or UTM GeoTIFF, an SRTM tile or a file without CRS never starts SIS,
 * which would otherwise take a core from the command for nothing (docs/performance.md, "Start-up"). The input is
 * the first argument that names an existing DEM file; without one (the bundled sample, {@code --version}, a typo)
 * nothing is done. When the command will need latitude/longitude ({@link #needsLatLon}), the file's CRS is also
 * resolved by SIS here. Any failure here is ignored: the command reads the file again and reports its own errors.
 */
final class CrsWarmUp {

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
            Optional<Path> dem = readFirstDem(args);
            if (dem.isPresent() && needsLatLon(args)) {
                DemReader.inspect(dem.get()).geometry().geoLocator();   // SIS's CRS and transform, as the command will
            }
        } catch (IOException | RuntimeException | LinkageError e) {
            // ignored: see the class comment
        }
    }

    /**
     * True when the command will locate the grid in latitude/longitude, which needs Apache SIS also for a CRS the
     * reader knows without it (a UTM zone): {@code info}, a sun by date and time, a world file's {@code .prj}.
     */
    static boolean needsLatLon(String[] args) {
        if (args.length > 0 && args[0].equals("info")) {
            return true;
        }
        for (String arg : args) {
            if (arg.equals("--sun-time") || arg.startsWith("--sun-time=") || arg.equals("--world-file")) {
                return true;
            }
        }
        return false;
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
