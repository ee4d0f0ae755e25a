package io.github.jdem846.render;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.shade.IlluminationStage;
import io.github.jdem846.shadow.ShadowMask;
import io.github.jdem846.tint.TintFunction;
import java.util.Objects;
import java.util.concurrent.ForkJoinPool;

/**
 * Renders a {@link Scene} of a {@link Dem} into ARGB pixels, one pixel per DEM cell: cast shadows first (the whole
 * grid, parallel inside the shadow algorithm), then tint, illumination and composition tile by tile on a
 * {@link ForkJoinPool}. The result is identical for any thread count and tile size.
 *
 * <p>To render at a smaller size, resample the DEM first ({@link io.github.jdem846.raster.DemResampler}, or a
 * decimated read): stages then run at the output resolution. Interrupting the calling thread stops the work
 * promptly with {@link InterruptedException}.
 */
public final class Renderer {

    /** Mid-gray, the base colour when a scene has no tint (the original's gray tint, 0.5). */
    static final int PLAIN_GRAY = 0xFF808080;

    private final RenderSettings settings;

    public Renderer(RenderSettings settings) {
        this.settings = Objects.requireNonNull(settings, "settings");
    }

    /** A renderer using every processor and the default tile size. */
    public Renderer() {
        this(RenderSettings.defaults());
    }

    /** Renders without progress reports. */
    public RenderedImage render(Dem dem, Scene scene) throws InterruptedException {
        return render(dem, scene, RenderProgress.NONE);
    }

    /** Renders {@code scene} over the whole of {@code dem}, reporting progress per stage. */
    public RenderedImage render(Dem dem, Scene scene, RenderProgress progress) throws InterruptedException {
        Objects.requireNonNull(dem, "dem");
        Objects.requireNonNull(scene, "scene");
        Objects.requireNonNull(progress, "progress");
        ForkJoinPool pool = new ForkJoinPool(settings.parallelism());
        try {
            return render(dem, scene, progress, pool);
        } finally {
            pool.shutdownNow();
        }
    }

    private RenderedImage render(Dem dem, Scene scene, RenderProgress progress, ForkJoinPool pool)
            throws InterruptedException {
        int width = dem.width();
        int height = dem.height();
        TintFunction tint = scene.tint() == null ? elevation -> Float.isNaN(elevation) ? 0 : PLAIN_GRAY
                : scene.tint().bind(scene.tintRange() != null ? scene.tintRange() : dem.statistics());
        float[] shadow = castShadows(dem, scene, pool, progress);
        IlluminationStage illumination = scene.hillshade() == null ? null
                : scene.hillshade().stage(scene.hillshadeOptions());
        Compositor compositor = new Compositor(scene.hillshadeOptions(), scene.shadowIntensity());
        LightField light = scene.light();
        int[] argb = new int[width * height];
        float[] values = dem.backingArray();
        new TileExecutor(pool, settings.tileSize()).forEachTile(width, height, "shading", progress,
                (col0, row0, w, h) -> {
                    float[] dot = new float[w * h];
                    if (illumination != null) {
                        illuminate(dem, illumination, light, col0, row0, w, h, dot);
                    }
                    for (int r = 0; r < h; r++) {
                        int rowBase = (row0 + r) * width + col0;
                        for (int c = 0; c < w; c++) {
                            int i = rowBase + c;
                            double s = shadow == null ? 0 : shadow[i];
                            argb[i] = compositor.compose(tint.argb(values[i]), dot[r * w + c], s, scene.fade());
                        }
                    }
                });
        return new RenderedImage(width, height, argb, dem.geometry());
    }

    /**
     * The illumination layer alone (for single-band hillshade products): the cosine of incidence of every cell,
     * NaN for no-data, computed tile by tile.
     */
    public float[] illumination(Dem dem, IlluminationStage stage, LightField light, RenderProgress progress)
            throws InterruptedException {
        int width = dem.width();
        float[] out = new float[width * dem.height()];
        ForkJoinPool pool = new ForkJoinPool(settings.parallelism());
        try {
            new TileExecutor(pool, settings.tileSize()).forEachTile(width, dem.height(), "hillshade", progress,
                    (col0, row0, w, h) -> {
                        float[] tile = new float[w * h];
                        illuminate(dem, stage, light, col0, row0, w, h, tile);
                        for (int r = 0; r < h; r++) {
                            System.arraycopy(tile, r * w, out, (row0 + r) * width + col0, w);
                        }
                    });
        } finally {
            pool.shutdownNow();
        }
        return out;
    }

    /**
     * The single-band gray hillshade product: {@link HillshadeMethod#gray} of every cell's illumination (0 =
     * no-data), computed and converted tile by tile, so it equals {@code method.toGray(illumination(…))} without
     * holding the float layer.
     */
    public byte[] hillshadeGray(Dem dem, HillshadeMethod method, HillshadeOptions options, LightField light,
                                RenderProgress progress) throws InterruptedException {
        Objects.requireNonNull(method, "method");
        Objects.requireNonNull(options, "options");
        IlluminationStage stage = method.stage(options);
        int width = dem.width();
        byte[] out = new byte[width * dem.height()];
        ForkJoinPool pool = new ForkJoinPool(settings.parallelism());
        try {
            new TileExecutor(pool, settings.tileSize()).forEachTile(width, dem.height(), "hillshade", progress,
                    (col0, row0, w, h) -> {
                        float[] tile = new float[w * h];
                        illuminate(dem, stage, light, col0, row0, w, h, tile);
                        for (int r = 0; r < h; r++) {
                            int o = (row0 + r) * width + col0;
                            for (int c = 0; c < w; c++) {
                                out[o + c] = (byte) method.gray(tile[r * w + c], options);
                            }
                        }
                    });
        } finally {
            pool.shutdownNow();
        }
        return out;
    }

    /**
     * The cast-shadow layer alone: the shadowed fraction of every cell (0 = lit, 1 = shadow; no-data 0).
     */
    public float[] shadows(Dem dem, Scene scene, RenderProgress progress) throws InterruptedException {
        ForkJoinPool pool = new ForkJoinPool(settings.parallelism());
        try {
            float[] s = castShadows(dem, scene, pool, progress);
            return s != null ? s : new float[dem.width() * dem.height()];
        } finally {
            pool.shutdownNow();
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

    /** The shadowed fraction per cell, or {@code null} when the scene has no cast shadows. */
    private static float[] castShadows(Dem dem, Scene scene, ForkJoinPool pool, RenderProgress progress)
            throws InterruptedException {
        if (!scene.hasShadows()) {
            return null;
        }
        progress.update("shadows", 0, 1);
        ShadowMask mask = scene.shadows().compute(dem, scene.light().central(), scene.shadowOptions(), pool);
        if (Thread.interrupted()) {
            throw new InterruptedException("render cancelled");
        }
        progress.update("shadows", 1, 1);
        return mask.backingArray();
    }
}
