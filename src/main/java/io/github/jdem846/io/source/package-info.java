/**
 * What every reader shares: the raster source interface, block-wise decimated reading, raw binary grids (and SRTM
 * {@code .hgt}), the memory guard and georeferencing checks. Internal: not exported by the module.
 */
package io.github.jdem846.io.source;
