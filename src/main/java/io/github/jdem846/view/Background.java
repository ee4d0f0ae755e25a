package io.github.jdem846.view;

/**
 * The colour where no terrain is drawn: on a plane, a sky from {@link ViewOptions#skyTop()} straight up to {@link
 * ViewOptions#skyHorizon()} at the horizon and below; on the globe, the body's ellipsoid in {@link
 * ViewOptions#bodyColor()}, darker towards its limb, on {@link ViewOptions#skyTop()} (space).
 */
final class Background {

    private final Pose pose;
    private final ViewOptions options;
    private final GlobeFrame globe;

    Background(Pose pose, ViewOptions options, GlobeFrame globe) {
        this.pose = pose;
        this.options = options;
        this.globe = globe;
    }

    /** The colour of pixel ({@code px}, {@code py}). */
    int at(int px, int py) {
        double[] d = pose.ray(px + 0.5, py + 0.5);
        double length = Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (globe == null) {
            double t = Math.sqrt(Math.max(0, d[2] / length));
            return mix(options.skyHorizon(), options.skyTop(), t);
        }
        double shade = bodyShade(d);
        return Double.isNaN(shade) ? options.skyTop() : mix(0xFF000000, options.bodyColor(), 0.25 + 0.75 * shade);
    }

    /** Cosine between the ray and the ellipsoid's normal where the ray meets it, or NaN when it misses. */
    private double bodyShade(double[] localRay) {
        double[] o = new double[3];
        double[] d = new double[3];
        globe.toEcef(pose.eye, true, o);
        globe.toEcef(localRay, false, d);
        double a = globe.ellipsoid.semiMajorAxis();
        double b = globe.ellipsoid.semiMinorAxis();
        double[] os = {o[0] / a, o[1] / a, o[2] / b};
        double[] ds = {d[0] / a, d[1] / a, d[2] / b};
        double qa = dot(ds, ds);
        double qb = 2 * dot(os, ds);
        double qc = dot(os, os) - 1;
        double disc = qb * qb - 4 * qa * qc;
        if (disc < 0) {
            return Double.NaN;
        }
        double t = (-qb - Math.sqrt(disc)) / (2 * qa);
        if (t <= 0) {
            return Double.NaN;
        }
        double[] n = {(o[0] + t * d[0]) / (a * a), (o[1] + t * d[1]) / (a * a), (o[2] + t * d[2]) / (b * b)};
        return Math.abs(dot(n, d)) / Math.sqrt(dot(n, n) * dot(d, d));
    }

    private static double dot(double[] p, double[] q) {
        return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
    }

    /** {@code from} blended towards {@code to} by {@code t} in 0..1, channel by channel, opaque. */
    static int mix(int from, int to, double t) {
        int r = (int) Math.round(((from >> 16) & 255) * (1 - t) + ((to >> 16) & 255) * t);
        int g = (int) Math.round(((from >> 8) & 255) * (1 - t) + ((to >> 8) & 255) * t);
        int bl = (int) Math.round((from & 255) * (1 - t) + (to & 255) * t);
        return 0xFF000000 | r << 16 | g << 8 | bl;
    }
}
