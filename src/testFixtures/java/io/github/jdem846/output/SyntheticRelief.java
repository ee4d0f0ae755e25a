package io.github.jdem846.output;

/**
 * Realistic-looking rendered products for encoder measurements and tests: a fractal terrain (eight octaves of
 * smoothly interpolated value noise), shaded with a Lambertian hillshade (light from the north-west, 45° up) and
 * tinted from green through brown to white. Cells below "sea level" are no-data (alpha 0 in the colour image, 0 in
 * the gray one), like a DEM with a masked ocean. Deterministic for a given size and seed.
 */
final class SyntheticRelief {

    final int width;
    final int height;
    /** Non-premultiplied ARGB, row-major; no-data pixels are 0x00000000. */
    final int[] argb;
    /** The hillshade, 1..255; no-data is 0. */
    final byte[] gray;

    SyntheticRelief(int width, int height, long seed) {
        this.width = width;
        this.height = height;
        float[] z = terrain(width, height, seed);
        argb = new int[width * height];
        gray = new byte[width * height];
        double lx = -Math.sqrt(0.25), ly = Math.sqrt(0.25), lz = Math.sqrt(0.5); // NW, 45° altitude
        float exaggeration = 0.05f * Math.max(width, height); // relief of a mountain range at any image size
        for (int r = 0; r < height; r++) {
            for (int c = 0; c < width; c++) {
                int i = r * width + c;
                if (z[i] < 0.38f) {
                    continue; // sea: no-data
                }
                float dzdx = (z[r * width + Math.min(width - 1, c + 1)] - z[r * width + Math.max(0, c - 1)]) * exaggeration;
                float dzdy = (z[Math.max(0, r - 1) * width + c] - z[Math.min(height - 1, r + 1) * width + c]) * exaggeration;
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

    private static float[] terrain(int width, int height, long seed) {
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
