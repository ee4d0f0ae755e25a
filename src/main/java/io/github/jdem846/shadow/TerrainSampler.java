package io.github.jdem846.shadow;

/**
 * Reads a DEM at fractional grid positions. Position (x, y) is in cell units with cell (c, r)'s centre at (c, r);
 * the grid covers [−0.5, width − 0.5] × [−0.5, height − 0.5] (its outer cell edges, the article's N/S/E/W limits).
 */
final class TerrainSampler {

    private TerrainSampler() {
    }

    /** True when (x, y) lies outside the grid's outer edges (the article's test 2). */
    static boolean isOutside(double x, double y, int w, int h) {
        return !(x >= -0.5 && x <= w - 0.5 && y >= -0.5 && y <= h - 0.5);
    }

    /** The elevation of the cell containing (x, y) (NaN = no-data). (x, y) must be inside the grid. */
    static double nearest(float[] v, int w, int h, double x, double y) {
        int c = clamp((int) Math.floor(x + 0.5), w);
        int r = clamp((int) Math.floor(y + 0.5), h);
        return v[r * w + c];
    }

    /**
     * Bilinear interpolation between the four cell centres around (x, y), clamped at the grid edge. No-data corners
     * are left out and the weights of the others renormalised; NaN when every corner with a positive weight is
     * no-data.
     */
    static double bilinear(float[] v, int w, int h, double x, double y) {
        // Math.min(Math.max(x, 0), w − 1), by comparisons (see io.github.jdem846.internal.Clamp): x is never NaN here
        double cx = x <= 0 ? 0 : x >= w - 1 ? w - 1 : x;
        double cy = y <= 0 ? 0 : y >= h - 1 ? h - 1 : y;
        int c0 = (int) Math.floor(cx);
        int r0 = (int) Math.floor(cy);
        double fx = cx - c0;
        double fy = cy - r0;
        int c1 = Math.min(c0 + 1, w - 1);
        int r1 = Math.min(r0 + 1, h - 1);
        float z00 = v[r0 * w + c0];
        float z10 = v[r0 * w + c1];
        float z01 = v[r1 * w + c0];
        float z11 = v[r1 * w + c1];
        double w00 = (1 - fx) * (1 - fy);
        double w10 = fx * (1 - fy);
        double w01 = (1 - fx) * fy;
        double w11 = fx * fy;
        if (z00 == z00 && z10 == z10 && z01 == z01 && z11 == z11) {
            return w00 * z00 + w10 * z10 + w01 * z01 + w11 * z11;
        }
        double sum = 0;
        double wsum = 0;
        if (z00 == z00 && w00 > 0) {
            sum += w00 * z00;
            wsum += w00;
        }
        if (z10 == z10 && w10 > 0) {
            sum += w10 * z10;
            wsum += w10;
        }
        if (z01 == z01 && w01 > 0) {
            sum += w01 * z01;
            wsum += w01;
        }
        if (z11 == z11 && w11 > 0) {
            sum += w11 * z11;
            wsum += w11;
        }
        return wsum > 0 ? sum / wsum : Double.NaN;
    }

    private static int clamp(int i, int n) {
        return i < 0 ? 0 : (i >= n ? n - 1 : i);
    }
}
