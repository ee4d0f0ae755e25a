package io.github.jdem846.geo;

/**
 * A position in degrees on the CRS's own geodetic datum (no datum shift is applied).
 *
 * @param latitude  degrees north, −90 to 90
 * @param longitude degrees east
 */
public record LatLon(double latitude, double longitude) {
}
