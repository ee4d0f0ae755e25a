package io.github.jdem846.shadow;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import java.util.Random;

/** Small synthetic DEMs for the shadow tests. */
final class ShadowTestDems {

    private ShadowTestDems() {
    }

    static Dem metric(int w, int h, double cell, float[] v) {
        return new Dem(v, GridGeometry.metric(w, h, cell));
    }

    static Dem flat(int w, int h, double cell, float z) {
        float[] v = new float[w * h];
        java.util.Arrays.fill(v, z);
        return metric(w, h, cell, v);
    }

    /** Flat at 0 with one cell raised to {@code height}. */
    static Dem spike(int w, int h, double cell, int sc, int sr, float height) {
        float[] v = new float[w * h];
        v[sr * w + sc] = height;
        return metric(w, h, cell, v);
    }

    /**
     * Seeded rough terrain: a sum of random sinusoids (octaves with amplitude ∝ wavelength), heights quantised to
     * 1/16 m so that adding a power-of-two offset or doubling is exact in float32.
     */
    static Dem rough(int w, int h, double cell, long seed, double relief) {
        Random rnd = new Random(seed);
        int waves = 24;
        double[] kx = new double[waves];
        double[] ky = new double[waves];
        double[] ph = new double[waves];
        double[] amp = new double[waves];
        for (int q = 0; q < waves; q++) {
            double wavelength = Math.max(w, h) / Math.pow(1.35, q) + 2;
            double dir = rnd.nextDouble() * 2 * Math.PI;
            kx[q] = Math.cos(dir) * 2 * Math.PI / wavelength;
            ky[q] = Math.sin(dir) * 2 * Math.PI / wavelength;
            ph[q] = rnd.nextDouble() * 2 * Math.PI;
            amp[q] = wavelength;
        }
        double[] raw = new double[w * h];
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                double s = 0;
                for (int q = 0; q < waves; q++) {
                    s += amp[q] * Math.sin(kx[q] * c + ky[q] * r + ph[q]);
                }
                raw[r * w + c] = s;
                min = Math.min(min, s);
                max = Math.max(max, s);
            }
        }
        float[] v = new float[w * h];
        for (int i = 0; i < v.length; i++) {
            double z = (raw[i] - min) / (max - min + 1e-12) * relief;
            v[i] = (float) (Math.round(z * 16) / 16.0);
        }
        return metric(w, h, cell, v);
    }

    /** A geographic (WGS 84) grid with the given corner and square cells in degrees. */
    static Dem geographic(int w, int h, double west, double north, double cellDeg, float[] v) {
        GridGeometry g = new GridGeometry(w, h, west, north, cellDeg, cellDeg,
                CrsInfo.geographic("WGS 84", 4326, Ellipsoid.WGS84), PixelAnchor.CORNER);
        return new Dem(v, g);
    }

    /** The DEM rotated 90° clockwise (north edge becomes the east edge); square metric cells. */
    static Dem rotateClockwise(Dem dem, double cell) {
        int w = dem.width();
        int h = dem.height();
        float[] out = new float[w * h];
        // new width = h, new height = w; new(c', r') = old(c = r', r = h − 1 − c')
        for (int r2 = 0; r2 < w; r2++) {
            for (int c2 = 0; c2 < h; c2++) {
                out[r2 * h + c2] = dem.get(r2, h - 1 - c2);
            }
        }
        return metric(h, w, cell, out);
    }

    /** The mask rotated like {@link #rotateClockwise}. */
    static float[] rotateClockwise(ShadowMask m) {
        int w = m.width();
        int h = m.height();
        float[] out = new float[w * h];
        for (int r2 = 0; r2 < w; r2++) {
            for (int c2 = 0; c2 < h; c2++) {
                out[r2 * h + c2] = m.get(r2, h - 1 - c2);
            }
        }
        return out;
    }

    /** A copy with every elevation transformed. */
    static Dem map(Dem dem, java.util.function.DoubleUnaryOperator op) {
        float[] v = dem.backingArray().clone();
        for (int i = 0; i < v.length; i++) {
            v[i] = (float) op.applyAsDouble(v[i]);
        }
        return new Dem(v, dem.geometry());
    }
}
