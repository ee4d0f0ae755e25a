package io.github.jdem846.shade;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;

/**
 * Small helpers for the hillshade tests: whole-DEM illumination and the analytic reference on a plane (the DEMs
 * come from {@link io.github.jdem846.testing.SyntheticDems}).
 */
final class ShadeTestSupport {

    private ShadeTestSupport() {
    }

    /** The stage's output for the whole DEM. */
    static float[] illuminate(IlluminationStage stage, Dem dem, LightDirection light) {
        float[] out = new float[dem.width() * dem.height()];
        stage.illuminate(dem, light, 0, 0, dem.width(), dem.height(), out);
        return out;
    }

    /**
     * The analytic cosine of incidence on the plane z = a·x + b·y (x east, y north): the unit normal
     * (−a, −b, 1)/√(1 + a² + b²) dotted with the light (cos e·sin az, cos e·cos az, sin e).
     */
    static double planeCosine(double a, double b, double azimuthDeg, double elevationDeg) {
        double e = Math.toRadians(elevationDeg);
        double az = Math.toRadians(azimuthDeg);
        double le = Math.cos(e) * Math.sin(az);
        double ln = Math.cos(e) * Math.cos(az);
        double lu = Math.sin(e);
        return (-a * le - b * ln + lu) / Math.sqrt(1 + a * a + b * b);
    }
}
