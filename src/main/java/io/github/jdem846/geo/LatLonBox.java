package io.github.jdem846.geo;

/**
 * A latitude/longitude bounding box in degrees (west may exceed east only if the box crosses the antimeridian,
 * which this project's readers do not produce).
 *
 * @param south southern latitude
 * @param north northern latitude
 * @param west  western longitude
 * @param east  eastern longitude
 */
public record LatLonBox(double south, double north, double west, double east) {
}
