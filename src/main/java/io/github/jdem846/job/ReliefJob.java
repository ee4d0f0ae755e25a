package io.github.jdem846.job;

import io.github.jdem846.internal.Clamp;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.Window;
import io.github.jdem846.output.InputProtection;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.output.WriteResult;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.OutputSize;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.RenderedImage;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.CellWindow;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.ShadowOptions;
import io.github.jdem846.sun.Body;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Objects;

/**
 * One picture of one DEM file, from file to pixels (and to a file): plans the read (the window, the halo each stage
 * needs around it, the decimation for a smaller picture), reads only that, lights the grid with the {@link Sun}
 * (fixed, or the real sun at a date and time over the cells read), renders the {@link Product} and hands it back
 * or writes it. Every command of the CLI is this job with options parsed.
 *
 * <pre>{@code
 * ReliefResult relief = ReliefJob.of(Path.of("dem.tif"))
 *         .withWindow(Window.world(380000, 3780000, 400000, 3800000))
 *         .withSun(Sun.at(ZonedDateTime.parse("2024-06-21T06:30-07:00[America/Los_Angeles]")))
 *         .withScene(Scene.defaults().withShadows(ShadowAlgorithm.SWEEP))
 *         .run(JobListener.NONE);
 * relief.write(Path.of("relief.png"), WriteOptions.defaults());
 * }</pre>
 *
 * <p>Immutable and thread-safe; {@link #run} may be called from several threads at once. Interrupting the calling
 * thread stops a run with {@link InterruptedException}.
 *
 * @param input     the DEM file (GeoTIFF, GridFloat, ESRI ASCII, BIL, SRTM HGT) or files read as one grid, or
 *                  {@code null} for the bundled sample DEM
 * @param product   what to make
 * @param scene     the stages and their settings; its light is replaced by {@code sun}'s. For {@link
 *                  Product#HILLSHADE} only its hillshade method and options count, for {@link Product#TINT} only
 *                  its tint, for {@link Product#SHADOWS} only its shadow algorithm and options (not NONE)
 * @param window    the part of the DEM to draw, or {@code null} for all of it
 * @param size      the picture's size ({@link OutputSize#FULL}: one pixel per cell); stages run at that resolution
 * @param sun       the light
 * @param body      the body a DEM whose file names no ellipsoid lies on (metric cell sizes, the sun by date and
 *                  time)
 * @param execution threads and tile size; the result does not depend on them
 */
public record ReliefJob(DemInput input, Product product, Scene scene, Window window, OutputSize size, Sun sun,
                        Body body, RenderSettings execution) {

    public ReliefJob {
        Objects.requireNonNull(product, "product");
        Objects.requireNonNull(scene, "scene");
        Objects.requireNonNull(size, "size");
        Objects.requireNonNull(sun, "sun");
        Objects.requireNonNull(body, "body");
        Objects.requireNonNull(execution, "execution");
    }

    /**
     * The whole of {@code dem} as a relief picture with the original's defaults, on every processor.
     *
     * @param dem the DEM file
     * @return the job, to be refined with the {@code with…} methods
     */
    public static ReliefJob of(Path dem) {
        return of(DemInput.of(dem));
    }

    /**
     * The whole of {@code dem} (one file or several read as one grid) as a relief picture with the original's
     * defaults, on every processor.
     *
     * @param dem the DEM file or files
     * @return the job, to be refined with the {@code with…} methods
     */
    public static ReliefJob of(DemInput dem) {
        return new ReliefJob(dem, Product.RELIEF, Scene.defaults(), null, OutputSize.FULL, Sun.ORIGINAL_DEFAULT,
                Body.EARTH, RenderSettings.defaults());
    }

    /**
     * The bundled sample DEM (Big Tujunga, California, 600 × 400 cells) with the original's defaults.
     *
     * @return the job, to be refined with the {@code with…} methods
     */
    public static ReliefJob ofSample() {
        return of((DemInput) null);
    }

    /**
     * A copy with another {@code product}.
     *
     * @param value what to make
     * @return the new job
     */
    public ReliefJob withProduct(Product value) {
        return new ReliefJob(input, value, scene, window, size, sun, body, execution);
    }

    /**
     * A copy with another {@code scene}.
     *
     * @param value the stages and their settings
     * @return the new job
     */
    public ReliefJob withScene(Scene value) {
        return new ReliefJob(input, product, value, window, size, sun, body, execution);
    }

    /**
     * A copy with another {@code window}.
     *
     * @param value the part of the DEM to draw, or {@code null} for all of it
     * @return the new job
     */
    public ReliefJob withWindow(Window value) {
        return new ReliefJob(input, product, scene, value, size, sun, body, execution);
    }

    /**
     * A copy with another {@code size}.
     *
     * @param value the picture's size
     * @return the new job
     */
    public ReliefJob withSize(OutputSize value) {
        return new ReliefJob(input, product, scene, window, value, sun, body, execution);
    }

    /**
     * A copy with another {@code sun}.
     *
     * @param value the light
     * @return the new job
     */
    public ReliefJob withSun(Sun value) {
        return new ReliefJob(input, product, scene, window, size, value, body, execution);
    }

    /**
     * A copy with another {@code body}.
     *
     * @param value the body a DEM whose file names no ellipsoid lies on
     * @return the new job
     */
    public ReliefJob withBody(Body value) {
        return new ReliefJob(input, product, scene, window, size, sun, value, execution);
    }

    /**
     * A copy with another {@code execution}.
     *
     * @param value threads and tile size
     * @return the new job
     */
    public ReliefJob withExecution(RenderSettings value) {
        return new ReliefJob(input, product, scene, window, size, sun, body, value);
    }

    /**
     * Reads what the picture needs and renders it.
     *
     * @param listener told of progress, notices, the sun used and the end of each phase
     * @return the picture
     * @throws IOException              naming the file when it cannot be read ({@link
     *                                  io.github.jdem846.io.DemFormatException})
     * @throws IllegalArgumentException when the window lies outside the grid, or the sun cannot be placed
     * @throws InterruptedException     when the calling thread is interrupted
     */
    public ReliefResult run(JobListener listener) throws IOException, InterruptedException {
        Objects.requireNonNull(listener, "listener");
        requireDrawable();
        Scene s = productScene();
        DemLoader.Loaded loaded = load(s);
        listener.phaseDone("read");
        for (String notice : loaded.info().notices()) {
            listener.notice(notice);
        }
        ScaleNotice.of(loaded.info().geometry()).ifPresent(listener::notice);
        if (s.hasShadows()) {
            s = s.withShadowOptions(forLoadedGrid(s.shadowOptions(), loaded));
        }
        return render(loaded.dem(), loaded.info(), loaded.area(), s.withTintRange(loaded.fileStatistics()),
                listener);
    }

    /**
     * Renders the product of the whole of {@code dem}, a grid already in memory ({@link #input()} is not read):
     * the tint spans the grid's own range and no halo is needed.
     *
     * @throws IllegalArgumentException when the job has a window or a size other than {@link OutputSize#FULL}
     *                                  (crop or resample the grid first: {@link Dem#crop}, {@link
     *                                  io.github.jdem846.raster.DemResampler})
     * @param dem      the grid to draw
     * @param listener told of progress, the sun used and the end of each phase
     * @return the picture
     * @throws InterruptedException when the calling thread is interrupted
     */
    public ReliefResult run(Dem dem, JobListener listener) throws InterruptedException {
        Objects.requireNonNull(dem, "dem");
        Objects.requireNonNull(listener, "listener");
        requireDrawable();
        if (window != null || !size.equals(OutputSize.FULL)) {
            throw new IllegalArgumentException("a grid in memory is rendered whole: crop or resample it first");
        }
        return render(dem, null, CellWindow.whole(dem.width(), dem.height()), productScene(), listener);
    }

    /** Lights and renders {@code area} of {@code dem} (the rest is halo) with {@code s}. */
    private ReliefResult render(Dem dem, DemInfo source, CellWindow area, Scene s, JobListener listener)
            throws InterruptedException {
        GridGeometry geometry = dem.geometry().window(area.col(), area.row(), area.width(), area.height());
        Renderer renderer = new Renderer(execution);
        ReliefResult result;
        if (product == Product.TINT) {
            RenderedImage image = renderer.render(dem, s, area, listener);
            result = ReliefResult.rgba(this, source, geometry, image.argb(), null);
        } else {
            Sun.Lighting lighting = sun.over(dem.geometry(), body, execution.tileSize());
            if (lighting.sun() != null) {
                listener.sun(lighting.sun());
            }
            result = switch (product) {
                case RELIEF -> ReliefResult.rgba(this, source, geometry, renderer.render(dem,
                        s.withLight(lighting.field()).withFade(lighting.fade()), area, listener).argb(),
                        lighting.sun());
                case HILLSHADE -> ReliefResult.gray(this, source, geometry, renderer.hillshadeGray(dem,
                        s.hillshade(), s.hillshadeOptions(), lighting.field(), area, listener), lighting.sun());
                case SHADOWS -> ReliefResult.gray(this, source, geometry, maskBytes(renderer.shadows(dem,
                        s.withLight(lighting.field()), area, listener)), lighting.sun());
                case TINT -> throw new AssertionError();
            };
        }
        listener.phaseDone(product == Product.RELIEF ? "render" : product.name().toLowerCase(Locale.ROOT));
        return result;
    }

    /**
     * Runs the job and writes the product to {@code file} ({@link ReliefResult#write}); an output that would
     * replace or delete a file of the input is refused before anything is read ({@link InputProtection}).
     *
     * @param file     the image file (its extension chooses the format)
     * @param options  how to write it
     * @param listener told of progress, notices, the sun used and the end of each phase
     * @return the files written
     * @throws IOException          when the input cannot be read or the output cannot be written
     * @throws InterruptedException when the calling thread is interrupted
     */
    public WriteResult runAndWrite(Path file, WriteOptions options, JobListener listener)
            throws IOException, InterruptedException {
        requireDrawable();
        checkOutput(file, options);
        ReliefResult result = run(listener);
        WriteResult written = result.write(file, options);
        written.notices().forEach(listener::notice);
        listener.phaseDone("write");
        return written;
    }

    /**
     * Refuses, before any work, an output that would replace or delete a file of the input DEM (the DEM itself,
     * its {@code .hdr} or {@code .prj}); nothing to check for the bundled sample or a file that is not a DEM (the
     * read reports that).
     *
     * @param file    the image file to be written
     * @param options how it will be written (its sidecars count too)
     * @throws io.github.jdem846.output.OutputOverwritesInputException naming both files
     * @throws IOException when the output's place cannot be checked
     */
    public void checkOutput(Path file, WriteOptions options) throws IOException {
        if (input == null) {
            return;
        }
        List<Path> inputFiles;
        try {
            inputFiles = DemReader.filesOf(input);
        } catch (IOException notADem) {
            return;
        }
        InputProtection.check(file, options, inputFiles);
    }

    /**
     * Checks that the scene has what the product draws.
     *
     * @throws IllegalArgumentException for a hillshade without a method or a shadow mask without an algorithm
     */
    public void requireDrawable() {
        if (product == Product.HILLSHADE && scene.hillshade() == null) {
            throw new IllegalArgumentException("a hillshade product needs a hillshade method in the scene");
        }
        if (product == Product.SHADOWS && !scene.hasShadows()) {
            throw new IllegalArgumentException("a shadow mask needs a shadow algorithm (sweep, march or exact), "
                    + "not " + scene.shadows());
        }
    }

    /** The scene with what the product does not draw switched off, so that it costs nothing. */
    private Scene productScene() {
        return switch (product) {
            case RELIEF -> scene;
            case HILLSHADE -> scene.withTint(null).withShadows(ShadowAlgorithm.NONE);
            case TINT -> scene.withHillshade(null).withShadows(ShadowAlgorithm.NONE);
            case SHADOWS -> scene.withTint(null).withHillshade(null);
        };
    }

    /** Reads the window with the halo the scene's stages need, and the file's range when a stage needs it. */
    private DemLoader.Loaded load(Scene s) throws IOException {
        DemLoader.Halo halo = s.hillshade() == null ? DemLoader.Halo.NONE : DemLoader.Halo.uniform(1);
        if (s.hasShadows()) {
            halo = halo.union(shadowHalo(s));
        }
        // a percent tint spans the whole file's range; a windowed sweep needs the file's lowest elevation
        boolean fileStatistics = s.tint() != null || s.hasShadows() && window != null;
        if (input != null) {
            return DemLoader.load(input, window, size, halo, fileStatistics, body.ellipsoid(), bytesPerPixel(s));
        }
        return DemLoader.loadSample(window, size, halo, fileStatistics, body.ellipsoid(), bytesPerPixel(s));
    }

    /** What the product holds per output pixel besides the grid (for the heap check before the read). */
    private int bytesPerPixel(Scene s) {
        return switch (product) {
            case RELIEF -> Integer.BYTES + (s.hasShadows() ? Float.BYTES : 0);
            case HILLSHADE -> Byte.BYTES;
            case TINT -> Integer.BYTES;
            case SHADOWS -> Float.BYTES + Byte.BYTES;
        };
    }

    /**
     * The cast-shadow halo. With a sun by date and time the direction is not known before the grid is placed, so
     * it is computed from the file's header for the sun of the whole file; the light used for rendering is
     * computed again over the cells read.
     */
    private DemLoader.Halo shadowHalo(Scene s) {
        double zFactor = s.hillshadeOptions().zFactor();
        return (statistics, info, win) -> DemLoader.Halo.shadows(
                sun.centralOver(info.geometry(), body).forHeightsScaledBy(zFactor), s.shadowOptions())
                .cells(statistics, info, win);
    }

    /**
     * The shadow options for a grid loaded as a window of its file: with the file's lowest elevation, so that the
     * sweep's mask equals the same window of the whole file's ({@link ShadowOptions#terrainMinimum()}); unchanged
     * when the file's statistics were not streamed (no window).
     */
    private static ShadowOptions forLoadedGrid(ShadowOptions options, DemLoader.Loaded loaded) {
        return loaded.fileStatistics() == null ? options
                : options.withTerrainMinimum(loaded.fileStatistics().min());
    }

    /** The shadowed fraction as 0..255. */
    private static byte[] maskBytes(float[] mask) {
        byte[] bytes = new byte[mask.length];
        for (int i = 0; i < mask.length; i++) {
            bytes[i] = (byte) Math.round(Clamp.between(mask[i], 0f, 1f) * 255f);
        }
        return bytes;
    }
}
