package io.github.jdem846.shade;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Horn and jdem846 compute cells with finite windows inside the grid a row at a time ({@link HornRows},
 * {@link JDem846Rows}), the others through {@link GdalWindow} or jdem846's general path (bounds checks, fills);
 * multidirectional reads the nine cells straight from the array where none is missing, and through
 * {@link GdalWindow} elsewhere. Both paths must give the same float, bit for bit: checked against a
 * reference that takes every cell through {@link GdalWindow} with the kernels' documented formulas (jdem846:
 * through {@link JDem846Illumination#general}), on random grids with no-data, infinities and float32 extremes, for
 * whole grids and for tiles.
 */
class WindowKernelEquivalenceTest {

    private static final double COS_225 = Math.cos(Math.toRadians(225));

    @Test
    void theDirectReadGivesTheSameValuesAsTheWindow() {
        Random rnd = new Random(11);
        for (int t = 0; t < 60; t++) {
            int w = 1 + rnd.nextInt(40);
            int h = 1 + rnd.nextInt(40);
            float[] v = new float[w * h];
            double amp = rnd.nextInt(3) == 0 ? 3e38 : 1000;
            for (int i = 0; i < v.length; i++) {
                int kind = rnd.nextInt(40);
                v[i] = kind == 0 ? Float.NaN : kind == 1 ? Float.POSITIVE_INFINITY : kind == 2
                        ? Float.NEGATIVE_INFINITY : (float) ((rnd.nextDouble() - 0.5) * amp);
            }
            Dem dem = new Dem(v, GridGeometry.metric(w, h, 0.5 + rnd.nextDouble() * 100));
            LightDirection light = new LightDirection(rnd.nextDouble() * 360, rnd.nextDouble() * 100 - 10);
            HillshadeOptions options = HillshadeOptions.DEFAULTS.withZFactor(rnd.nextBoolean() ? 1 : 1e3);
            int c0 = rnd.nextInt(w);
            int r0 = rnd.nextInt(h);
            int tw = 1 + rnd.nextInt(w - c0);
            int th = 1 + rnd.nextInt(h - r0);
            float[] horn = new float[tw * th];
            float[] multi = new float[tw * th];
            float[] jdem = new float[tw * th];
            new HornIllumination(options).illuminate(dem, light, c0, r0, tw, th, horn);
            new MultidirectionalIllumination(options).illuminate(dem, light, c0, r0, tw, th, multi);
            new JDem846Illumination(options).illuminate(dem, light, c0, r0, tw, th, jdem);
            double k = options.zFactor() * options.lightMultiple();
            CellSpacing spacing = new CellSpacing(dem.geometry(), options);
            double[] win = new double[9];
            for (int r = r0; r < r0 + th; r++) {
                for (int c = c0; c < c0 + tw; c++) {
                    int o = (r - r0) * tw + c - c0;
                    String at = "trial " + t + " cell (" + c + ", " + r + ")";
                    double dx = spacing.eastWest(r);
                    double dy = spacing.northSouth(r);
                    if (Float.isNaN(v[r * w + c])) {
                        assertEquals(Float.NaN, jdem[o], at);
                    } else {
                        assertEquals(Float.floatToRawIntBits(JDem846Illumination.general(v, w, h, c, r, dx, dy, k,
                                light.east(), light.north(), light.up(), light.isBelowHorizon())),
                                Float.floatToRawIntBits(jdem[o]), at + " jdem846");
                    }
                    if (!GdalWindow.fill(v, w, h, c, r, win)) {
                        assertEquals(Float.NaN, horn[o], at);
                        assertEquals(Float.NaN, multi[o], at);
                        continue;
                    }
                    assertEquals(Float.floatToRawIntBits(horn(win, dx, dy, options.zFactor() / 8.0, light)),
                            Float.floatToRawIntBits(horn[o]), at + " horn");
                    assertEquals(Float.floatToRawIntBits(multidirectional(win, dx, dy, options.zFactor() / 8.0,
                            light)), Float.floatToRawIntBits(multi[o]), at + " multidirectional");
                }
            }
        }
    }

    /** HornIllumination's formula (its class comment), multiplied through by Δx·Δy. */
    private static float horn(double[] win, double dx, double dy, double zf, LightDirection light) {
        double gx = (win[2] + 2 * win[5] + win[8]) - (win[0] + 2 * win[3] + win[6]);
        double gy = (win[0] + 2 * win[1] + win[2]) - (win[6] + 2 * win[7] + win[8]);
        double area = dx * dy;
        double nx = -zf * gx * dy;
        double ny = -zf * gy * dx;
        double len = Math.sqrt(nx * nx + ny * ny + area * area);
        double cos = len > 0 ? (nx * light.east() + ny * light.north() + area * light.up()) / len : light.up();
        return (float) Math.max(-1.0, Math.min(1.0, cos));
    }

    /** MultidirectionalIllumination's formula (gdaldem's, multiplied through by Δx·Δy). */
    private static float multidirectional(double[] win, double dx, double dy, double zf, LightDirection light) {
        double alt = Math.toRadians(light.elevationDegrees());
        double sinAlt = Math.sin(alt);
        double cosAltZ = Math.cos(alt) * zf;
        double area = dx * dy;
        double x = ((win[0] + 2 * win[3] + win[6]) - (win[2] + 2 * win[5] + win[8])) * dy;
        double y = ((win[0] + 2 * win[1] + win[2]) - (win[6] + 2 * win[7] + win[8])) * dx;
        double xx = x * x;
        double yy = y * y;
        double s = xx + yy;
        if (s == 0) {
            return (float) sinAlt;
        }
        double base = area * sinAlt;
        double v225 = Math.max(0.0, base + (x - y) * COS_225 * cosAltZ);
        double v270 = Math.max(0.0, base - x * cosAltZ);
        double v315 = Math.max(0.0, base + (x + y) * COS_225 * cosAltZ);
        double v360 = Math.max(0.0, base - y * cosAltZ);
        double w225 = 0.5 * s - x * y;
        double w315 = s - w225;
        double weighted = (w225 * v225 + xx * v270 + w315 * v315 + yy * v360) / s;
        double result = weighted / Math.sqrt(area * area + zf * zf * s) / 2;
        return (float) Math.max(0.0, Math.min(1.0, result));
    }
}
