/**
 * Writing pictures: {@link io.github.jdem846.output.ImageOutput} writes PNG and GeoTIFF files with, as
 * {@link io.github.jdem846.output.WriteOptions} ask, a world file, a {@code .prj} and a GDAL {@code .aux.xml} placed
 * by a {@link io.github.jdem846.output.GeoReference}; GeoTIFFs in strips or as Cloud-Optimized GeoTIFFs. Pictures
 * larger than memory are written band of rows by band of rows through an {@link io.github.jdem846.output.ImageSink}.
 * Files appear whole or not at all, and never over an input DEM
 * ({@link io.github.jdem846.output.OutputOverwritesInputException}).
 */
package io.github.jdem846.output;
