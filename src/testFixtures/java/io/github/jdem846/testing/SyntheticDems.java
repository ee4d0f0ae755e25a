package io.github.jdem846.testing;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import java.util.Arrays;
import java.util.Random;
import java.util.function.DoubleBinaryOperator;
import java.util.function.DoubleUnaryOperator;

/**
 * Synthetic terrain for the tests and the benchmark programs: DEMs made in memory (metric and geographic grids,
 * flat ground, a spike, analytic surfaces, seeded rough terrain), real DEMs mirror-tiled or turned a quarter turn,
 * and a shaded, tinted fractal relief for the image encoders. Everything is deterministic: the same arguments give
 * the same values, bit for bit.
 */
public final class SyntheticDems {

    private SyntheticDems() {
    }

    /** A DEM on a metric grid with square cells of {@code cellSize} metres (no CRS); {@code values} row-major. */
    public static Dem metric(int width, int height, double cellSize, float[] values) {
        return new Dem(values, GridGeometry.metric(width, height, cellSize));
    }

    /** A geographic (WGS 84) grid with the given north-west corner and square cells in degrees. */
    public static Dem geographic(int width, int height, double west, double north, double cellDegrees,
                                 float[] values) {
        GridGeometry g = new GridGeometry(width, height, west, north, cellDegrees, cellDegrees,
                CrsInfo.geographic("WGS 84", 4326, Ellipsoid.WGS84), PixelAnchor.CORNER);
        return new Dem(values, g);
    }

    /** A metric DEM at {@code z} everywhere. */
    public static Dem flat(int width, int height, double cellSize, float z) {
        float[] v = new float[width * height];
        Arrays.fill(v, z);
        return metric(width, height, cellSize, v);
    }

    /** A metric DEM at 0 with the one cell ({@code col}, {@code row}) raised to {@code spikeHeight}. */
    public static Dem spike(int width, int height, double cellSize, int col, int row, float spikeHeight) {
        float[] v = new float[width * height];
        v[row * width + col] = spikeHeight;
        return metric(width, height, cellSize, v);
    }

    /** A metric DEM whose cell (c, r) holds f(x east, y north) at the cell centre, in metres from the SW corner. */
    public static Dem surface(int width, int height, double cellSize, DoubleBinaryOperator f) {
        float[] v = new float[width * height];
        for (int r = 0; r < height; r++) {
            for (int c = 0; c < width; c++) {
                double x = (c + 0.5) * cellSize;
                double y = (height - r - 0.5) * cellSize;
                v[r * width + c] = (float) f.applyAsDouble(x, y);
            }
        }
        return metric(width, height, cellSize, v);
    }

    /**
     * Seeded rough terrain from 0 to {@code relief} metres: a sum of random sinusoids (octaves with amplitude ∝
     * wavelength), heights quantised to 1/16 m so that adding a power-of-two offset or doubling is exact in float32.
     */
    public static Dem rough(int width, int height, double cellSize, long seed, double relief) {
        Random rnd = new Random(seed);
        int waves = 24;
        double[] kx = new double[waves];
        double[] ky = new double[waves];
        double[] ph = new double[waves];
        double[] amp = new double[waves];
        for (int q = 0; q < waves; q++) {
            double wavelength = Math.max(width, height) / Math.pow(1.35, q) + 2;
            double dir = rnd.nextDouble() * 2 * Math.PI;
            kx[q] = Math.cos(dir) * 2 * Math.PI / wavelength;
            ky[q] = Math.sin(dir) * 2 * Math.PI / wavelength;
            ph[q] = rnd.nextDouble() * 2 * Math.PI;
            amp[q] = wavelength;
        }
        double[] raw = new double[width * height];
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (int r = 0; r < height; r++) {
            for (int c = 0; c < width; c++) {
                double s = 0;
                for (int q = 0; q < waves; q++) {
                    s += amp[q] * Math.sin(kx[q] * c + ky[q] * r + ph[q]);
                }
                raw[r * width + c] = s;
                min = Math.min(min, s);
                max = Math.max(max, s);
            }
        }
        float[] v = new float[width * height];
        for (int i = 0; i < v.length; i++) {
            double z = (raw[i] - min) / (max - min + 1e-12) * relief;
            v[i] = (float) (Math.round(z * 16) / 16.0);
        }
        return metric(width, height, cellSize, v);
    }

    /** A copy of {@code dem} (same grid) with every elevation transformed by {@code op}. */
    public static Dem map(Dem dem, DoubleUnaryOperator op) {
        float[] v = dem.backingArray().clone();
        for (int i = 0; i < v.length; i++) {
            v[i] = (float) op.applyAsDouble(v[i]);
        }
        return new Dem(v, dem.geometry());
    }

    /**
     * {@code source} mirror-tiled to {@code width × height} cells: tile (i, j) (i counts columns of tiles, j rows) is
     * the source flipped east–west when i is odd and north–south when j is odd, so every tile edge is a reflection
     * and the surface has no cliffs at the seams. The terrain repeats with a period of twice the source's size; the
     * elevations, cell size and CRS are the source's, tile (0, 0) is the source itself in place (same north-west
     * corner), and no-data cells stay no-data.
     */
    public static Dem mirrored(Dem source, int width, int height) {
        float[] v = new float[Math.multiplyExact(width, height)];
        for (int y = 0; y < height; y++) {
            int sy = mirroredIndex(y, source.height());
            for (int x = 0; x < width; x++) {
                v[y * width + x] = source.get(mirroredIndex(x, source.width()), sy);
            }
        }
        GridGeometry g = source.geometry();
        return Dem.ofNormalized(v, new GridGeometry(width, height, g.originX(), g.originY(), g.cellWidth(),
                g.cellHeight(), g.crs(), g.declaredAnchor()), source.declaredNoData());
    }

    /** The source cell of {@link #mirrored} that cell {@code i} (0 ≤ i) takes along an axis of {@code length}. */
    public static int mirroredIndex(int i, int length) {
        int local = i % length;
        return (i / length) % 2 == 0 ? local : length - 1 - local;
    }

    /**
     * {@code dem} turned 90° clockwise (its north edge becomes the east edge) on a metric grid of its cell size;
     * the cells must be square.
     */
    public static Dem rotateClockwise(Dem dem) {
        GridGeometry g = dem.geometry();
        if (g.cellWidth() != g.cellHeight()) {
            throw new IllegalArgumentException("a quarter turn needs square cells, not " + g.cellWidth() + " × "
                    + g.cellHeight());
        }
        return metric(dem.height(), dem.width(), g.cellWidth(),
                rotateClockwise(dem.backingArray(), dem.width(), dem.height()));
    }

    /** A copy of the row-major {@code width × height} grid {@code a}, turned as {@link #rotateClockwise(Dem)}. */
    public static float[] rotateClockwise(float[] a, int width, int height) {
        float[] out = new float[width * height];
        // new width = height, new height = width; new (c', r') = old (c = r', r = height − 1 − c')
        for (int r2 = 0; r2 < width; r2++) {
            for (int c2 = 0; c2 < height; c2++) {
                out[r2 * height + c2] = a[(height - 1 - c2) * width + r2];
            }
        }
        return out;
    }

    /**
     * A realistic-looking rendered product for encoder measurements and tests: a fractal terrain (eight octaves of
     * smoothly interpolated value noise), shaded with a Lambertian hillshade (light from the north-west, 45° up) and
     * tinted from green through brown to white. Cells below "sea level" are no-data (alpha 0 in the colour image, 0
     * in the gray one), like a DEM with a masked ocean.
     */
    public static ShadedRelief shadedRelief(int width, int height, long seed) {
        float[] z = valueNoiseTerrain(width, height, seed);
        int[] argb = new int[width * height];
        byte[] gray = new byte[width * height];
        double lx = -Math.sqrt(0.25), ly = Math.sqrt(0.25), lz = Math.sqrt(0.5); // NW, 45° altitude
        float exaggeration = 0.05f * Math.max(width, height); // relief of a mountain range at any image size
        for (int r = 0; r < height; r++) {
            for (int c = 0; c < width; c++) {
                int i = r * width + c;
                if (z[i] < 0.38f) {
                    continue; // sea: no-data
                }
                float dzdx = (z[r * width + Math.min(width - 1, c + 1)] - z[r * width + Math.max(0, c - 1)])
                        * exaggeration;
                float dzdy = (z[Math.max(0, r - 1) * width + c] - z[Math.min(height - 1, r + 1) * width + c])
                        * exaggeration;
                double n = Math.sqrt(dzdx * dzdx + dzdy * dzdy + 1);
                double shade = Math.max(0, (-dzdx * lx - dzdy * ly + lz) / n);
                int g = 1 + (int) Math.round(shade * 254);
                gray[i] = (byte) g;
                int[] tint = tint(z[i]);
                int red = (int) Math.round(tint[0] * (0.35 + 0.65 * shade));
                int grn = (int) Math.round(tint[1] * (0.35 + 0.65 * shade));
                int blu = (int) Math.round(tint[2] * (0.35 + 0.65 * shade));
                argb[i] = 0xFF000000 | red << 16 | grn << 8 | blu;
            }
        }
        return new ShadedRelief(width, height, argb, gray);
    }

    /**
     * The picture of {@link #shadedRelief}.
     *
     * @param argb non-premultiplied ARGB, row-major; no-data pixels are 0x00000000
     * @param gray the hillshade, 1..255; no-data is 0
     */
    public record ShadedRelief(int width, int height, int[] argb, byte[] gray) {
    }

    /** The fractal terrain of {@link #shadedRelief}, about 0 to 1, row-major. */
    public static float[] valueNoiseTerrain(int width, int height, long seed) {
        float[] z = new float[width * height];
        double amplitude = 0.5;
        double cells = 4;
        for (int octave = 0; octave < 8; octave++) {
            double scale = cells / Math.max(width, height);
            for (int r = 0; r < height; r++) {
                for (int c = 0; c < width; c++) {
                    z[r * width + c] += (float) (amplitude * valueNoise(c * scale, r * scale, seed + octave));
                }
            }
            amplitude *= 0.5;
            cells *= 2.3;
        }
        return z;
    }

    private static int[] tint(float z) {
        float t = Math.min(1, Math.max(0, (z - 0.38f) / 0.5f));
        int[][] stops = {{70, 140, 60}, {160, 150, 80}, {140, 100, 60}, {250, 250, 250}};
        float p = t * (stops.length - 1);
        int k = Math.min(stops.length - 2, (int) p);
        float f = p - k;
        return new int[]{Math.round(stops[k][0] + f * (stops[k + 1][0] - stops[k][0])),
                Math.round(stops[k][1] + f * (stops[k + 1][1] - stops[k][1])),
                Math.round(stops[k][2] + f * (stops[k + 1][2] - stops[k][2]))};
    }

    private static double valueNoise(double x, double y, long seed) {
        int x0 = (int) Math.floor(x);
        int y0 = (int) Math.floor(y);
        double fx = smooth(x - x0);
        double fy = smooth(y - y0);
        double a = lattice(x0, y0, seed);
        double b = lattice(x0 + 1, y0, seed);
        double c = lattice(x0, y0 + 1, seed);
        double d = lattice(x0 + 1, y0 + 1, seed);
        return (a + (b - a) * fx) + ((c + (d - c) * fx) - (a + (b - a) * fx)) * fy;
    }

    private static double smooth(double t) {
        return t * t * (3 - 2 * t);
    }

    private static double lattice(int x, int y, long seed) {
        long h = seed * 0x9E3779B97F4A7C15L + x * 0xC2B2AE3D27D4EB4FL + y * 0x165667B19E3779F9L;
        h ^= h >>> 33;
        h *= 0xFF51AFD7ED558CCDL;
        h ^= h >>> 33;
        return (h >>> 11) / (double) (1L << 53);
    }
}
