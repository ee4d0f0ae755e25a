/**
 * The tile pyramids of {@code jdem846 tiles} rendered on Apache Spark: {@link io.github.jdem846.spark.SparkTiles}
 * measures the DEM's range in row bands and renders the tile groups of a {@link io.github.jdem846.tiles.TilePlan} on
 * the executors, with the same library code as one machine, so the tiles are the same bytes.
 */
package io.github.jdem846.spark;
