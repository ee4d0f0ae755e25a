package io.github.jdem846.view;

import io.github.jdem846.parallel.Cancellation;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.RenderedRelief;
import java.io.IOException;
import java.util.Objects;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Draws a perspective view of a DEM with a picture draped on it (normally its shaded relief, {@link
 * io.github.jdem846.render.Renderer}): the grid's cells become two triangles each, rasterised with a depth buffer
 * and perspective-correct, bilinear texture lookups, over horizontal bands of the picture in parallel (with walls
 * down to a base, {@link ViewOptions#base()}); pixels no
 * terrain covers get the background ({@link ViewOptions}). The result is identical for any thread count.
 *
 * <p>Threads and cancelling as {@link io.github.jdem846.render.Renderer}: a pool of the settings' parallelism per
 * call, or the settings' shared pool; interrupting the calling thread stops the call with {@link
 * InterruptedException}. Immutable and thread-safe.
 */
public final class PerspectiveRenderer {

    /** The base's walls are the edge's colours at this fraction of their brightness. */
    static final double WALL_BRIGHTNESS = 0.45;

    private final RenderSettings settings;

    /**
     * A renderer on {@code settings}' threads (its tile size is not used).
     *
     * @param settings threads, or a shared pool
     */
    public PerspectiveRenderer(RenderSettings settings) {
        this.settings = Objects.requireNonNull(settings, "settings");
    }

    /**
     * Renders the view.
     *
     * @param dem      the terrain, one vertex per cell; no-data cells are holes
     * @param texture  the picture draped on it, placed by its geometry (same CRS as {@code dem}'s; any resolution)
     * @param camera   where the camera stands and the picture's size
     * @param options  exaggeration, background, globe
     * @param progress told of the bands drawn (stage "view")
     * @return the picture
     * @throws InterruptedException     when the calling thread is interrupted
     * @throws IllegalArgumentException in globe mode, for a grid whose CRS gives no latitude and longitude
     */
    public RenderedView render(Dem dem, RenderedRelief texture, Camera camera, ViewOptions options,
                               RenderProgress progress) throws InterruptedException {
        Objects.requireNonNull(dem, "dem");
        Objects.requireNonNull(texture, "texture");
        Objects.requireNonNull(camera, "camera");
        Objects.requireNonNull(options, "options");
        Objects.requireNonNull(progress, "progress");
        Terrain terrain = Terrain.of(dem, texture.geometry(), options);
        Pose pose = pose(terrain, camera);
        return draw(Mesh.of(terrain), terrain, pose, texture, camera, options, progress);
    }

    /**
     * Renders the view with levels of detail ({@link LevelsOfDetail}): the grid of {@code source} box-averaged by
     * {@code decimation}, and finer near the camera.
     *
     * @throws IOException when a level cannot be read
     */
    RenderedView render(TerrainSource source, int decimation, RenderedRelief texture, Camera camera,
                        ViewOptions options, RenderProgress progress) throws IOException, InterruptedException {
        Dem coarse = source.read(0, 0, source.width(), source.height(), decimation);
        return render(coarse, source, decimation, texture, camera, options, progress);
    }

    /** As {@link #render(TerrainSource, int, RenderedRelief, Camera, ViewOptions, RenderProgress)}, its coarse grid read. */
    RenderedView render(Dem coarse, TerrainSource source, int decimation, RenderedRelief texture, Camera camera,
                        ViewOptions options, RenderProgress progress) throws IOException, InterruptedException {
        Terrain terrain = Terrain.of(coarse, texture.geometry(), options);
        Pose pose = pose(terrain, camera);
        Mesh mesh = LevelsOfDetail.mesh(terrain, coarse, source, decimation, pose, camera.width(), camera.height(),
                texture.geometry());
        return draw(mesh, terrain, pose, texture, camera, options, progress);
    }

    private RenderedView draw(Mesh mesh, Terrain terrain, Pose pose, RenderedRelief texture, Camera camera,
                              ViewOptions options, RenderProgress progress) throws InterruptedException {
        int w = camera.width();
        int h = camera.height();
        Rasterizer rasterizer = new Rasterizer(mesh, pose, w, h);
        Background background = new Background(pose, options, terrain.globe);
        TextureSampler sampler = new TextureSampler(texture);
        float[] depth = new float[w * h];
        float[] texU = new float[w * h];
        float[] texV = new float[w * h];
        boolean[] wall = new boolean[w * h];
        int[] argb = new int[w * h];
        int bands = rasterizer.bands();
        AtomicLong done = new AtomicLong();
        ForkJoinPool shared = settings.pool();
        ForkJoinPool pool = shared != null ? shared : new ForkJoinPool(settings.parallelism());
        try {
            Cancellation.invokeAll(pool, bands, (band, cancel) -> {
                rasterizer.drawBand(band, depth, texU, texV, wall);
                int end = Math.min(h, (band + 1) * Rasterizer.BAND) * w;
                for (int p = band * Rasterizer.BAND * w; p < end; p++) {
                    int colour = depth[p] > 0 ? sampler.at(texU[p], texV[p]) : 0;
                    if (colour != 0 && wall[p]) {
                        colour = Background.mix(0xFF000000, colour, WALL_BRIGHTNESS);
                    }
                    argb[p] = colour != 0 ? colour : background.at(p % w, p / w);
                }
                progress.update("view", done.incrementAndGet(), bands);
            });
        } catch (CancellationException e) {
            Thread.interrupted();
            InterruptedException stopped = new InterruptedException("view cancelled");
            stopped.initCause(e);
            throw stopped;
        } finally {
            if (shared == null) {
                pool.shutdownNow();
            }
        }
        return new RenderedView(w, h, argb);
    }

    /**
     * The cells of {@code dem} whose triangles the camera sees (all of them, or fewer when it stands close):
     * {firstCol, firstRow, lastCol, lastRow}, or null when none.
     *
     * @param dem     the terrain
     * @param camera  the camera
     * @param options exaggeration and globe
     * @return the box of cells, each the square between four vertices (so the last is at most width − 2)
     */
    static int[] visibleCells(Dem dem, Camera camera, ViewOptions options) {
        Terrain terrain = Terrain.of(dem, dem.geometry(), options);
        return new Rasterizer(terrain, pose(terrain, camera), camera.width(), camera.height()).drawnCells();
    }

    /**
     * The camera's pose: looking at the middle of the terrain's height range above its centre, or from and at the
     * points of its {@link LookAt}.
     */
    static Pose pose(Terrain terrain, Camera camera) {
        LookAt at = camera.lookAt();
        if (at != null) {
            double targetZ = at.targetZ();
            if (at.targetOnTerrain()) {
                targetZ = terrain.heightAt(at.targetX(), at.targetY());
                if (Double.isNaN(targetZ)) {
                    targetZ = terrain.middleHeight();
                }
            }
            return Pose.lookAt(camera, terrain.toLocal(at.x(), at.y(), at.z()),
                    terrain.toLocal(at.targetX(), at.targetY(), targetZ));
        }
        double zMin = Double.POSITIVE_INFINITY;
        double zMax = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < terrain.size(); i++) {
            float z = terrain.z[i];
            if (!Float.isNaN(z)) {
                zMin = Math.min(zMin, z);
                zMax = Math.max(zMax, z);
            }
        }
        double[] target = {0, 0, zMin <= zMax ? 0.5 * (zMin + zMax) : 0};
        if (!camera.fits()) {
            return Pose.of(camera, target, camera.distanceMeters());
        }
        return FitDistance.of(terrain, camera, target);
    }
}
