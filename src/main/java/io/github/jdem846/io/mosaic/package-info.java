/**
 * Several DEM files read as one grid: a list of tiles ({@link io.github.jdem846.io.mosaic.MosaicPlanner}) or a
 * GDAL virtual raster ({@link io.github.jdem846.io.mosaic.VrtReader}) is planned from the files' headers (one CRS,
 * one cell size, one grid), then read through {@link io.github.jdem846.io.mosaic.MosaicSource}, which opens a
 * file only when a read touches it. Internal: not exported by the module; {@code io.DemReader} is the entry
 * point.
 */
package io.github.jdem846.io.mosaic;
