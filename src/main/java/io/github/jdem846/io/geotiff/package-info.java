/**
 * The GeoTIFF reader behind {@code io.DemReader}: TIFF structure, strip and tile subsets, predictors and LZW, GeoKeys
 * and the coordinate reference system they name. Internal: not exported by the module.
 */
package io.github.jdem846.io.geotiff;
