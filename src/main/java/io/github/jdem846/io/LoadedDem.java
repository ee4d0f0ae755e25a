package io.github.jdem846.io;

import io.github.jdem846.raster.Dem;

/**
 * A DEM read from a file together with what the file declared.
 *
 * @param info the file's header information (geometry of the whole file)
 * @param dem  the elevations read (geometry of the window/decimation requested)
 */
public record LoadedDem(DemInfo info, Dem dem) {
}
