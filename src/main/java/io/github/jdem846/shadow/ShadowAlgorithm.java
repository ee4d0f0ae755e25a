package io.github.jdem846.shadow;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.parallel.Cancellation;
import io.github.jdem846.raster.Dem;
import java.util.Objects;
import java.util.concurrent.ForkJoinPool;

/**
 * The cast-shadow methods ({@code --algorithm}). All give the same kind of {@link ShadowMask}; the scene decides
 * what is computed at all: a sun at or below the horizon shades every valid cell without tracing, a sun at the
 * zenith casts no shadow, an all-no-data DEM gives an empty mask.
 *
 * <p>Cancelling: interrupt the thread that called {@code compute}, {@code computeWindow} or {@code computeCells}.
 * The work stops within one block of 48 sweep lines or one 64-ray run of a march, and the call throws {@link
 * java.util.concurrent.CancellationException} with the thread's interrupt status still set; when it returns or throws,
 * none of its work is left running on the pool ({@link io.github.jdem846.parallel.Cancellation}).
 */
public enum ShadowAlgorithm {

    /**
     * The article's ray march (section 4.2, eq. 9–11, tests 1–4): one ray per cell, by default with the article's
     * step (eq. 9) and nearest-cell sampling; {@link ShadowOptions#step()} and {@link ShadowOptions#sampling()}
     * change both. Cost grows with the ray length, i.e. as the sun gets lower.
     */
    MARCH,
    /** The same shadow test in O(cells) by sun-parallel lines (see docs/shadows.md); bilinear by default. */
    SWEEP,
    /** The reference: a march with eighth-cell steps on the bilinear surface. Slow by design. */
    EXACT,
    /** No cast shadows: every cell lit. */
    NONE;

    /**
     * Shadows of the whole DEM on the common ForkJoinPool.
     *
     * @param dem the elevations
     * @param light where the light comes from, in the grid's frame
     * @param options step, sampling, soft shadows and curvature
     * @return the shadowed fraction of every cell, in [0, 1]
     */
    public ShadowMask compute(Dem dem, LightDirection light, ShadowOptions options) {
        return compute(dem, light, options, ForkJoinPool.commonPool());
    }

    /**
     * Shadows of the whole DEM, the work split across {@code pool}.
     *
     * @param dem the elevations
     * @param light where the light comes from, in the grid's frame
     * @param options step, sampling, soft shadows and curvature
     * @param pool the pool the rows or lines are computed on
     * @return the shadowed fraction of every cell, in [0, 1]
     */
    public ShadowMask compute(Dem dem, LightDirection light, ShadowOptions options, ForkJoinPool pool) {
        return computeWindow(dem, light, options, pool, CellWindow.whole(dem.width(), dem.height()));
    }

    /**
     * Shadows of the cells of {@code window} only (a mask of the window's size). {@code march} and {@code exact} read
     * the DEM only inside {@link ShadowHalo#window(Dem, LightDirection, ShadowOptions, CellWindow)}; {@code sweep}
     * reads a halo longer by (zMax − zMin)/tan(elevation) toward the sun. Hard-shadow results are identical to the
     * same cells of a whole-DEM computation, for any window and any pool.
     *
     * @param dem the elevations
     * @param light where the light comes from, in the grid's frame
     * @param options step, sampling, soft shadows and curvature
     * @param pool the pool the rows or lines are computed on
     * @param window the cells to compute, inside the DEM
     * @return the shadowed fractions of the window's cells, in [0, 1]
     */
    public ShadowMask computeWindow(Dem dem, LightDirection light, ShadowOptions options, ForkJoinPool pool,
                                    CellWindow window) {
        return computeWindow(dem, light, options, pool, window, ShadowProgress.NONE);
    }

    /**
     * {@link #computeWindow(Dem, LightDirection, ShadowOptions, ForkJoinPool, CellWindow)}, telling {@code progress}
     * how far it has come after each block of sweep lines or rows of rays (see {@link ShadowProgress}); a mask
     * computed without tracing (no shadows, a sun at the zenith or below the horizon) reports 1 of 1.
     *
     * @param dem      the grid, the window and its halo
     * @param light    the sun
     * @param options  the shadow options
     * @param pool     the pool the work is split across
     * @param window   the cells whose shadow is computed
     * @param progress told of the blocks done
     * @return the mask of the window
     */
    public ShadowMask computeWindow(Dem dem, LightDirection light, ShadowOptions options, ForkJoinPool pool,
                                    CellWindow window, ShadowProgress progress) {
        Objects.requireNonNull(progress, "progress");
        Finishing tracked = new Finishing(progress);
        ShadowMask mask = computeTracked(dem, light, options, pool, window, tracked);
        tracked.finish();
        return mask;
    }

    /** Passes progress on and remembers its total, so that the computation can end at {@code done == total}. */
    private static final class Finishing implements ShadowProgress {
        private final ShadowProgress to;
        private long total = 1;

        Finishing(ShadowProgress to) {
            this.to = to;
        }

        @Override
        public synchronized void update(long done, long t) {
            total = t;
            to.update(done, t);
        }

        synchronized void finish() {
            to.update(total, total);
        }
    }

    private ShadowMask computeTracked(Dem dem, LightDirection light, ShadowOptions options, ForkJoinPool pool,
                                      CellWindow window, ShadowProgress progress) {
        Objects.requireNonNull(dem, "dem");
        Objects.requireNonNull(light, "light");
        Objects.requireNonNull(options, "options");
        Objects.requireNonNull(pool, "pool");
        Objects.requireNonNull(window, "window");
        if (!window.isInside(dem.width(), dem.height())) {
            throw new IllegalArgumentException("window " + window + " is not inside the " + dem.width() + "×"
                    + dem.height() + " DEM");
        }
        int ww = window.width();
        int wh = window.height();
        if (this == NONE || dem.statistics().isEmpty() || light.isAtZenith()) {
            return ShadowMask.filled(ww, wh, 0f);
        }
        float[] out = new float[ww * wh];
        if (light.isBelowHorizon()) {
            float[] v = dem.backingArray();
            for (int r = 0; r < wh; r++) {
                for (int c = 0; c < ww; c++) {
                    float z = v[(window.row() + r) * dem.width() + window.col() + c];
                    out[r * ww + c] = z == z ? 1f : 0f;
                }
            }
            return new ShadowMask(ww, wh, out);
        }
        switch (this) {
            case SWEEP -> {
                if (options.softShadows()) {
                    softSweep(dem, light, options, pool, window, out, progress);
                } else {
                    hardSweep(dem, light, options, pool, window, out, progress);
                }
            }
            case MARCH, EXACT -> march(marcher(dem, new RayFrame(dem, light, options), options), window, out, pool,
                    progress);
            default -> throw new AssertionError(this);
        }
        Cancellation.checkInterrupted();                 // also during the soft sweep's work on this thread
        return new ShadowMask(ww, wh, out);
    }

    /** Cells of the soft sweep's loops on the calling thread between two tests of its interrupt status. */
    private static final int CELLS_PER_CALLER_CHECK = 1 << 16;

    /** Brackets across the sun's disk of the soft sweep: the horizon is placed within 1/16 of the disk's diameter. */
    static final int SOFT_SWEEP_LEVELS = 16;

    private static void hardSweep(Dem dem, LightDirection light, ShadowOptions options, ForkJoinPool pool,
                                  CellWindow window, float[] out, ShadowProgress progress) {
        RayFrame frame = new RayFrame(dem, light, options);
        boolean bilinear = options.sampling() != Sampling.NEAREST;
        SunSweep sweep = new SunSweep(dem, frame, bilinear, bilinear && options.firstCellTest(), true,
                options.terrainMinimum(), options.thinFeatures());
        int halo = window.width() == dem.width() && window.height() == dem.height() ? Integer.MAX_VALUE
                : ShadowHalo.sweepSteps(frame, sweep.lowestFloor(), light, options);
        sweep.run(window, halo, out, pool, progress);
    }

    /**
     * Soft shadows by hard sweeps: a hard sweep with the sun at elevation a answers, for every cell, whether the
     * horizon toward the sun is above a. Sweeps at {@link #SOFT_SWEEP_LEVELS} + 1 angles from the lower to the upper
     * limb (and at 0° when the disk straddles the horizon) bracket each cell's horizon; the hidden fraction is the
     * disk's segment below the bracket's middle (1 above the upper limb, 0 below the lower). A level at or below 0°
     * counts as blocked, as a sun at or below the horizon does everywhere, so a cell whose horizon lies between 0°
     * and the next level takes 0°, the horizon of flat ground. Every level is the hard sweep itself, so the soft
     * mask is consistent with the hard one (hidden fraction above ½ exactly where the hard sweep shades), and no
     * horizon angle is read off the sweep's running maxima, which come from the occluder highest above the sun's
     * slope rather than from the steepest one. Error: at most about 2/(π·levels) ≈ 0.04 of the disk.
     */
    private static void softSweep(Dem dem, LightDirection light, ShadowOptions options, ForkJoinPool pool,
                                  CellWindow window, float[] out, ShadowProgress progress) {
        ShadowOptions hard = options.withSoftShadows(false);
        double e = light.elevationDegrees();
        double r = options.sunDiameterDegrees() / 2;
        double[] levels = softLevels(e, r);
        int n = out.length;
        int[] highestBlocked = highestBlockedInOneWalk(dem, light, hard, pool, window, levels, progress);
        if (highestBlocked == null) {
            highestBlocked = highestBlockedLevelByLevel(dem, light, hard, pool, window, levels, progress);
        }
        for (int i = 0; i < n; i++) {
            if ((i & CELLS_PER_CALLER_CHECK - 1) == 0) {
                Cancellation.checkInterrupted();
            }
            int k = highestBlocked[i];
            if (k < 0) {
                out[i] = 0f;
            } else if (k == levels.length - 1) {
                out[i] = 1f;
            } else {
                double horizon = levels[k] == 0 ? 0 : 0.5 * (levels[k] + levels[k + 1]);
                out[i] = (float) SunDisk.hiddenFraction(e, horizon, r);
            }
        }
    }

    /**
     * The ascending sun elevations of the soft sweep's hard sweeps: {@link #SOFT_SWEEP_LEVELS} + 1 across the disk
     * of radius {@code r} around {@code e}, and the horizon when the disk straddles it.
     */
    static double[] softLevels(double e, double r) {
        java.util.TreeSet<Double> angles = new java.util.TreeSet<>();
        for (int k = 0; k <= SOFT_SWEEP_LEVELS; k++) {
            angles.add(e - r + 2 * r * k / SOFT_SWEEP_LEVELS);
        }
        if (e - r < 0 && e + r > 0) {
            angles.add(0.0);
        }
        return angles.stream().mapToDouble(Double::doubleValue).toArray();
    }

    /**
     * Per cell of {@code window}, the highest of the ascending sun elevations {@code levels} at which it is in hard
     * shadow (−1 = none), from hard sweeps one elevation after another, the lowest first; a level at or below the
     * horizon shades every valid cell, none at or above the zenith does, and once a level shades no cell the higher
     * ones are not swept.
     */
    static int[] highestBlockedLevelByLevel(Dem dem, LightDirection light, ShadowOptions hard, ForkJoinPool pool,
                                            CellWindow window, double[] levels) {
        return highestBlockedLevelByLevel(dem, light, hard, pool, window, levels, ShadowProgress.NONE);
    }

    /** Progress units of one level of the level-by-level soft sweep (its blocks done, scaled). */
    private static final long PER_LEVEL = 1000;

    private static int[] highestBlockedLevelByLevel(Dem dem, LightDirection light, ShadowOptions hard,
                                                    ForkJoinPool pool, CellWindow window, double[] levels,
                                                    ShadowProgress progress) {
        long total = PER_LEVEL * levels.length;
        int n = window.width() * window.height();
        int[] highestBlocked = new int[n];
        java.util.Arrays.fill(highestBlocked, -1);
        float[] level = new float[n];
        float[] v = dem.backingArray();
        for (int k = 0; k < levels.length; k++) {
            double a = levels[k];
            if (a >= 90) {
                break;                                   // nothing rises above a sun at the zenith
            }
            if (a <= 0) {
                for (int i = 0; i < n; i++) {            // at or below the horizon: every valid cell
                    float z = v[(window.row() + i / window.width()) * dem.width() + window.col()
                            + i % window.width()];
                    level[i] = z == z ? 1f : 0f;
                }
            } else {
                long before = PER_LEVEL * k;
                hardSweep(dem, new LightDirection(light.azimuthDegrees(), a), hard, pool, window, level,
                        (d, t) -> progress.update(before + PER_LEVEL * d / Math.max(1, t), total));
            }
            progress.update(PER_LEVEL * (k + 1), total);
            boolean any = false;
            for (int i = 0; i < n; i++) {
                if (level[i] > 0.5f) {
                    highestBlocked[i] = k;
                    any = true;
                }
            }
            if (!any) {
                break;                                   // a higher sun is blocked nowhere either
            }
        }
        return highestBlocked;
    }

    /**
     * {@link #highestBlockedLevelByLevel}, the same numbers from one sweep that walks all elevations above the
     * horizon at once ({@code SunSweep.runLevels}), or null when this grid and these options need the sweep's
     * general path.
     */
    static int[] highestBlockedInOneWalk(Dem dem, LightDirection light, ShadowOptions hard, ForkJoinPool pool,
                                         CellWindow window, double[] levels) {
        return highestBlockedInOneWalk(dem, light, hard, pool, window, levels, ShadowProgress.NONE);
    }

    private static int[] highestBlockedInOneWalk(Dem dem, LightDirection light, ShadowOptions hard,
                                                 ForkJoinPool pool, CellWindow window, double[] levels,
                                                 ShadowProgress progress) {
        int first = 0;                                   // the first level above the horizon
        while (first < levels.length && levels[first] <= 0) {
            first++;
        }
        int end = first;                                 // levels first … end − 1 are swept
        while (end < levels.length && levels[end] < 90) {
            end++;
        }
        if (end == first || end - first > 31) {
            return null;
        }
        double azimuth = light.azimuthDegrees();
        LightDirection lowest = new LightDirection(azimuth, levels[first]);
        RayFrame frame = new RayFrame(dem, lowest, hard);
        boolean bilinear = hard.sampling() != Sampling.NEAREST;
        SunSweep sweep = new SunSweep(dem, frame, bilinear, bilinear && hard.firstCellTest(), true,
                hard.terrainMinimum(), hard.thinFeatures());
        if (!sweep.canRunLevels()) {
            return null;
        }
        double[] tans = new double[end - first];
        for (int k = first; k < end; k++) {
            tans[k - first] = new RayFrame(dem, new LightDirection(azimuth, levels[k]), hard).tanElevation;
        }
        int halo = window.width() == dem.width() && window.height() == dem.height() ? Integer.MAX_VALUE
                : ShadowHalo.sweepSteps(frame, sweep.lowestFloor(), lowest, hard);
        int n = window.width() * window.height();
        int[] bits = new int[n];
        sweep.runLevels(window, halo, tans, bits, pool, progress);
        // the level-by-level rule: stop at the first level that shades no cell (levels below the horizon shade
        // every valid cell; with none, every cell is −1 anyway) or at the zenith
        int union = 0;
        for (int b : bits) {
            union |= b;
        }
        int swept = 0;
        while (swept < end - first && (union >>> swept & 1) != 0) {
            swept++;
        }
        int kept = (int) ((1L << swept) - 1);
        float[] v = dem.backingArray();
        int[] highest = new int[n];
        int w = window.width();
        for (int i = 0; i < n; i++) {
            if ((i & CELLS_PER_CALLER_CHECK - 1) == 0) {
                Cancellation.checkInterrupted();
            }
            int b = bits[i] & kept;
            if (b != 0) {
                highest[i] = first + 31 - Integer.numberOfLeadingZeros(b);
            } else {
                float z = v[(window.row() + i / w) * dem.width() + window.col() + i % w];
                highest[i] = z == z ? first - 1 : -1;
            }
        }
        return highest;
    }

    /**
     * Shadowed fractions of the listed cells only, in the order given: the same values as the same cells of
     * {@link #compute(Dem, LightDirection, ShadowOptions, ForkJoinPool)}. {@code MARCH} and {@code EXACT} trace
     * just these cells, so the cost grows with {@code cells.length} (the accuracy study measures them on a random
     * sample of a large grid this way); {@code SWEEP} has no per-cell form and computes the whole grid first.
     *
     * @param dem the elevations
     * @param light where the light comes from, in the grid's frame
     * @param options step, sampling, soft shadows and curvature
     * @param pool the pool the work is split across
     * @param cells flat cell indices, {@code row · width + col}, each in [0, width · height)
     * @return the shadowed fraction of each listed cell, in [0, 1], in the order of {@code cells}
     */
    public float[] computeCells(Dem dem, LightDirection light, ShadowOptions options, ForkJoinPool pool,
                                int[] cells) {
        Objects.requireNonNull(dem, "dem");
        Objects.requireNonNull(light, "light");
        Objects.requireNonNull(options, "options");
        Objects.requireNonNull(pool, "pool");
        long n = (long) dem.width() * dem.height();
        for (int cell : cells) {
            if (cell < 0 || cell >= n) {
                throw new IllegalArgumentException("cell index " + cell + " is outside the " + dem.width() + "×"
                        + dem.height() + " DEM (expected 0 to " + (n - 1) + ")");
            }
        }
        float[] out = new float[cells.length];
        if (this == SWEEP || this == NONE || dem.statistics().isEmpty() || light.isAtZenith()
                || light.isBelowHorizon()) {
            float[] all = compute(dem, light, options, pool).backingArray();
            for (int q = 0; q < cells.length; q++) {
                out[q] = all[cells[q]];
            }
            return out;
        }
        RayMarcher marcher = marcher(dem, new RayFrame(dem, light, options), options);
        int w = dem.width();
        int perTask = 256;
        Cancellation.invokeAll(pool, (cells.length + perTask - 1) / perTask, (t, cancel) -> {
            for (int q = t * perTask; q < Math.min(cells.length, (t + 1) * perTask); q++) {
                if ((q & CELLS_PER_CHECK - 1) == 0 && cancel.isCancelled()) {
                    return;
                }
                out[q] = marcher.shade(cells[q] % w, cells[q] / w);
            }
        });
        return out;
    }

    /** The ray marcher of {@code MARCH} (the options' step and sampling) or of {@code EXACT}. */
    private RayMarcher marcher(Dem dem, RayFrame frame, ShadowOptions options) {
        return this == EXACT ? new RayMarcher(dem, frame, StepSize.EIGHTH_CELL, true)
                : new RayMarcher(dem, frame, options.step(), options.sampling() == Sampling.BILINEAR);
    }

    /** Rays traced between two tests of {@link Cancellation#isCancelled()}: one ray is already many samples. */
    private static final int CELLS_PER_CHECK = 64;

    private static void march(RayMarcher marcher, CellWindow win, float[] out, ForkJoinPool pool,
                              ShadowProgress progress) {
        int rowsPerTask = Math.max(1, Math.min(16, win.height() / 64));
        int ww = win.width();
        int tasks = (win.height() + rowsPerTask - 1) / rowsPerTask;
        Cancellation.invokeAll(pool, tasks, (t, cancel) -> {
            for (int rr = t * rowsPerTask; rr < Math.min(win.height(), (t + 1) * rowsPerTask); rr++) {
                for (int c = 0; c < ww; c++) {
                    if ((c & CELLS_PER_CHECK - 1) == 0 && cancel.isCancelled()) {
                        return;
                    }
                    out[rr * ww + c] = marcher.shade(win.col() + c, win.row() + rr);
                }
            }
        }, done -> progress.update(Math.min(win.height(), (long) done * rowsPerTask), win.height()));
    }
}
