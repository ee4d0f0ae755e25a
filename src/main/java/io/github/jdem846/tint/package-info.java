/**
 * Elevation tints: a {@link io.github.jdem846.tint.ColorRamp} (built-in by name, from a gdaldem colour file, or built
 * from {@link io.github.jdem846.tint.ColorStop}s) bound to a grid's range gives the
 * {@link io.github.jdem846.tint.TintFunction} that colours each cell.
 */
package io.github.jdem846.tint;
