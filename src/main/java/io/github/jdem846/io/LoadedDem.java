package io.github.jdem846.io;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.ElevationStatistics;

/**
 * A DEM read from a file together with what the file declared.
 *
 * @param info             the file's header information (geometry of the whole file), with notices learned while
 *                         reading (values after the end of an ASCII grid)
 * @param dem              the elevations read (geometry of the window/decimation requested)
 * @param sourceStatistics min, max and valid count of the file cells the read covered, at full resolution: for a
 *                         decimated read of the whole file, the file's own elevation range, which the
 *                         box-averaged {@code dem} narrows
 */
public record LoadedDem(DemInfo info, Dem dem, ElevationStatistics sourceStatistics) {
}
