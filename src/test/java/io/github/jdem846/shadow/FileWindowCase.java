package io.github.jdem846.shadow;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import java.util.Random;
import java.util.concurrent.ForkJoinPool;

/**
 * A DEM, a sun and a window read from it as a file window is read: the window plus the halo of {@link
 * ShadowHalo#window} for the file's range, cut out as a grid of its own that remembers its place in the file
 * ({@link Dem#crop}). The generator makes what provokes a sweep whose floor depends on the loaded grid: rough low
 * terrain with no-data blobs across the rays, spikes, and a deep pit and a peak that give the file a relief the
 * window's surroundings do not have.
 *
 * @param dem    the whole file
 * @param light  the sun
 * @param window the window's cells in the file
 * @param loaded the cells read: window and halo
 */
public record FileWindowCase(Dem dem, LightDirection light, CellWindow window, CellWindow loaded) {

    /**
     * {@code windows} random windows of one random DEM and sun (metric 30 m grid, 30–110 cells a side, sun
     * 0.5–30.5° at any azimuth).
     */
    public static java.util.List<FileWindowCase> random(Random rnd, int windows) {
        int w = 30 + rnd.nextInt(80);
        int h = 30 + rnd.nextInt(80);
        float[] v = new float[w * h];
        double amp = rnd.nextDouble() * 50;
        for (int i = 0; i < v.length; i++) {
            v[i] = (float) (amp * rnd.nextDouble());
        }
        for (int b = rnd.nextInt(6); b > 0; b--) {
            int bx = rnd.nextInt(w);
            int by = rnd.nextInt(h);
            int bw = 1 + rnd.nextInt(6);
            int bh = 1 + rnd.nextInt(6);
            for (int y = by; y < Math.min(h, by + bh); y++) {
                for (int x = bx; x < Math.min(w, bx + bw); x++) {
                    v[y * w + x] = Float.NaN;
                }
            }
        }
        for (int s = rnd.nextInt(5); s > 0; s--) {
            v[rnd.nextInt(v.length)] = (float) (amp + rnd.nextDouble() * 40);
        }
        v[rnd.nextInt(v.length)] = (float) (-rnd.nextDouble() * 2000);
        v[rnd.nextInt(v.length)] = (float) (rnd.nextDouble() * 500);
        Dem dem = new Dem(v, GridGeometry.metric(w, h, 30));
        LightDirection light = new LightDirection(rnd.nextDouble() * 360, 0.5 + rnd.nextDouble() * 30);
        java.util.List<FileWindowCase> cases = new java.util.ArrayList<>();
        for (int q = 0; q < windows; q++) {
            int ww = 1 + rnd.nextInt(w / 2);
            int wh = 1 + rnd.nextInt(h / 2);
            CellWindow window = new CellWindow(rnd.nextInt(w - ww + 1), rnd.nextInt(h - wh + 1), ww, wh);
            CellWindow loaded = ShadowHalo.window(dem.geometry(), dem.statistics().max(), dem.statistics().min(),
                    light, ShadowOptions.DEFAULTS, window);
            cases.add(new FileWindowCase(dem, light, window, loaded));
        }
        return cases;
    }

    /** The grid a windowed read loads. */
    public Dem loadedGrid() {
        return dem.crop(loaded.col(), loaded.row(), loaded.width(), loaded.height());
    }

    /** The window's cells within {@link #loadedGrid()}. */
    public CellWindow windowInLoaded() {
        return new CellWindow(window.col() - loaded.col(), window.row() - loaded.row(), window.width(),
                window.height());
    }

    /**
     * Cells of the window where the sweep of the loaded grid with {@code options} differs from the whole file's
     * (with the same options, less the terrain minimum: the whole file has its own).
     */
    public int differences(ShadowOptions options, ForkJoinPool pool) {
        ShadowMask whole = ShadowAlgorithm.SWEEP.compute(dem, light, options.withTerrainMinimum(Double.NaN), pool);
        ShadowMask part = ShadowAlgorithm.SWEEP.computeWindow(loadedGrid(), light, options, pool, windowInLoaded());
        int differ = 0;
        for (int r = 0; r < window.height(); r++) {
            for (int c = 0; c < window.width(); c++) {
                differ += Float.compare(part.get(c, r), whole.get(window.col() + c, window.row() + r)) != 0 ? 1 : 0;
            }
        }
        return differ;
    }

    /** The first of {@code trials} seeded DEMs (8 windows each) with a window that differs when the sweep is not told the file's minimum. */
    public static FileWindowCase sensitive(long seed, int trials, ForkJoinPool pool) {
        Random rnd = new Random(seed);
        for (int t = 0; t < trials; t++) {
            for (FileWindowCase c : random(rnd, 8)) {
                if (c.differences(ShadowOptions.DEFAULTS, pool) > 0) {
                    return c;
                }
            }
        }
        throw new AssertionError("no case in " + trials + " trials needs the file's minimum");
    }
}
