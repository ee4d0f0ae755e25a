package io.github.jdem846.shade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.testing.TestDems;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The row kernels ({@link HornRows}, {@link JDem846Rows}), in both loop shapes ({@link KernelShape}), must give the
 * per-cell paths' floats bit for bit: every cell of a stage's output is compared with {@link HornIllumination#cell}
 * (gdaldem's window, {@link GdalWindow}) and with {@link JDem846Illumination#general}, on the real DEMs of
 * testdata/dem with no-data and infinities inserted, crops of odd sizes and 1–3 cells wide or high, tiles anywhere
 * (at the grid's edges too), and on grids of extreme values and cell sizes.
 */
class RowKernelEquivalenceTest {

    private static final String[] DEMS = {TestDems.BIG_TUJUNGA, TestDems.JACKSBORO, TestDems.LUXEMBOURG,
        TestDems.VANCOUVER, TestDems.VOLCANO};

    @Test
    void realDemsWithHolesGiveThePerCellValues() {
        Random rnd = new Random(846);
        for (String name : DEMS) {
            Dem full = TestDems.load(name);
            for (int t = 0; t < 12; t++) {
                int w = t < 3 ? 1 + t : t < 6 ? full.width() : 1 + rnd.nextInt(Math.min(full.width(), 97));
                int h = t >= 3 && t < 6 ? t - 2 : t < 3 ? full.height() : 1 + rnd.nextInt(Math.min(full.height(), 89));
                int col = rnd.nextInt(full.width() - w + 1);
                int row = rnd.nextInt(full.height() - h + 1);
                Dem crop = full.crop(col, row, w, h);
                float[] v = crop.backingArray().clone();
                int holes = t % 3 == 0 ? 0 : 1 + rnd.nextInt(Math.max(1, v.length / 50));
                for (int i = 0; i < holes; i++) {
                    int kind = rnd.nextInt(8);
                    v[rnd.nextInt(v.length)] = kind == 0 ? Float.POSITIVE_INFINITY : kind == 1
                            ? Float.NEGATIVE_INFINITY : Float.NaN;
                }
                Dem dem = new Dem(v, crop.geometry());
                HillshadeOptions options = HillshadeOptions.DEFAULTS.withZFactor(1 + rnd.nextInt(3));
                if (name.equals(TestDems.JACKSBORO) && rnd.nextBoolean()) {
                    options = options.withHorizontalScale(111120);
                }
                LightDirection light = new LightDirection(rnd.nextDouble() * 360, rnd.nextDouble() * 100 - 10);
                checkTiles(name + " trial " + t, dem, options, light, rnd);
            }
        }
    }

    @Test
    void extremeValuesAndCellSizesGiveThePerCellValues() {
        Random rnd = new Random(7);
        double[] cellSizes = {1e9, 1e-3, 0.999e-3, 1e-7, 0.5, 30, 111120};
        for (int t = 0; t < 80; t++) {
            int w = 1 + rnd.nextInt(23);
            int h = 1 + rnd.nextInt(19);
            float[] v = new float[w * h];
            for (int i = 0; i < v.length; i++) {
                v[i] = switch (rnd.nextInt(12)) {
                    case 0 -> Float.MAX_VALUE;
                    case 1 -> -Float.MAX_VALUE;
                    case 2 -> Float.MIN_VALUE;
                    case 3 -> -0.0f;
                    case 4 -> 3e38f * (float) rnd.nextDouble();
                    case 5 -> 1e-30f * (float) rnd.nextGaussian();
                    case 6 -> t % 4 == 0 ? Float.NaN : 0f;
                    default -> (float) (rnd.nextGaussian() * (t % 2 == 0 ? 1e4 : 1e-3));
                };
            }
            Dem dem = new Dem(v, GridGeometry.metric(w, h, cellSizes[t % cellSizes.length]));
            HillshadeOptions options = HillshadeOptions.DEFAULTS
                    .withZFactor(t % 3 == 0 ? HillshadeOptions.MAX_HEIGHT_FACTOR : 1)
                    .withLightMultiple(t % 5 == 0 ? HillshadeOptions.MAX_HEIGHT_FACTOR : t % 5 == 1 ? 0 : 0.75);
            LightDirection light = new LightDirection(rnd.nextDouble() * 360, rnd.nextDouble() * 180 - 90);
            checkTiles("trial " + t, dem, options, light, rnd);
        }
    }

    @Test
    void runsAreExactlyTheInteriorCellsWithFiniteWindows() {
        Random rnd = new Random(3);
        for (int t = 0; t < 200; t++) {
            int width = 1 + rnd.nextInt(12);
            int height = 1 + rnd.nextInt(12);
            float[] v = new float[width * height];
            boolean clean = t % 3 == 0;                  // a grid known to be finite: no row looked at
            for (int i = 0; i < v.length; i++) {
                int kind = clean ? 9 : rnd.nextInt(10);
                v[i] = kind == 0 ? Float.NaN : kind == 1 ? Float.NEGATIVE_INFINITY : i;
            }
            int col0 = rnd.nextInt(width);
            int row0 = rnd.nextInt(height);
            int w = 1 + rnd.nextInt(width - col0);
            int h = 1 + rnd.nextInt(height - row0);
            FiniteWindows windows = new FiniteWindows(v, width, height, col0, row0, w, h, clean);
            int[] runs = new int[FiniteWindows.runsLength(w)];
            for (int r = row0; r < row0 + h; r++) {
                boolean[] inRun = new boolean[width];
                int n = windows.runs(r, runs);
                for (int i = 0; i < n; i += 2) {
                    assertTrue(runs[i] < runs[i + 1] && (i == 0 || runs[i - 1] < runs[i]), "runs ordered, not empty");
                    for (int c = runs[i]; c < runs[i + 1]; c++) {
                        inRun[c] = true;
                    }
                }
                for (int c = col0; c < col0 + w; c++) {
                    assertEquals(finiteWindow(v, width, height, c, r), inRun[c],
                            "trial " + t + " (" + c + ", " + r + ")");
                }
            }
        }
    }

    private static boolean finiteWindow(float[] v, int width, int height, int c, int r) {
        if (c < 1 || r < 1 || c > width - 2 || r > height - 2) {
            return false;
        }
        for (int i = -1; i <= 1; i++) {
            for (int j = -1; j <= 1; j++) {
                if (!Float.isFinite(v[(r + i) * width + c + j])) {
                    return false;
                }
            }
        }
        return true;
    }

    /** The whole grid, and tiles of it (corners, edges, random), against the per-cell paths. */
    private static void checkTiles(String what, Dem dem, HillshadeOptions options, LightDirection light, Random rnd) {
        int width = dem.width();
        int height = dem.height();
        check(what + " whole", dem, options, light, 0, 0, width, height);
        for (int i = 0; i < 6; i++) {
            int tw = 1 + rnd.nextInt(Math.min(width, 40));
            int th = 1 + rnd.nextInt(Math.min(height, 40));
            int c0 = i == 0 ? 0 : i == 1 ? width - tw : rnd.nextInt(width - tw + 1);
            int r0 = i == 0 ? 0 : i == 1 ? height - th : rnd.nextInt(height - th + 1);
            check(what + " tile " + tw + "×" + th + " at (" + c0 + ", " + r0 + ")", dem, options, light, c0, r0, tw,
                    th);
        }
    }

    private static void check(String what, Dem dem, HillshadeOptions options, LightDirection light, int c0, int r0,
                              int tw, int th) {
        for (KernelShape shape : KernelShape.values()) {
            check(what + " " + shape, dem, options, light, c0, r0, tw, th, shape);
        }
    }

    private static void check(String what, Dem dem, HillshadeOptions options, LightDirection light, int c0, int r0,
                              int tw, int th, KernelShape shape) {
        float[] horn = new float[tw * th];
        float[] jdem = new float[tw * th];
        new HornIllumination(options, shape).illuminate(dem, light, c0, r0, tw, th, horn);
        new JDem846Illumination(options, shape).illuminate(dem, light, c0, r0, tw, th, jdem);
        float[] v = dem.backingArray();
        int width = dem.width();
        int height = dem.height();
        CellSpacing spacing = new CellSpacing(dem.geometry(), options);
        double zf = options.zFactor() / 8.0;
        double k = options.zFactor() * options.lightMultiple();
        double[] win = new double[9];
        for (int r = r0; r < r0 + th; r++) {
            double dx = spacing.eastWest(r);
            double dy = spacing.northSouth(r);
            for (int c = c0; c < c0 + tw; c++) {
                int o = (r - r0) * tw + c - c0;
                final int cc = c;
                final int rr = r;
                java.util.function.Supplier<String> at = () -> what + " cell (" + cc + ", " + rr + ")";
                float hornCell = HornIllumination.cell(v, width, height, c, r, win, zf, dx, dy, dx * dy, light.east(),
                        light.north(), light.up());
                assertEquals(Float.floatToRawIntBits(hornCell), Float.floatToRawIntBits(horn[o]),
                        () -> at.get() + " horn");
                float jdemCell = Float.isNaN(v[r * width + c]) ? Float.NaN
                        : JDem846Illumination.general(v, width, height, c, r, dx, dy, k, light.east(), light.north(),
                        light.up(), light.isBelowHorizon());
                assertEquals(Float.floatToRawIntBits(jdemCell), Float.floatToRawIntBits(jdem[o]),
                        () -> at.get() + " jdem846");
            }
        }
    }
}
