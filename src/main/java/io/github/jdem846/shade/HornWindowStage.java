package io.github.jdem846.shade;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import java.util.Objects;

/**
 * An illumination stage computed cell by cell from Horn's (1981) 3×3 sums on gdaldem's window ({@link GdalWindow},
 * the {@code -compute_edges} rules): the subclass turns each cell's sums and the row's cell spacing into a value.
 * One loop with a per-cell callback, simpler and slower than the row loops of {@link HornIllumination}
 * ({@link HornRows}) and the hand-inlined loop of {@link MultidirectionalIllumination}; used by the rarer gdaldem
 * variants.
 */
abstract class HornWindowStage implements IlluminationStage {

    /** One cell's value from Horn's sums, for one light. */
    interface CellShader {
        /**
         * @param eastMinusWest   (w2 + 2w5 + w8) − (w0 + 2w3 + w6), heights only
         * @param northMinusSouth (w0 + 2w1 + w2) − (w6 + 2w7 + w8), heights only
         * @param dx              east–west cell spacing in metres (≥ 0)
         * @param dy              north–south cell spacing in metres (≥ 0)
         * @return the cell's value (never NaN)
         */
        float shade(double eastMinusWest, double northMinusSouth, double dx, double dy);
    }

    private final HillshadeOptions options;

    HornWindowStage(HillshadeOptions options) {
        this.options = Objects.requireNonNull(options, "options");
    }

    /** @return the options this stage was made with */
    public HillshadeOptions options() {
        return options;
    }

    /** The per-cell formula for {@code light}, its constants computed once. */
    abstract CellShader shader(LightDirection light);

    @Override
    public final void illuminate(Dem dem, LightDirection light, int col0, int row0, int w, int h, float[] out) {
        StageArguments.check(dem, light, col0, row0, w, h, out);
        final CellShader shader = shader(light);
        final CellSpacing spacing = new CellSpacing(dem.geometry(), options);
        final float[] v = dem.backingArray();
        final double[] win = new double[9];
        for (int r = row0; r < row0 + h; r++) {
            final double dx = spacing.eastWest(r);
            final double dy = spacing.northSouth(r);
            int o = (r - row0) * w;
            for (int c = col0; c < col0 + w; c++, o++) {
                if (!GdalWindow.fill(v, dem.width(), dem.height(), c, r, win)) {
                    out[o] = Float.NaN;
                    continue;
                }
                out[o] = shader.shade((win[2] + 2 * win[5] + win[8]) - (win[0] + 2 * win[3] + win[6]),
                        (win[0] + 2 * win[1] + win[2]) - (win[6] + 2 * win[7] + win[8]), dx, dy);
            }
        }
    }

    /**
     * The slope angle in radians, [0, π/2], of Horn's gradient with the z-factor {@code zf / 8} = {@code zOver8}:
     * atan(zOver8 · √((Σe/dx)² + (Σn/dy)²)), computed multiplied through by dx·dy so that a cell of zero width (a
     * pole) gives a vertical face with relief and a flat one without.
     */
    static double slope(double eastMinusWest, double northMinusSouth, double dx, double dy, double zOver8) {
        final double e = eastMinusWest * dy;
        final double n = northMinusSouth * dx;
        return Math.atan2(zOver8 * Math.sqrt(e * e + n * n), dx * dy);
    }
}
