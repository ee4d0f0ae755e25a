package io.github.jdem846.shade;

import io.github.jdem846.internal.Clamp;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import java.util.Objects;

/**
 * gdaldem's default hillshade ({@code gdaldem hillshade -compute_edges}, GDAL 3.6 {@code GDALHillshadeAlg}): Horn's
 * (1981) 3×3 gradient and the cosine of incidence on the plane it defines.
 *
 * <p>With the window of {@link GdalWindow} (0 = NW … 8 = SE), Δx, Δy the cell sizes in metres and z the z-factor:
 * <pre>
 *   ∂z/∂east  = z · ((w2 + 2w5 + w8) − (w0 + 2w3 + w6)) / (8Δx)
 *   ∂z/∂north = z · ((w0 + 2w1 + w2) − (w6 + 2w7 + w8)) / (8Δy)
 *   cos i     = (sin alt − cos alt · (∂z/∂east · sin az + ∂z/∂north · cos az)) / √(1 + (∂z/∂east)² + (∂z/∂north)²)
 * </pre>
 * which is the dot product of the unit normal (−∂z/∂east, −∂z/∂north, 1)/‖·‖ with the light (east, north, up) of
 * {@link LightDirection}. It is computed multiplied through by Δx·Δy, so a cell of zero width (a pole) gives a
 * vertical face instead of an infinity, and a window without extent or relief gives sin alt. The light is used as
 * given, also at or below the horizon, as gdaldem does. gdaldem's bytes are {@link HillshadeMethod#gray}.
 * Deviation: gdaldem approximates 1/√ with an SSE estimate plus one Newton step (relative error ≈ 1e−7); this uses
 * an exact square root.
 *
 * <p>Cells whose window is inside the grid and finite are computed a row segment at a time by {@link HornRows}
 * (SIMD-friendly loops, the same floats); the others one by one through {@link GdalWindow} ({@link #cell}).
 */
final class HornIllumination implements IlluminationStage {

    private final HillshadeOptions options;
    private final KernelShape shape;

    public HornIllumination(HillshadeOptions options) {
        this(options, KernelShape.CHOSEN);
    }

    /** With the row kernels' loops in {@code shape} (the same floats either way). */
    HornIllumination(HillshadeOptions options, KernelShape shape) {
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
        final double zf = options.zFactor() / 8.0;
        final CellSpacing spacing = new CellSpacing(dem.geometry(), options);
        final float[] v = dem.backingArray();
        final int width = dem.width();
        final int height = dem.height();
        final double[] win = new double[9];
        final FiniteWindows windows = new FiniteWindows(v, width, height, col0, row0, w, h,
                dem.knownAllFinite());
        final int[] runs = new int[FiniteWindows.runsLength(w)];
        final HornRows rows = new HornRows(w, zf, le, ln, lu, shape);
        for (int r = row0; r < row0 + h; r++) {
            final double dx = spacing.eastWest(r);
            final double dy = spacing.northSouth(r);
            final double area = dx * dy;
            final int o = (r - row0) * w - col0;
            final int n = HornRows.applies(dx, dy) ? windows.runs(r, runs) : 0;
            int c = col0;
            for (int i = 0; i < n; i += 2) {
                for (; c < runs[i]; c++) {
                    out[o + c] = cell(v, width, height, c, r, win, zf, dx, dy, area, le, ln, lu);
                }
                rows.shade(v, width, r, runs[i], runs[i + 1], dx, dy, out, o + runs[i]);
                c = runs[i + 1];
            }
            for (; c < col0 + w; c++) {
                out[o + c] = cell(v, width, height, c, r, win, zf, dx, dy, area, le, ln, lu);
            }
        }
    }

    /**
     * One cell through gdaldem's window ({@link GdalWindow}): the cells {@link HornRows} does not take (grid edge,
     * no-data or infinity in the window, a row of zero area), and the reference it must equal.
     */
    static float cell(float[] v, int width, int height, int c, int r, double[] win, double zf, double dx, double dy,
                      double area, double le, double ln, double lu) {
        if (!GdalWindow.fill(v, width, height, c, r, win)) {
            return Float.NaN;
        }
        return shade((win[2] + 2 * win[5] + win[8]) - (win[0] + 2 * win[3] + win[6]),
                (win[0] + 2 * win[1] + win[2]) - (win[6] + 2 * win[7] + win[8]), zf, dx, dy, area, le, ln, lu);
    }

    /** The clamped cosine of incidence from Horn's sums gx (east) and gy (north). */
    private static float shade(double gx, double gy, double zf, double dx, double dy, double area, double le,
                               double ln, double lu) {
        // The normal (−∂z/∂east, −∂z/∂north, 1) multiplied by Δx·Δy.
        final double nx = -zf * gx * dy;
        final double ny = -zf * gy * dx;
        final double len = Math.sqrt(nx * nx + ny * ny + area * area);
        final double cos = len > 0 ? (nx * le + ny * ln + area * lu) / len : lu;
        return (float) Clamp.between(cos, -1.0, 1.0);
    }
}
