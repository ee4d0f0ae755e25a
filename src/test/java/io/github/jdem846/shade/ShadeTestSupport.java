package io.github.jdem846.shade;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.TestDems;
import java.util.function.DoubleBinaryOperator;

/** Small helpers for the hillshade tests: synthetic DEMs and whole-DEM illumination. */
final class ShadeTestSupport {

    private ShadeTestSupport() {
    }

    /** A metric DEM whose cell (c, r) holds f(x east, y north) at the cell centre, in metres. */
    static Dem surface(int w, int h, double cell, DoubleBinaryOperator f) {
        float[] v = new float[w * h];
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                double x = (c + 0.5) * cell;
                double y = (h - r - 0.5) * cell;
                v[r * w + c] = (float) f.applyAsDouble(x, y);
            }
        }
        return TestDems.metric(w, h, cell, v);
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

    /** The DEM turned 90° clockwise (north becomes east), same square cell size. */
    static Dem rotateClockwise(Dem dem, double cell) {
        int w = dem.width();
        int h = dem.height();
        float[] v = new float[w * h];
        // New grid: width h, height w; new (c', r') = old (c = r', r = h − 1 − c').
        for (int r2 = 0; r2 < w; r2++) {
            for (int c2 = 0; c2 < h; c2++) {
                v[r2 * h + c2] = dem.get(r2, h - 1 - c2);
            }
        }
        return TestDems.metric(h, w, cell, v);
    }

    /** A copy of a row-major array of a w × h grid, turned 90° clockwise. */
    static float[] rotateClockwise(float[] a, int w, int h) {
        float[] out = new float[w * h];
        for (int r2 = 0; r2 < w; r2++) {
            for (int c2 = 0; c2 < h; c2++) {
                out[r2 * h + c2] = a[(h - 1 - c2) * w + r2];
            }
        }
        return out;
    }
}
