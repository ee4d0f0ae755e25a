package io.github.jdem846.render;

import io.github.jdem846.internal.Clamp;
import io.github.jdem846.internal.Rounding;
import io.github.jdem846.internal.SpareArrays;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.shade.IlluminationStage;
import io.github.jdem846.shadow.CellWindow;
import io.github.jdem846.shadow.ShadowMask;
import io.github.jdem846.shadow.ShadowProgress;
import io.github.jdem846.shadow.SkyView;
import io.github.jdem846.tint.TintFunction;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinWorkerThread;
import java.util.concurrent.TimeUnit;

/**
 * Renders a {@link Scene} of a {@link Dem} (or of a rectangle of it, the rest serving as halo) into ARGB pixels, one
 * pixel per DEM cell: cast shadows first (parallel inside the shadow algorithm), then the sky-view factor when the
 * scene has sky light ({@link Scene#hasAmbient()}, {@link SkyView}), then tint, illumination and composition tile by
 * tile on a {@link ForkJoinPool}. The result is identical for any thread count and tile size.
 *
 * <p>To render at another size, resample the DEM first ({@link io.github.jdem846.raster.DemResampler}, or a
 * decimated read): stages then run at the output resolution. An enlarged DEM's coverage ({@link Dem#coverage})
 * scales the alpha of its pixels, so that the edges of no-data are anti-aliased.
 *
 * <p>Threads: each call runs on a pool of its own ({@link RenderSettings#parallelism()} daemon threads named
 * {@code jdem846-render-…}, shut down when the call returns), or on the caller's pool given by
 * {@link RenderSettings#withPool}, which it never shuts down. A renderer is immutable and thread-safe: one renderer,
 * or several, may render at once from several threads, with or without a shared pool; the DEM, scene and settings
 * are only read. Renders sharing a pool share its threads, and the result is the same on any pool.
 *
 * <p>Cancelling: interrupt the thread that called a method. The running stage stops at its next test, before each
 * tile, each block of 48 sweep lines or every 64 rays of a march, and the method throws
 * {@link InterruptedException} (interrupt status cleared) once none of its work runs any more (and, on a pool of
 * its own, once the pool's threads have ended); other renders on a shared pool go on. Measured on two
 * threads of a 2-core machine: an exact-shadow render of a 1197 × 643 DEM (3.7–7.7 s uninterrupted) throws a median
 * 1.4 ms and at most 8 ms after the interrupt, a soft sweep of 4788 × 2572 cells a median 22 ms, at most 94 ms
 * (docs/algorithms.md). The stages alone cancel the same way: {@link io.github.jdem846.shadow.ShadowAlgorithm}.
 */
public final class Renderer {

    /** The name prefix of the renderer's worker threads. */
    static final String WORKER_NAME = "jdem846-render-";
    /** The name of the sky-view stage in progress reports. */
    public static final String SKY_STAGE = "sky view";
    private static final long TERMINATION_WAIT_SECONDS = 10;

    /** Mid-gray, the base colour when a scene has no tint (the original's gray tint, 0.5). */
    static final int PLAIN_GRAY = 0xFF808080;

    private final RenderSettings settings;

    /**
     * A renderer with the given thread count, tile size and pool.
     *
     * @param settings threads, tile size and optional pool; not null
     */
    public Renderer(RenderSettings settings) {
        this.settings = Objects.requireNonNull(settings, "settings");
    }

    /** A renderer using every processor and the default tile size. */
    public Renderer() {
        this(RenderSettings.defaults());
    }

    /**
     * Renders without progress reports.
     *
     * @param dem the elevations
     * @param scene what to draw: tint, hillshade, shadows and light
     * @return the picture, one pixel per cell of {@code dem}
     * @throws InterruptedException when the calling thread is interrupted; no picture is returned
     */
    public RenderedRelief render(Dem dem, Scene scene) throws InterruptedException {
        return render(dem, scene, RenderProgress.NONE);
    }

    /**
     * Renders {@code scene} over the whole of {@code dem}, reporting progress per stage.
     *
     * @param dem the elevations
     * @param scene what to draw: tint, hillshade, shadows and light
     * @param progress told the stage and the work done; {@link RenderProgress#NONE} for no reports
     * @return the picture, one pixel per cell of {@code dem}
     * @throws InterruptedException when the calling thread is interrupted; no picture is returned
     */
    public RenderedRelief render(Dem dem, Scene scene, RenderProgress progress) throws InterruptedException {
        return render(dem, scene, CellWindow.whole(dem.width(), dem.height()), progress);
    }

    /**
     * Renders only the cells of {@code area} (the picture has its size and geometry); the rest of {@code dem} is
     * read as the halo that hillshade normals and cast shadows need, but never drawn or traced. Equal to the same
     * cells of a whole-grid render.
     *
     * @param dem the elevations, the area and its halo
     * @param scene what to draw: tint, hillshade, shadows and light
     * @param area the cells to draw, inside {@code dem}
     * @param progress told the stage and the work done; {@link RenderProgress#NONE} for no reports
     * @return the picture of {@code area}, one pixel per cell
     * @throws InterruptedException when the calling thread is interrupted; no picture is returned
     * @throws java.io.UncheckedIOException when the scene's drape cannot be read (its cause names the file)
     */
    public RenderedRelief render(Dem dem, Scene scene, CellWindow area, RenderProgress progress)
            throws InterruptedException {
        Objects.requireNonNull(dem, "dem");
        Objects.requireNonNull(scene, "scene");
        Objects.requireNonNull(progress, "progress");
        requireInside(area, dem);
        try (WorkerPool workers = WorkerPool.of(settings)) {
            return render(dem, scene, area, progress, workers.pool);
        }
    }

    private RenderedRelief render(Dem dem, Scene scene, CellWindow area, RenderProgress progress, ForkJoinPool pool)
            throws InterruptedException {
        int width = area.width();
        int height = area.height();
        TintFunction tint = scene.tint() == null ? elevation -> Float.isNaN(elevation) ? 0 : PLAIN_GRAY
                : scene.tint().bind(scene.tintRange() != null ? scene.tintRange() : dem.statistics());
        float[] shadow = castShadows(dem, scene, area, pool, progress);
        float[] sky = skyView(dem, scene, area, pool, progress);
        IlluminationStage illumination = scene.hillshade() == null ? null
                : scene.hillshade().stage(scene.hillshadeOptions());
        boolean levelGround = illumination == null && scene.lightModel() == LightModel.SKY;
        Compositor compositor = new Compositor(scene.hillshadeOptions(), scene.shadowIntensity(),
                scene.lightModel(), scene.ambient(), scene.blend());
        LightField light = scene.light();
        int[] argb = new int[width * height];
        float[] values = dem.backingArray();
        int demWidth = dem.width();
        boolean covered = dem.hasCoverage();
        int[] drape = drape(dem, scene, area);
        SpareArrays<float[]> buffers = SpareArrays.floats();
        new TileExecutor(pool, settings.tileSize()).forEachTile(width, height, RenderProgress.SHADING, progress,
                (c0, r0, w, h) -> {
                    float[] dot = buffers.take(w * h);
                    if (illumination != null) {
                        illuminate(dem, illumination, light, area.col() + c0, area.row() + r0, w, h, dot);
                    } else if (levelGround) {
                        levelGround(light, area.col() + c0, area.row() + r0, w, h, dot);
                    } else {
                        java.util.Arrays.fill(dot, 0, w * h, 0f);
                    }
                    for (int r = 0; r < h; r++) {
                        int out = (r0 + r) * width + c0;
                        int in = (area.row() + r0 + r) * demWidth + area.col() + c0;
                        for (int c = 0; c < w; c++) {
                            double s = shadow == null ? 0 : shadow[out + c];
                            double v = sky == null ? 1 : sky[out + c];
                            float elevation = values[in + c];
                            int base = drape == null || elevation != elevation ? tint.argb(elevation)
                                    : ColorLayer.over(drape[out + c], tint.argb(elevation));
                            int pixel = compositor.compose(base, dot[r * w + c], s, v, scene.fade());
                            argb[out + c] = covered ? withCoverage(pixel, dem.coverage(area.col() + c0 + c,
                                    area.row() + r0 + r)) : pixel;
                        }
                    }
                    buffers.give(dot);
                });
        return new RenderedRelief(width, height, argb,
                dem.geometry().window(area.col(), area.row(), width, height));
    }

    /**
     * The scene's draped colours over {@code area} ({@link Scene#drape()}), or null without a drape; an image that
     * cannot be read throws {@link java.io.UncheckedIOException} with the {@link java.io.IOException} naming it.
     */
    private static int[] drape(Dem dem, Scene scene, CellWindow area) {
        if (scene.drape() == null) {
            return null;
        }
        try {
            return scene.drape().argb(dem.geometry(), area);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e.getMessage(), e);
        }
    }

    /** {@code argb} with its alpha scaled by {@code coverage} (an anti-aliased edge of no-data). */
    static int withCoverage(int argb, float coverage) {
        int alpha = Math.round((argb >>> 24) * coverage);
        return alpha << 24 | (alpha == 0 ? 0 : argb & 0xFFFFFF);
    }

    /**
     * The illumination layer alone (for single-band hillshade products): the cosine of incidence of every cell,
     * NaN for no-data, computed tile by tile.
     *
     * @param dem the elevations
     * @param stage computes the illumination of a block of cells ({@link HillshadeMethod#stage})
     * @param light the light of each cell
     * @param progress told the stage and the work done; {@link RenderProgress#NONE} for no reports
     * @return the illumination, row-major, one value per cell of {@code dem}
     * @throws InterruptedException when the calling thread is interrupted
     */
    public float[] illumination(Dem dem, IlluminationStage stage, LightField light, RenderProgress progress)
            throws InterruptedException {
        return illumination(dem, stage, light, CellWindow.whole(dem.width(), dem.height()), progress);
    }

    /**
     * The illumination of the cells of {@code area} only (row length {@code area.width()}).
     *
     * @param dem the elevations, the area and its halo
     * @param stage computes the illumination of a block of cells ({@link HillshadeMethod#stage})
     * @param light the light of each cell
     * @param area the cells to compute, inside {@code dem}
     * @param progress told the stage and the work done; {@link RenderProgress#NONE} for no reports
     * @return the illumination, row-major, one value per cell of {@code area}
     * @throws InterruptedException when the calling thread is interrupted
     */
    public float[] illumination(Dem dem, IlluminationStage stage, LightField light, CellWindow area,
                                RenderProgress progress) throws InterruptedException {
        int width = area.width();
        float[] out = new float[width * area.height()];
        illuminateTiles(dem, stage, light, area, progress, (c0, r0, w, h, tile) -> {
            for (int r = 0; r < h; r++) {
                System.arraycopy(tile, r * w, out, (r0 + r) * width + c0, w);
            }
        });
        return out;
    }

    /**
     * The single-band gray hillshade product: {@link HillshadeMethod#gray} of every cell's illumination (0 =
     * no-data), computed and converted tile by tile, so it equals {@code method.toGray(illumination(…))} without
     * holding the float layer.
     *
     * @param dem the elevations
     * @param method the hillshade method
     * @param options its z-factor, intensities and scale
     * @param light the light of each cell
     * @param progress told the stage and the work done; {@link RenderProgress#NONE} for no reports
     * @return the gray values, row-major, one byte per cell of {@code dem}
     * @throws InterruptedException when the calling thread is interrupted
     */
    public byte[] hillshadeGray(Dem dem, HillshadeMethod method, HillshadeOptions options, LightField light,
                                RenderProgress progress) throws InterruptedException {
        return hillshadeGray(dem, method, options, light, CellWindow.whole(dem.width(), dem.height()), progress);
    }

    /**
     * {@link #hillshadeGray(Dem, HillshadeMethod, HillshadeOptions, LightField, RenderProgress)} of {@code area}.
     *
     * @param dem the elevations, the area and its halo
     * @param method the hillshade method
     * @param options its z-factor, intensities and scale
     * @param light the light of each cell
     * @param area the cells to compute, inside {@code dem}
     * @param progress told the stage and the work done; {@link RenderProgress#NONE} for no reports
     * @return the gray values, row-major, one byte per cell of {@code area}
     * @throws InterruptedException when the calling thread is interrupted
     */
    public byte[] hillshadeGray(Dem dem, HillshadeMethod method, HillshadeOptions options, LightField light,
                                CellWindow area, RenderProgress progress) throws InterruptedException {
        Objects.requireNonNull(method, "method");
        Objects.requireNonNull(options, "options");
        int width = area.width();
        byte[] out = new byte[width * area.height()];
        illuminateTiles(dem, method.stage(options), light, area, progress, (c0, r0, w, h, tile) -> {
            for (int r = 0; r < h; r++) {
                method.toGray(tile, r * w, out, (r0 + r) * width + c0, w, options);
            }
        });
        return out;
    }

    /**
     * Receives the illumination of one tile ({@code w × h}, at ({@code c0}, {@code r0}) of the area), in an array
     * that later tiles reuse once this returns.
     */
    @FunctionalInterface
    private interface IlluminatedTile {
        void accept(int c0, int r0, int w, int h, float[] tile);
    }

    /** Computes the illumination of {@code area} tile by tile on a pool of its own, handing each tile over. */
    private void illuminateTiles(Dem dem, IlluminationStage stage, LightField light, CellWindow area,
                                 RenderProgress progress, IlluminatedTile sink) throws InterruptedException {
        requireInside(area, dem);
        SpareArrays<float[]> buffers = SpareArrays.floats();
        try (WorkerPool workers = WorkerPool.of(settings)) {
            new TileExecutor(workers.pool, settings.tileSize()).forEachTile(area.width(), area.height(),
                    RenderProgress.HILLSHADE,
                    progress, (c0, r0, w, h) -> {
                        float[] tile = buffers.take(w * h);
                        illuminate(dem, stage, light, area.col() + c0, area.row() + r0, w, h, tile);
                        sink.accept(c0, r0, w, h, tile);
                        buffers.give(tile);
                    });
        }
    }

    /**
     * The cast-shadow layer alone: the shadowed fraction of every cell (0 = lit, 1 = shadow; no-data 0).
     *
     * @param dem the elevations
     * @param scene its shadow algorithm, options and light
     * @param progress told the stage and the work done; {@link RenderProgress#NONE} for no reports
     * @return the shadowed fractions, row-major, one value per cell of {@code dem}
     * @throws InterruptedException when the calling thread is interrupted
     */
    public float[] shadows(Dem dem, Scene scene, RenderProgress progress) throws InterruptedException {
        return shadows(dem, scene, CellWindow.whole(dem.width(), dem.height()), progress);
    }

    /**
     * The cast-shadow layer of the cells of {@code area} only (row length {@code area.width()}).
     *
     * @param dem the elevations, the area and its halo
     * @param scene its shadow algorithm, options and light
     * @param area the cells to compute, inside {@code dem}
     * @param progress told the stage and the work done; {@link RenderProgress#NONE} for no reports
     * @return the shadowed fractions, row-major, one value per cell of {@code area}
     * @throws InterruptedException when the calling thread is interrupted
     */
    public float[] shadows(Dem dem, Scene scene, CellWindow area, RenderProgress progress)
            throws InterruptedException {
        requireInside(area, dem);
        try (WorkerPool workers = WorkerPool.of(settings)) {
            float[] s = castShadows(dem, scene, area, workers.pool, progress);
            return s != null ? s : new float[area.width() * area.height()];
        }
    }

    /**
     * The cast-shadow layer of {@code area} as bytes: 0 = lit … 255 = in shadow, the shadowed fraction times 255
     * rounded half up, converted on the workers that computed it (16 million cells take a one-shot command's single
     * thread about 60 ms).
     *
     * @param dem the elevations, the area and its halo
     * @param scene its shadow algorithm, options and light
     * @param area the cells to compute, inside {@code dem}
     * @param progress told the stage and the work done; {@link RenderProgress#NONE} for no reports
     * @return one byte per cell of {@code area}, row-major; read as unsigned
     * @throws InterruptedException when the calling thread is interrupted
     */
    public byte[] shadowBytes(Dem dem, Scene scene, CellWindow area, RenderProgress progress)
            throws InterruptedException {
        requireInside(area, dem);
        int width = area.width();
        byte[] out = new byte[width * area.height()];
        try (WorkerPool workers = WorkerPool.of(settings)) {
            float[] s = castShadows(dem, scene, area, workers.pool, progress);
            if (s != null) {
                new TileExecutor(workers.pool, settings.tileSize()).forEachTile(width, area.height(),
                        RenderProgress.SHADOWS, RenderProgress.NONE, (c0, r0, w, h) -> {
                            for (int i = r0 * width; i < (r0 + h) * width; i += width) {
                                for (int c = c0; c < c0 + w; c++) {
                                    out[i + c] = (byte) Rounding.halfUp(Clamp.between(s[i + c], 0f, 1f) * 255f);
                                }
                            }
                        });
            }
        }
        return out;
    }

    /**
     * The pool of one call: the settings' shared pool, left as it is on closing, or else a pool of daemon threads
     * named {@value #WORKER_NAME}…, one per call: closing it shuts it down and waits (at most
     * {@link #TERMINATION_WAIT_SECONDS}) until its threads have ended, which takes no time since every stage has
     * returned by then. The interrupt status is kept.
     */
    private static final class WorkerPool implements AutoCloseable {
        final ForkJoinPool pool;
        private final boolean own;
        private final List<Thread> threads = new CopyOnWriteArrayList<>();

        private WorkerPool(ForkJoinPool shared) {
            pool = shared;
            own = false;
        }

        private WorkerPool(int parallelism) {
            pool = new ForkJoinPool(parallelism, p -> {
                ForkJoinWorkerThread t = ForkJoinPool.defaultForkJoinWorkerThreadFactory.newThread(p);
                t.setName(WORKER_NAME + t.getName());
                threads.add(t);
                return t;
            }, null, false);
            own = true;
        }

        static WorkerPool of(RenderSettings settings) {
            return settings.pool() != null ? new WorkerPool(settings.pool()) : new WorkerPool(settings.parallelism());
        }

        @Override
        public void close() {
            if (!own) {
                return;
            }
            pool.shutdownNow();
            boolean interrupted = Thread.interrupted();
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(TERMINATION_WAIT_SECONDS);
            try {
                for (Thread t : threads) {
                    t.join(Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
                }
            } catch (InterruptedException e) {
                interrupted = true;
            }
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
    }

    private static void requireInside(CellWindow area, Dem dem) {
        Objects.requireNonNull(area, "area");
        if (!area.isInside(dem.width(), dem.height())) {
            throw new IllegalArgumentException("area " + area + " is not inside the " + dem.width() + "×"
                    + dem.height() + " DEM");
        }
    }

    private static void illuminate(Dem dem, IlluminationStage stage, LightField light, int col0, int row0, int w,
                                   int h, float[] out) {
        if (light.isUniform()) {
            stage.illuminate(dem, light.central(), col0, row0, w, h, out);
            return;
        }
        float[] row = new float[w];
        for (int r = 0; r < h; r++) {
            LightDirection l = light.at(col0 + w / 2, row0 + r);
            stage.illuminate(dem, l, col0, row0 + r, w, 1, row);
            System.arraycopy(row, 0, out, r * w, w);
        }
    }

    /** The cosine of incidence of level ground, sin(sun elevation), for a scene without a hillshade. */
    private static void levelGround(LightField light, int col0, int row0, int w, int h, float[] out) {
        for (int r = 0; r < h; r++) {
            float up = (float) light.at(col0 + w / 2, row0 + r).up();
            java.util.Arrays.fill(out, r * w, (r + 1) * w, up);
        }
    }

    /**
     * The sky-view layer alone: the sky-view factor of every cell of {@code area} ({@link SkyView}, with the scene's
     * directions and z-factor), NaN for no-data; horizons are seen over the whole of {@code dem}.
     *
     * @param dem      the terrain
     * @param scene    supplies the directions and the z-factor
     * @param area     the cells wanted
     * @param progress receives the stage "sky view"
     * @return the factors, row length {@code area.width()}
     * @throws InterruptedException when the calling thread is interrupted
     */
    public float[] skyView(Dem dem, Scene scene, CellWindow area, RenderProgress progress)
            throws InterruptedException {
        requireInside(area, dem);
        try (WorkerPool workers = WorkerPool.of(settings)) {
            return computeSkyView(dem, scene, area, workers.pool, progress);
        }
    }

    /** The sky-view factor of each cell of {@code area}, or {@code null} when the scene has no sky light. */
    private static float[] skyView(Dem dem, Scene scene, CellWindow area, ForkJoinPool pool, RenderProgress progress)
            throws InterruptedException {
        return scene.hasAmbient() ? computeSkyView(dem, scene, area, pool, progress) : null;
    }

    private static float[] computeSkyView(Dem dem, Scene scene, CellWindow area, ForkJoinPool pool,
                                          RenderProgress progress) throws InterruptedException {
        progress.update(SKY_STAGE, 0, 1);
        float[] f;
        try {
            f = SkyView.compute(dem, scene.skyViewOptions(), pool, area);
        } catch (CancellationException e) {
            throw TileExecutor.interrupted(e);
        }
        progress.update(SKY_STAGE, 1, 1);
        return f;
    }

    /** The shadowed fraction of each cell of {@code area}, or {@code null} when the scene has no cast shadows. */
    private static float[] castShadows(Dem dem, Scene scene, CellWindow area, ForkJoinPool pool,
                                       RenderProgress progress) throws InterruptedException {
        if (!scene.hasShadows()) {
            return null;
        }
        ShadowMask mask;
        try {
            mask = scene.shadows().computeWindow(dem, scene.shadowLight(), scene.shadowOptions(), pool, area,
                    new ShadowStage(progress));
        } catch (CancellationException e) {
            throw TileExecutor.interrupted(e);
        }
        return mask.backingArray();
    }

    /** The shadow algorithm's blocks as the {@value RenderProgress#SHADOWS} stage, thinned ({@link StageProgress}). */
    private static final class ShadowStage implements ShadowProgress {
        private final RenderProgress progress;
        private StageProgress stage;

        ShadowStage(RenderProgress progress) {
            this.progress = progress;
        }

        @Override
        public synchronized void update(long done, long total) {
            if (stage == null) {
                stage = new StageProgress(progress, RenderProgress.SHADOWS, total).start();
            }
            stage.reached(done);
        }
    }
}
