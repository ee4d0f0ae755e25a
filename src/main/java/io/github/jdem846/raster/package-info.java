/**
 * An elevation grid in memory ({@link io.github.jdem846.raster.Dem}: float cells, NaN for no-data) and its place and
 * cell sizes ({@link io.github.jdem846.raster.GridGeometry}), with elevation statistics and area-weighted resampling
 * to another size ({@link io.github.jdem846.raster.DemResampler}).
 */
package io.github.jdem846.raster;
