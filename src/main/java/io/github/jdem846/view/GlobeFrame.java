package io.github.jdem846.view;

import io.github.jdem846.geo.Ellipsoid;

/**
 * Earth-centred coordinates (ECEF) of a body's ellipsoid and the east–north–up frame at one point of its surface,
 * the local frame of a globe view: the usual geodetic formulas, x = (N + h) cos φ cos λ, y = (N + h) cos φ sin λ,
 * z = (N (1 − e²) + h) sin φ, with N the prime-vertical radius.
 */
final class GlobeFrame {

    final Ellipsoid ellipsoid;
    private final double[] origin = new double[3];
    private final double[] east;
    private final double[] north;
    private final double[] up;

    private GlobeFrame(Ellipsoid ellipsoid, double latitude, double longitude) {
        this.ellipsoid = ellipsoid;
        double phi = Math.toRadians(latitude);
        double lambda = Math.toRadians(longitude);
        ecef(latitude, longitude, 0, origin);
        east = new double[] {-Math.sin(lambda), Math.cos(lambda), 0};
        north = new double[] {-Math.sin(phi) * Math.cos(lambda), -Math.sin(phi) * Math.sin(lambda), Math.cos(phi)};
        up = new double[] {Math.cos(phi) * Math.cos(lambda), Math.cos(phi) * Math.sin(lambda), Math.sin(phi)};
    }

    /** The frame at latitude/longitude (degrees) on the ellipsoid's surface. */
    static GlobeFrame at(Ellipsoid ellipsoid, double latitude, double longitude) {
        return new GlobeFrame(ellipsoid, latitude, longitude);
    }

    /** ECEF metres of a point at {@code height} above the ellipsoid, into {@code out}. */
    void ecef(double latitude, double longitude, double height, double[] out) {
        double phi = Math.toRadians(latitude);
        double lambda = Math.toRadians(longitude);
        double n = ellipsoid.primeVerticalRadius(phi);
        double cosPhi = Math.cos(phi);
        out[0] = (n + height) * cosPhi * Math.cos(lambda);
        out[1] = (n + height) * cosPhi * Math.sin(lambda);
        out[2] = (n * (1 - ellipsoid.eccentricitySquared()) + height) * Math.sin(phi);
    }

    /** The local east–north–up coordinates of an ECEF point, into {@code out}. */
    void toLocal(double[] p, double[] out) {
        double dx = p[0] - origin[0];
        double dy = p[1] - origin[1];
        double dz = p[2] - origin[2];
        out[0] = dx * east[0] + dy * east[1] + dz * east[2];
        out[1] = dx * north[0] + dy * north[1] + dz * north[2];
        out[2] = dx * up[0] + dy * up[1] + dz * up[2];
    }

    /** The ECEF point of local coordinates (a position when {@code point}, else a direction), into {@code out}. */
    void toEcef(double[] local, boolean point, double[] out) {
        for (int k = 0; k < 3; k++) {
            out[k] = local[0] * east[k] + local[1] * north[k] + local[2] * up[k] + (point ? origin[k] : 0);
        }
    }
}
