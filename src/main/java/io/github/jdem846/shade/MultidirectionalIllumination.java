package io.github.jdem846.shade;

import io.github.jdem846.internal.Clamp;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import java.util.Objects;

/**
 * gdaldem's multidirectional hillshade ({@code gdaldem hillshade -multidirectional -compute_edges}, GDAL 3.6
 * {@code GDALHillshadeMultiDirectionalAlg}, after USGS Open-File Report 92-422): Horn's gradient lit from the
 * azimuths 225°, 270°, 315° and 360° at the given altitude (the light's azimuth is ignored), each cosine clamped at 0
 * and weighted by cos²(A − azimuth), A the compass direction the slope faces (gdaldem's comment writes it as
 * sin²(aspect − azimuth) with its own aspect angle); a slope is lit mostly by the light it faces:
 * <pre>
 *   x = ((w0 + 2w3 + w6) − (w2 + 2w5 + w8)) / Δx,   y = ((w0 + 2w1 + w2) − (w6 + 2w7 + w8)) / Δy,   s = x² + y²
 *   W225 = s/2 − xy,  W270 = x²,  W315 = s/2 + xy,  W360 = y²          (they sum to 2s)
 *   result = Σ W·max(0, cos i_az) / (2s)        (s = 0: sin alt)
 * </pre>
 * a weighted mean of clamped cosines, in [0, 1] (below the horizon a flat cell gives sin alt &lt; 0). gdaldem's
 * byte is 1 + 254·result ({@link HillshadeMethod#gray}). Computed multiplied through by Δx·Δy like
 * {@link HornIllumination}; same window and edge rules ({@link GdalWindow}).
 */
final class MultidirectionalIllumination implements IlluminationStage {

    private static final double COS_225 = Math.cos(Math.toRadians(225));

    private final HillshadeOptions options;

    public MultidirectionalIllumination(HillshadeOptions options) {
        this.options = Objects.requireNonNull(options, "options");
    }

    public HillshadeOptions options() {
        return options;
    }

    @Override
    public void illuminate(Dem dem, LightDirection light, int col0, int row0, int w, int h, float[] out) {
        StageArguments.check(dem, light, col0, row0, w, h, out);
        final double alt = Math.toRadians(light.elevationDegrees());
        final double sinAlt = Math.sin(alt);
        final double zf = options.zFactor() / 8.0;
        final double cosAltZ = Math.cos(alt) * zf;
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
                    // numbers GdalWindow gives, without its window array). The same block is in HornIllumination:
                    // one loop for both with the formula as a per-cell callback was ~30 % slower (JMH
                    // HillshadeBenchmark, 4 forks: multidirectional 28.4 against 39.6 Mcells/s)
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
                        out[o] = shade((w0 + 2 * w3 + w6) - (w2 + 2 * w5 + w8),
                                (w0 + 2 * w1 + w2) - (w6 + 2 * w7 + w8), dx, dy, area, sinAlt, cosAltZ, zf);
                        continue;
                    }
                }
                if (!GdalWindow.fill(v, width, height, c, r, win)) {
                    out[o] = Float.NaN;
                    continue;
                }
                out[o] = shade((win[0] + 2 * win[3] + win[6]) - (win[2] + 2 * win[5] + win[8]),
                        (win[0] + 2 * win[1] + win[2]) - (win[6] + 2 * win[7] + win[8]), dx, dy, area, sinAlt,
                        cosAltZ, zf);
            }
        }
    }

    /** gdaldem's multidirectional value from the window's west-minus-east sum and north-minus-south sum. */
    private static float shade(double westMinusEast, double northMinusSouth, double dx, double dy, double area,
                               double sinAlt, double cosAltZ, double zf) {
        // gdaldem's x and y, multiplied by Δx·Δy.
        final double x = westMinusEast * dy;
        final double y = northMinusSouth * dx;
        final double xx = x * x;
        final double yy = y * y;
        final double s = xx + yy;
        if (s == 0) {
            return (float) sinAlt;
        }
        final double base = area * sinAlt;
        final double v225 = Clamp.atLeastZero(base + (x - y) * COS_225 * cosAltZ);
        final double v270 = Clamp.atLeastZero(base - x * cosAltZ);
        final double v315 = Clamp.atLeastZero(base + (x + y) * COS_225 * cosAltZ);
        final double v360 = Clamp.atLeastZero(base - y * cosAltZ);
        final double w225 = 0.5 * s - x * y;
        final double w315 = s - w225;
        final double weighted = (w225 * v225 + xx * v270 + w315 * v315 + yy * v360) / s;
        final double denominator = Math.sqrt(area * area + zf * zf * s);
        final double result = weighted / denominator / 2;
        return (float) Clamp.between(result, 0.0, 1.0);
    }
}
