/**
 * Reading DEM files: {@link io.github.jdem846.io.DemReader} reads a whole grid, a window of it or a decimated copy
 * ({@link io.github.jdem846.io.ReadRequest}, {@link io.github.jdem846.io.Window}), or only its header
 * ({@link io.github.jdem846.io.DemInfo}). GeoTIFF, ESRI GridFloat, ESRI ASCII grid, BIL and SRTM {@code .hgt} are
 * told apart by their first bytes and extension; a file that cannot be read is a
 * {@link io.github.jdem846.io.DemFormatException} naming the file and the fault. Several files
 * ({@link io.github.jdem846.io.DemInput}) or a GDAL {@code .vrt} are read as one grid, a mosaic
 * ({@link io.github.jdem846.io.DemFormat#MOSAIC}, {@link io.github.jdem846.io.DemFormat#VRT}).
 */
package io.github.jdem846.io;
