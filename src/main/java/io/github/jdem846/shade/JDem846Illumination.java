package io.github.jdem846.shade;

import io.github.jdem846.internal.Clamp;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import java.util.Objects;

/**
 * The jDem846 hillshade (article section 3, eq. 4–7): the cosine of the angle between each cell's vertex normal
 * and the light.
 *
 * <p>Frame: x = east, y = north, z = up (right-handed), metres. The centre cell C sits at the origin; its
 * 4-neighbours are E = (Δx, 0, z<sub>E</sub>), W = (−Δx, 0, z<sub>W</sub>), N = (0, Δy, z<sub>N</sub>),
 * S = (0, −Δy, z<sub>S</sub>), heights relative to C and multiplied by z-factor × light multiple, Δx and Δy the
 * row's metric cell width and height ({@link CellSpacing}). (The original used x = east, y = up, z = south; the
 * same right-handed geometry with other axis names.)
 * <ol>
 *   <li>eq. 5 (with eq. 12, 14, 16): a unit normal for each of the four triangles (W, C, N), (W, S, C), (C, S, E),
 *       (N, C, E): A = P0 − P1, B = P1 − P2, N = normalise(A × B), where a zero vector stays zero (L = 0 → 1);</li>
 *   <li>eq. 6: their mean;</li>
 *   <li>eq. 7: the dot product of the <em>normalised</em> mean with the unit light vector ({@link LightDirection},
 *       eq. 4). The original divided the sum by 4 and did not renormalise, so the value shrank on rough ground and
 *       was not a cosine; eq. 7 itself normalises both inputs, and renormalising makes a plane of any slope give
 *       exactly its analytic cosine of incidence. A mean of length 0 (only on a degenerate cell of zero width with
 *       no relief) is taken as straight up.</li>
 * </ol>
 *
 * <p>Missing neighbours, whether outside the grid or no-data, are never used as numbers. Each is extrapolated
 * linearly through the centre from the opposite neighbour (z<sub>W</sub> = 2z<sub>C</sub> − z<sub>E</sub>, as
 * gdaldem {@code -compute_edges} does at the grid edge); if the opposite neighbour is missing too, the axis has no
 * slope information and gets zero slope (z<sub>W</sub> = z<sub>E</sub> = z<sub>C</sub>). On a plane this
 * reproduces the plane exactly, so neither the grid edge nor a hole makes a ring. No-data cells give NaN.
 *
 * <p>Light at or below the horizon ({@link LightDirection#isBelowHorizon()}): there is no direct light, so the
 * result is min(cosine, 0): nothing is lit, flat ground gets sin(elevation) ≤ 0 and slopes facing away from the
 * light darken as usual.
 *
 * <p>Cells whose 3×3 window is inside the grid and finite are computed a row segment at a time by
 * {@link JDem846Rows} (SIMD-friendly loops, the same floats); the others one by one ({@link #general}).
 */
final class JDem846Illumination implements IlluminationStage {

    private final HillshadeOptions options;
    private final KernelShape shape;

    public JDem846Illumination(HillshadeOptions options) {
        this(options, KernelShape.CHOSEN);
    }

    /** With the row kernels' loops in {@code shape} (the same floats either way). */
    JDem846Illumination(HillshadeOptions options, KernelShape shape) {
        this.options = Objects.requireNonNull(options, "options");
        this.shape = Objects.requireNonNull(shape, "shape");
    }

    public HillshadeOptions options() {
        return options;
    }

    @Override
    public void illuminate(Dem dem, LightDirection light, int col0, int row0, int w, int h, float[] out) {
        StageArguments.check(dem, light, col0, row0, w, h, out);
        final double le = light.east();
        final double ln = light.north();
        final double lu = light.up();
        final boolean belowHorizon = light.isBelowHorizon();
        final double k = options.zFactor() * options.lightMultiple();
        final CellSpacing spacing = new CellSpacing(dem.geometry(), options);
        final float[] v = dem.backingArray();
        final int width = dem.width();
        final int height = dem.height();
        final FiniteWindows windows = new FiniteWindows(v, width, height, col0, row0, w, h,
                dem.knownAllFinite());
        final int[] runs = new int[FiniteWindows.runsLength(w)];
        final JDem846Rows rows = new JDem846Rows(w, k, le, ln, lu, belowHorizon, shape);
        for (int r = row0; r < row0 + h; r++) {
            final double dx = spacing.eastWest(r);
            final double dy = spacing.northSouth(r);
            final int o = (r - row0) * w - col0;
            final int n = JDem846Rows.applies(dx, dy) ? windows.runs(r, runs) : 0;
            int c = col0;
            for (int i = 0; i < n; i += 2) {
                for (; c < runs[i]; c++) {
                    out[o + c] = cell(v, width, height, c, r, dx, dy, k, le, ln, lu, belowHorizon);
                }
                rows.shade(v, width, r, runs[i], runs[i + 1], dx, dy, out, o + runs[i]);
                c = runs[i + 1];
            }
            for (; c < col0 + w; c++) {
                out[o + c] = cell(v, width, height, c, r, dx, dy, k, le, ln, lu, belowHorizon);
            }
        }
    }

    /** {@link #general}, or NaN for a no-data centre. */
    private static float cell(float[] v, int width, int height, int c, int r, double dx, double dy, double k,
                              double le, double ln, double lu, boolean belowHorizon) {
        return Float.isNaN(v[r * width + c]) ? Float.NaN
                : general(v, width, height, c, r, dx, dy, k, le, ln, lu, belowHorizon);
    }

    /**
     * One cell (centre not no-data) with the neighbours read with bounds checks and a missing one filled: the cells
     * {@link JDem846Rows} does not take, and the reference it must equal (WindowKernelEquivalenceTest).
     */
    static float general(float[] v, int width, int height, int c, int r, double dx, double dy, double k, double le,
                         double ln, double lu, boolean belowHorizon) {
        final int rowStart = r * width;
        final float zc = v[rowStart + c];
        // Heights relative to the centre, in double (float32 extremes cannot overflow); NaN = missing.
        double e = c + 1 < width ? (double) v[rowStart + c + 1] - zc : Double.NaN;
        double wv = c > 0 ? (double) v[rowStart + c - 1] - zc : Double.NaN;
        double n = r > 0 ? (double) v[rowStart - width + c] - zc : Double.NaN;
        double s = r + 1 < height ? (double) v[rowStart + width + c] - zc : Double.NaN;
        // Extrapolate a missing neighbour through the centre; zero slope when both are missing.
        final double eFilled = !Double.isNaN(e) ? e : !Double.isNaN(wv) ? -wv : 0.0;
        final double wFilled = !Double.isNaN(wv) ? wv : !Double.isNaN(e) ? -e : 0.0;
        final double nFilled = !Double.isNaN(n) ? n : !Double.isNaN(s) ? -s : 0.0;
        final double sFilled = !Double.isNaN(s) ? s : !Double.isNaN(n) ? -n : 0.0;
        double d = cosineOfIncidence(dx, dy, eFilled * k, wFilled * k, nFilled * k, sFilled * k, le, ln, lu);
        if (belowHorizon && d > 0) {
            d = 0.0;
        }
        return (float) Clamp.between(d, -1.0, 1.0);
    }

    /**
     * The unit vertex normal of a cell from its four neighbours (eq. 5, 6 and the normalisation of eq. 7): C at the
     * origin, E = (dx, 0, zE), W = (−dx, 0, zW), N = (0, dy, zN), S = (0, −dy, zS). Writes (east, north, up) into
     * {@code normal}.
     *
     * <p>With C at the origin the cross products of eq. 12 have closed forms, each triangle's normal being
     * (dy·a, dx·b, dx·dy) with a ∈ {zW, −zE} and b ∈ {−zN, zS}:
     * (W, C, N) → (dy·zW, −dx·zN, dx·dy), (W, S, C) → (dy·zW, dx·zS, dx·dy), (C, S, E) → (−dy·zE, dx·zS, dx·dy),
     * (N, C, E) → (−dy·zE, −dx·zN, dx·dy). Written out, the kernel needs five square roots and five divisions per
     * cell instead of the generic cross products' many multiplications by zero (which IEEE arithmetic forbids the
     * compiler to drop).
     */
    static void vertexNormal(double dx, double dy, double zE, double zW, double zN, double zS, double[] normal) {
        normal[0] = cosineOfIncidence(dx, dy, zE, zW, zN, zS, 1, 0, 0);
        normal[1] = cosineOfIncidence(dx, dy, zE, zW, zN, zS, 0, 1, 0);
        normal[2] = cosineOfIncidence(dx, dy, zE, zW, zN, zS, 0, 0, 1);
    }

    /**
     * Eq. 7: the dot product of the unit vertex normal ({@link #vertexNormal}) with the unit light vector
     * (east, north, up).
     */
    private static double cosineOfIncidence(double dx, double dy, double zE, double zW, double zN, double zS,
                                            double le, double ln, double lu) {
        final double aW = dy * zW;
        final double aE = -dy * zE;
        final double bN = -dx * zN;
        final double bS = dx * zS;
        final double c = dx * dy;
        final double cc = c * c;
        // eq. 14–16: each triangle's normal divided by its length (a zero normal stays zero).
        final double iWN = inverseLength(aW * aW + bN * bN + cc);
        final double iWS = inverseLength(aW * aW + bS * bS + cc);
        final double iES = inverseLength(aE * aE + bS * bS + cc);
        final double iEN = inverseLength(aE * aE + bN * bN + cc);
        // eq. 6: their sum (the mean's direction), then eq. 7 with the sum normalised.
        final double x = aW * (iWN + iWS) + aE * (iES + iEN);
        final double y = bN * (iWN + iEN) + bS * (iWS + iES);
        final double z = c * (iWN + iWS + iES + iEN);
        final double len = Math.sqrt(x * x + y * y + z * z);
        return len > 0 ? (x * le + y * ln + z * lu) / len : lu; // a zero mean: no extent, no relief, flat
    }

    /** 1/√{@code squaredLength}, or 0 for a zero vector (eq. 14's L = 0 case adds nothing). */
    private static double inverseLength(double squaredLength) {
        return squaredLength > 0 ? 1.0 / Math.sqrt(squaredLength) : 0.0;
    }
}
