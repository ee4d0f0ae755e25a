package io.github.jdem846.shade;

import io.github.jdem846.internal.Clamp;

/**
 * {@link JDem846Illumination}'s formula for a run of cells of one row whose 3×3 windows are inside the grid and
 * finite ({@link FiniteWindows}), in separate simple loops over the run so that HotSpot's C2 compiles the five
 * square roots and divisions per cell to SIMD instructions (4 cells at a time with AVX2). The numbers are the
 * per-cell path's ({@code cosineOfIncidence}), bit for bit: the same floating-point expressions in the same order.
 * Holds scratch arrays: one instance per thread.
 */
final class JDem846Rows {

    /**
     * Cells per pass of the loops: a longer run is done in pieces of this many, so that the scratch arrays stay in
     * the L1 cache (JMH over whole 2048-cell rows was slower without).
     */
    static final int CHUNK = 256;

    /**
     * Smallest cell spacing, metres, of a row shaded here: with both spacings at least this and at most
     * {@link CellSpacing#MAX_SPACING_METERS}, finite heights and a height factor of at most 10¹², no squared length
     * below is 0 or overflows (the mean's z component is at least about 10⁻⁶⁵), so the per-cell path's "length 0"
     * cases cannot arise.
     */
    static final double MIN_SPACING = 1e-3;

    private final KernelShape shape;
    private final double k;
    private final double le;
    private final double ln;
    private final double lu;
    private final boolean belowHorizon;
    private final double[] aW;
    private final double[] aE;
    private final double[] bN;
    private final double[] bS;
    private final double[] iWN;
    private final double[] iWS;
    private final double[] iES;
    private final double[] iEN;
    private final double[] x;
    private final double[] y;
    private final double[] z;

    /**
     * @param maxRun       longest run to be shaded (scratch arrays are sized for at most {@link #CHUNK} cells)
     * @param k            z-factor × light multiple
     * @param le           the light's east component
     * @param ln           its north component
     * @param lu           its up component
     * @param belowHorizon the light is at or below the horizon
     * @param shape        the loops' shape; {@link KernelShape#FUSED} needs none of the chunk arrays
     */
    JDem846Rows(int maxRun, double k, double le, double ln, double lu, boolean belowHorizon, KernelShape shape) {
        this.shape = shape;
        this.k = k;
        this.le = le;
        this.ln = ln;
        this.lu = lu;
        final int chunk = shape == KernelShape.FUSED ? 0 : Math.min(maxRun, CHUNK);
        this.belowHorizon = belowHorizon;
        aW = new double[chunk];
        aE = new double[chunk];
        bN = new double[chunk];
        bS = new double[chunk];
        iWN = new double[chunk];
        iWS = new double[chunk];
        iES = new double[chunk];
        iEN = new double[chunk];
        x = new double[chunk];
        y = new double[chunk];
        z = new double[chunk + 2];
    }

    /**
     * Whether rows with these cell spacings can be shaded here: both in [{@link #MIN_SPACING},
     * {@link CellSpacing#MAX_SPACING_METERS}].
     */
    static boolean applies(double dx, double dy) {
        return dx >= MIN_SPACING && dy >= MIN_SPACING && dx <= CellSpacing.MAX_SPACING_METERS
                && dy <= CellSpacing.MAX_SPACING_METERS;
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
        final int mid = r * width + a;
        // The rows as doubles (in x, y, z, free until further down), then the four neighbours relative to the
        // centre, times k, times the spacing: the per-cell path's aW, aE, bN, bS ("dy * zW", "-dy * zE",
        // "-dx * zN", "dx * zS" with zW = ((double) west − centre) · k).
        final double[] m = z;
        final double[] t = x;
        final double[] u = y;
        toDouble(v, mid - 1, m, n + 2);
        toDouble(v, mid - width, t, n);
        toDouble(v, mid + width, u, n);
        relative(m, 0, m, dy, k, aW, n);
        relative(m, 2, m, -dy, k, aE, n);
        relative(t, 0, m, -dx, k, bN, n);
        relative(u, 0, m, dx, k, bS, n);
        final double c = dx * dy;
        final double cc = c * c;
        inverseLengths(aW, bN, cc, iWN, n);
        inverseLengths(aW, bS, cc, iWS, n);
        inverseLengths(aE, bS, cc, iES, n);
        inverseLengths(aE, bN, cc, iEN, n);
        weighted(aW, iWN, iWS, aE, iES, iEN, x, n);
        weighted(bN, iWN, iEN, bS, iWS, iES, y, n);
        upward(c, iWN, iWS, iES, iEN, z, n);
        // the length of the mean, then the dot product with the light divided by it (in iWN: free now)
        lengths(x, y, z, iWN, n);
        cosines(x, y, z, le, ln, lu, iWN, n);
        store(iWN, belowHorizon, out, o, n);
    }

    /** The steps of {@link #shadeChunk} for one cell at a time, in one loop ({@link KernelShape#FUSED}). */
    private void shadeFused(float[] v, int width, int r, int a, int b, double dx, double dy, float[] out, int o) {
        final double c = dx * dy;
        final double cc = c * c;
        final int mid = r * width + a;
        final int n = b - a;
        for (int j = 0; j < n; j++) {
            final double centre = v[mid + j];
            final double w = dy * (((double) v[mid + j - 1] - centre) * k);
            final double e = -dy * (((double) v[mid + j + 1] - centre) * k);
            final double north = -dx * (((double) v[mid + j - width] - centre) * k);
            final double south = dx * (((double) v[mid + j + width] - centre) * k);
            final double iWN = 1.0 / Math.sqrt(w * w + north * north + cc);
            final double iWS = 1.0 / Math.sqrt(w * w + south * south + cc);
            final double iES = 1.0 / Math.sqrt(e * e + south * south + cc);
            final double iEN = 1.0 / Math.sqrt(e * e + north * north + cc);
            final double x = w * (iWN + iWS) + e * (iES + iEN);
            final double y = north * (iWN + iEN) + south * (iWS + iES);
            final double z = c * (iWN + iWS + iES + iEN);
            final double cos = (x * le + y * ln + z * lu) / Math.sqrt(x * x + y * y + z * z);
            out[o + j] = (float) Clamp.between(belowHorizon && cos > 0 ? 0.0 : cos, -1.0, 1.0);
        }
    }

    // One loop per method: small compilations, and no on-stack replacement of a method with many loops (which
    // HotSpot compiled once per loop, slowing a one-shot command down).

    private static void toDouble(float[] v, int from, double[] dst, int n) {
        for (int j = 0; j < n; j++) {
            dst[j] = v[from + j];
        }
    }

    /** f · ((neighbour − centre) · k), the centre being {@code m[j + 1]}. */
    private static void relative(double[] src, int off, double[] m, double f, double k, double[] dst, int n) {
        for (int j = 0; j < n; j++) {
            dst[j] = f * ((src[off + j] - m[j + 1]) * k);
        }
    }

    /** 1/length of a triangle's normal (a, b, c); the squared lengths are ≥ cc > 0 here. */
    private static void inverseLengths(double[] a, double[] b, double cc, double[] dst, int n) {
        for (int j = 0; j < n; j++) {
            dst[j] = 1.0 / Math.sqrt(a[j] * a[j] + b[j] * b[j] + cc);
        }
    }

    /** One horizontal component of the sum of the four unit normals. */
    private static void weighted(double[] a, double[] p, double[] q, double[] b, double[] r, double[] s, double[] dst,
                                 int n) {
        for (int j = 0; j < n; j++) {
            dst[j] = a[j] * (p[j] + q[j]) + b[j] * (r[j] + s[j]);
        }
    }

    /** The up component of the sum of the four unit normals. */
    private static void upward(double c, double[] p, double[] q, double[] r, double[] s, double[] dst, int n) {
        for (int j = 0; j < n; j++) {
            dst[j] = c * (p[j] + q[j] + r[j] + s[j]);
        }
    }

    private static void lengths(double[] x, double[] y, double[] z, double[] len, int n) {
        for (int j = 0; j < n; j++) {
            len[j] = Math.sqrt(x[j] * x[j] + y[j] * y[j] + z[j] * z[j]);
        }
    }

    /** The dot products over the lengths, in place; apart from the roots, which C2 (JDK 17) left scalar with it. */
    private static void cosines(double[] x, double[] y, double[] z, double le, double ln, double lu, double[] len,
                                int n) {
        for (int j = 0; j < n; j++) {
            len[j] = (x[j] * le + y[j] * ln + z[j] * lu) / len[j];
        }
    }

    private static void store(double[] d, boolean belowHorizon, float[] out, int o, int n) {
        if (belowHorizon) {
            for (int j = 0; j < n; j++) {
                final double dj = d[j];
                out[o + j] = (float) Clamp.between(dj > 0 ? 0.0 : dj, -1.0, 1.0);
            }
        } else {
            for (int j = 0; j < n; j++) {
                out[o + j] = (float) Clamp.between(d[j], -1.0, 1.0);
            }
        }
    }
}
