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
 */
final class HornIllumination implements IlluminationStage {

    private final HillshadeOptions options;

    public HornIllumination(HillshadeOptions options) {
        this.options = Objects.requireNonNull(options, "options");
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
        for (int r = row0; r < row0 + h; r++) {
            final double dx = spacing.eastWest(r);
            final double dy = spacing.northSouth(r);
            final double area = dx * dy;
            final boolean innerRow = r >= 1 && r <= height - 2;
            int o = (r - row0) * w;
            for (int c = col0; c < col0 + w; c++, o++) {
                if (innerRow && c >= 1 && c <= width - 2) {
                    // inside the grid with no no-data around: the nine cells straight from the array (the same
                    // numbers GdalWindow gives, without its window array). The same block is in
                    // MultidirectionalIllumination: one loop for both with the formula as a per-cell callback was
                    // ~30 % slower (JMH HillshadeBenchmark, 4 forks: Horn 34.6 against 51.0 Mcells/s)
                    final int i = (r - 1) * width + c - 1;
                    final int j = i + width;
                    final int k = j + width;
                    final double w0 = v[i];
                    final double w1 = v[i + 1];
                    final double w2 = v[i + 2];
                    final double w3 = v[j];
                    final double w4 = v[j + 1];
                    final double w5 = v[j + 2];
                    final double w6 = v[k];
                    final double w7 = v[k + 1];
                    final double w8 = v[k + 2];
                    final double sum = w0 + w1 + w2 + w3 + w4 + w5 + w6 + w7 + w8;
                    if (sum == sum) {
                        out[o] = shade((w2 + 2 * w5 + w8) - (w0 + 2 * w3 + w6),
                                (w0 + 2 * w1 + w2) - (w6 + 2 * w7 + w8), zf, dx, dy, area, le, ln, lu);
                        continue;
                    }
                }
                if (!GdalWindow.fill(v, width, height, c, r, win)) {
                    out[o] = Float.NaN;
                    continue;
                }
                out[o] = shade((win[2] + 2 * win[5] + win[8]) - (win[0] + 2 * win[3] + win[6]),
                        (win[0] + 2 * win[1] + win[2]) - (win[6] + 2 * win[7] + win[8]), zf, dx, dy, area, le, ln, lu);
            }
        }
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
