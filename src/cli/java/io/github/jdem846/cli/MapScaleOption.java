package io.github.jdem846.cli;

import io.github.jdem846.job.MercatorScale;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code --map-scale}: measure a Web Mercator DEM's cells in the projection's metres, as gdaldem does, instead of
 * on the ground row by row ({@link MercatorScale}).
 */
@Command(addMethodSubcommands = false) // no command methods to look for: a quicker start
final class MapScaleOption {

    @Option(names = "--map-scale",
            description = "Web Mercator DEMs: measure cells in map metres, as gdaldem does (1/cos latitude longer "
                    + "than on the ground: gentler slopes, shorter shadows). Default: the cells' ground size, row "
                    + "by row.")
    boolean mapScale;

    /** How the job measures a Web Mercator DEM's cells. */
    MercatorScale scale() {
        return mapScale ? MercatorScale.MAP : MercatorScale.GROUND;
    }
}
