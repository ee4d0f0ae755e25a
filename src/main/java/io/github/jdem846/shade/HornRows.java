package io.github.jdem846.shade;

import io.github.jdem846.internal.Clamp;

/**
 * {@link HornIllumination}'s formula for a run of cells of one row whose 3×3 windows are inside the grid and finite
 * ({@link FiniteWindows}), in separate simple loops over the run so that HotSpot's C2 compiles the square roots and
 * divisions to SIMD instructions (4 cells at a time with AVX2); one loop doing everything stays scalar. The numbers
 * are the per-cell path's, bit for bit: the same floating-point expressions in the same order, only shared
 * between neighbouring cells — the east-minus-west sum is S(c+1) − S(c−1) with the column sums
 * S(j) = top(j) + 2·mid(j) + bottom(j), which is what the window's (w2 + 2w5 + w8) − (w0 + 2w3 + w6) adds up.
 * Holds scratch arrays: one instance per thread.
 */
final class HornRows {

    /**
     * Cells per pass of the loops: a longer run is done in pieces of this many, so that the scratch arrays stay in
     * the L1 cache (JMH over whole 2048-cell rows was slower without).
     */
    static final int CHUNK = 256;

    private final KernelShape shape;
    private final double zf;
    private final double le;
    private final double ln;
    private final double lu;
    private final double[] top;
    private final double[] bottom;
    private final double[] columnSum;
    private final double[] nx;
    private final double[] ny;
    private final double[] len;

    /**
     * @param maxRun longest run to be shaded (scratch arrays are sized for at most {@link #CHUNK} cells)
     * @param zf     the z-factor divided by 8
     * @param le     the light's east component
     * @param ln     its north component
     * @param lu     its up component
     * @param shape  the loops' shape; {@link KernelShape#FUSED} needs none of the chunk arrays
     */
    HornRows(int maxRun, double zf, double le, double ln, double lu, KernelShape shape) {
        this.shape = shape;
        this.zf = zf;
        this.le = le;
        this.ln = ln;
        this.lu = lu;
        final int chunk = shape == KernelShape.FUSED ? 0 : Math.min(maxRun, CHUNK);
        top = new double[chunk + 2];
        bottom = new double[chunk + 2];
        columnSum = new double[chunk + 2];
        nx = new double[chunk];
        ny = new double[chunk];
        len = new double[chunk];
    }

    /**
     * Whether rows with these cell sizes can be shaded here: the cell has an area, so the normal is never of
     * length 0 and the per-cell path's "length 0" case cannot arise.
     */
    static boolean applies(double dx, double dy) {
        final double area = dx * dy;
        return area * area > 0;
    }

    /**
     * Shades cells [{@code a}, {@code b}) of row {@code r} into {@code out} from index {@code o}.
     *
     * @param v     the grid, row-major
     * @param width grid width
     * @param r     the row, 1 … height − 2
     * @param a     first column, ≥ 1, every window of the run finite
     * @param b     end column, ≤ width − 1
     * @param dx    east–west cell spacing of the row, with {@link #applies}
     * @param dy    north–south cell spacing of the row
     */
    void shade(float[] v, int width, int r, int a, int b, double dx, double dy, float[] out, int o) {
        if (shape == KernelShape.FUSED) {
            shadeFused(v, width, r, a, b, dx, dy, out, o);
            return;
        }
        for (int from = a; from < b; from += CHUNK) {
            shadeChunk(v, width, r, from, Math.min(b, from + CHUNK), dx, dy, out, o + from - a);
        }
    }

    /** {@link #shade} of at most {@link #CHUNK} cells. */
    private void shadeChunk(float[] v, int width, int r, int a, int b, double dx, double dy, float[] out, int o) {
        final int n = b - a;
        final int up = (r - 1) * width + a - 1;
        columnSums(v, up, width, top, bottom, columnSum, n + 2);
        // −zf · sum · spacing, as the per-cell path's "-zf * gx * dy" groups it
        final double mzf = -zf;
        eastMinusWest(columnSum, mzf, dy, nx, n);
        northMinusSouth(top, bottom, mzf, dx, ny, n);
        final double area = dx * dy;
        lengths(nx, ny, area * area, len, n);
        cosines(nx, ny, le, ln, area * lu, len, n);
        store(len, out, o, n);
    }

    /** The steps of {@link #shadeChunk} for one cell at a time, in one loop ({@link KernelShape#FUSED}). */
    private void shadeFused(float[] v, int width, int r, int a, int b, double dx, double dy, float[] out, int o) {
        final double mzf = -zf;
        final double area = dx * dy;
        final double areaSquared = area * area;
        final double areaUp = area * lu;
        final int up = (r - 1) * width + a - 1;
        final int mid = up + width;
        final int down = mid + width;
        final int n = b - a;
        for (int k = 0; k < n; k++) {
            final double t0 = v[up + k];
            final double t2 = v[up + k + 2];
            final double u0 = v[down + k];
            final double u2 = v[down + k + 2];
            final double west = t0 + 2 * (double) v[mid + k] + u0;
            final double east = t2 + 2 * (double) v[mid + k + 2] + u2;
            final double x = mzf * (east - west) * dy;
            final double y = mzf * ((t0 + 2 * (double) v[up + k + 1] + t2) - (u0 + 2 * (double) v[down + k + 1] + u2))
                    * dx;
            final double len = Math.sqrt(x * x + y * y + areaSquared);
            out[o + k] = (float) Clamp.between((x * le + y * ln + areaUp) / len, -1.0, 1.0);
        }
    }

    // One loop per method: small compilations, and no on-stack replacement of a method with many loops (which
    // HotSpot compiled once per loop, slowing a one-shot command down).

    /** The rows above and below as doubles, and the column sums top + 2·mid + bottom. */
    private static void columnSums(float[] v, int up, int width, double[] t, double[] u, double[] s, int n) {
        final int mid = up + width;
        final int down = mid + width;
        for (int j = 0; j < n; j++) {
            final double tj = v[up + j];
            final double uj = v[down + j];
            t[j] = tj;
            u[j] = uj;
            s[j] = tj + 2 * (double) v[mid + j] + uj;
        }
    }

    private static void eastMinusWest(double[] s, double mzf, double dy, double[] x, int n) {
        for (int k = 0; k < n; k++) {
            x[k] = mzf * (s[k + 2] - s[k]) * dy;
        }
    }

    private static void northMinusSouth(double[] t, double[] u, double mzf, double dx, double[] y, int n) {
        for (int k = 0; k < n; k++) {
            y[k] = mzf * ((t[k] + 2 * t[k + 1] + t[k + 2]) - (u[k] + 2 * u[k + 1] + u[k + 2])) * dx;
        }
    }

    private static void lengths(double[] x, double[] y, double areaSquared, double[] l, int n) {
        for (int k = 0; k < n; k++) {
            l[k] = Math.sqrt(x[k] * x[k] + y[k] * y[k] + areaSquared);
        }
    }

    /** The dot products over the lengths, in place; apart from the roots, which C2 (JDK 17) left scalar with it. */
    private static void cosines(double[] x, double[] y, double le, double ln, double areaUp, double[] l, int n) {
        for (int k = 0; k < n; k++) {
            l[k] = (x[k] * le + y[k] * ln + areaUp) / l[k];
        }
    }

    private static void store(double[] c, float[] out, int o, int n) {
        for (int k = 0; k < n; k++) {
            out[o + k] = (float) Clamp.between(c[k], -1.0, 1.0);
        }
    }
}
