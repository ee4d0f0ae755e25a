/**
 * Where a grid lies on the Earth (or another body): its coordinate reference system as read from the file
 * ({@link io.github.jdem846.geo.CrsInfo}), ellipsoids, latitude/longitude, UTM zones, and the conversion of grid
 * coordinates to latitude/longitude ({@link io.github.jdem846.geo.GeoLocator}). Coordinate reference systems beyond
 * the common ones are resolved by Apache SIS ({@link io.github.jdem846.geo.CrsResolver}).
 */
package io.github.jdem846.geo;
