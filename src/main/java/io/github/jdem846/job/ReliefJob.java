package io.github.jdem846.job;

import io.github.jdem846.internal.Interrupts;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.Window;
import io.github.jdem846.output.GeoReference;
import io.github.jdem846.output.ImageOutput;
import io.github.jdem846.output.ImageSink;
import io.github.jdem846.output.InputProtection;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.output.WriteResult;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.OutputSize;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.CellWindow;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.SkyView;
import io.github.jdem846.shadow.ShadowOptions;
import io.github.jdem846.sun.Body;
import io.github.jdem846.sun.SunPosition;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;

// Longer than the project's other classes on purpose: this record is the public entry point of a picture (its
// options as withers, and each way to run it: in memory, written whole or in tiles, float values, a plan without
// rendering), and about 40 % of it is Javadoc. The work itself is elsewhere: planning in PicturePlan and JobMemory,
// reading in DemLoader, rendering in AreaRenderer and render.Renderer, tiles in TiledWriter.

/**
 * One picture of one DEM file, from file to pixels (and to a file): plans the read (the window, the halo each stage
 * needs around it, the decimation for a smaller picture), reads only that, lights the grid with the {@link Sun}
 * (fixed, or the real sun at a date and time over the picture), renders the {@link Product} and hands it back or
 * writes it; a picture larger than the memory budget is written tile by tile ({@link #runAndWrite}). Every
 * command of the CLI is this job with options parsed.
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
 * <p>Immutable and thread-safe; {@link #run} may be called from several threads at once. Each run starts a pool of
 * {@link RenderSettings#parallelism()} threads of its own, unless its execution settings name a shared pool
 * ({@link RenderSettings#withPool}): then runs at once share that pool's threads and never shut it down, with the
 * same result. Interrupting the calling thread stops a run with {@link InterruptedException}.
 *
 * @param input     the DEM file (GeoTIFF, GridFloat, ESRI ASCII, BIL, SRTM HGT) or files read as one grid, or
 *                  {@code null} for a job that only renders grids already in memory ({@link #run(Dem, JobListener)})
 * @param product   what to make
 * @param scene     the stages and their settings; its light is replaced by {@code sun}'s. For {@link
 *                  Product#HILLSHADE} only its hillshade method and options count, for {@link Product#TINT} only
 *                  its tint, for {@link Product#SHADOWS} only its shadow algorithm and options (not NONE)
 * @param window    the part of the DEM to draw, or {@code null} for all of it
 * @param size      the picture's size ({@link OutputSize#FULL}: one pixel per cell); stages run at that resolution
 * @param sun       the light
 * @param body      the body a DEM whose file names no ellipsoid lies on (metric cell sizes, the sun by date and
 *                  time)
 * @param mercatorScale how the cells of a Web Mercator DEM are measured for slopes and shadow lengths: on the
 *                  ground row by row ({@link MercatorScale#GROUND}, the default) or in the projection's metres
 * @param execution threads, tile size and optionally a shared pool; the result does not depend on them
 * @param memory    the most heap bytes the job's grids, layers and pictures may take at once, or 0 for half the
 *                  heap's maximum ({@link #memoryBudget()}): {@link #runAndWrite} renders a picture that needs more
 *                  in tiles (docs/scale.md); the result does not depend on it
 */
public record ReliefJob(DemInput input, Product product, Scene scene, Window window, OutputSize size, Sun sun,
                        Body body, MercatorScale mercatorScale, RenderSettings execution, long memory) {

    /**
     * Checks that the parts are given and that the memory budget is ≥ 0.
     *
     * @param input the DEM file (GeoTIFF, GridFloat, ESRI ASCII, BIL, SRTM HGT) or files read as one grid, or {@code
     *     null} for a job that only renders grids already in memory ({@link #run(Dem, JobListener)})
     * @param product what to make
     * @param scene the stages and their settings; its light is replaced by {@code sun}'s. For {@link Product#HILLSHADE}
     *     only its hillshade method and options count, for {@link Product#TINT} only its tint, for {@link
     *     Product#SHADOWS} only its shadow algorithm and options (not NONE)
     * @param window the part of the DEM to draw, or {@code null} for all of it
     * @param size the picture's size ({@link OutputSize#FULL}: one pixel per cell); stages run at that resolution
     * @param sun the light
     * @param body the body a DEM whose file names no ellipsoid lies on (metric cell sizes, the sun by date and time)
     * @param mercatorScale how the cells of a Web Mercator DEM are measured for slopes and shadow lengths: on the
     *     ground row by row ({@link MercatorScale#GROUND}, the default) or in the projection's metres
     * @param execution threads, tile size and optionally a shared pool; the result does not depend on them
     * @param memory the most heap bytes the job's grids, layers and pictures may take at once, or 0 for half the heap's
     *     maximum ({@link #memoryBudget()}): {@link #runAndWrite} renders a picture that needs more in tiles
     *     (docs/scale.md); the result does not depend on it
     */
    public ReliefJob {
        Objects.requireNonNull(product, "product");
        Objects.requireNonNull(scene, "scene");
        Objects.requireNonNull(size, "size");
        Objects.requireNonNull(sun, "sun");
        Objects.requireNonNull(body, "body");
        Objects.requireNonNull(mercatorScale, "mercatorScale");
        Objects.requireNonNull(execution, "execution");
        if (memory < 0) {
            throw new IllegalArgumentException("a memory budget must be a number of bytes ≥ 0 (0 = half the heap),"
                    + " got " + memory);
        }
    }

    /**
     * A job that measures Web Mercator cells on the ground ({@link MercatorScale#GROUND}).
     *
     * @param input     the DEM file or files, or {@code null} for grids already in memory only
     * @param product   what to make
     * @param scene     the stages and their settings
     * @param window    the part of the DEM to draw, or {@code null} for all of it
     * @param size      the picture's size
     * @param sun       the light
     * @param body      the body a DEM whose file names no ellipsoid lies on
     * @param execution threads and tile size
     * @param memory    the memory budget in bytes, or 0 for half the heap's maximum
     */
    public ReliefJob(DemInput input, Product product, Scene scene, Window window, OutputSize size, Sun sun,
                     Body body, RenderSettings execution, long memory) {
        this(input, product, scene, window, size, sun, body, MercatorScale.GROUND, execution, memory);
    }

    /**
     * A job with the automatic memory budget (half the heap's maximum) that measures Web Mercator cells on the
     * ground.
     *
     * @param input     the DEM file or files, or {@code null} for grids already in memory only
     * @param product   what to make
     * @param scene     the stages and their settings
     * @param window    the part of the DEM to draw, or {@code null} for all of it
     * @param size      the picture's size
     * @param sun       the light
     * @param body      the body a DEM whose file names no ellipsoid lies on
     * @param execution threads and tile size
     */
    public ReliefJob(DemInput input, Product product, Scene scene, Window window, OutputSize size, Sun sun,
                     Body body, RenderSettings execution) {
        this(input, product, scene, window, size, sun, body, execution, 0);
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
                Body.EARTH, MercatorScale.GROUND, RenderSettings.defaults(), 0);
    }

    /**
     * A copy with another {@code product}.
     *
     * @param value what to make
     * @return the new job
     */
    public ReliefJob withProduct(Product value) {
        return new ReliefJob(input, value, scene, window, size, sun, body, mercatorScale, execution, memory);
    }

    /**
     * A copy with another {@code scene}.
     *
     * @param value the stages and their settings
     * @return the new job
     */
    public ReliefJob withScene(Scene value) {
        return new ReliefJob(input, product, value, window, size, sun, body, mercatorScale, execution, memory);
    }

    /**
     * A copy with another {@code window}.
     *
     * @param value the part of the DEM to draw, or {@code null} for all of it
     * @return the new job
     */
    public ReliefJob withWindow(Window value) {
        return new ReliefJob(input, product, scene, value, size, sun, body, mercatorScale, execution, memory);
    }

    /**
     * A copy with another {@code size}.
     *
     * @param value the picture's size
     * @return the new job
     */
    public ReliefJob withSize(OutputSize value) {
        return new ReliefJob(input, product, scene, window, value, sun, body, mercatorScale, execution, memory);
    }

    /**
     * A copy with another {@code sun}.
     *
     * @param value the light
     * @return the new job
     */
    public ReliefJob withSun(Sun value) {
        return new ReliefJob(input, product, scene, window, size, value, body, mercatorScale, execution, memory);
    }

    /**
     * A copy with another {@code body}.
     *
     * @param value the body a DEM whose file names no ellipsoid lies on
     * @return the new job
     */
    public ReliefJob withBody(Body value) {
        return new ReliefJob(input, product, scene, window, size, sun, value, mercatorScale, execution, memory);
    }

    /**
     * A copy with another {@code mercatorScale}: {@link MercatorScale#MAP} measures a Web Mercator DEM's cells in
     * the projection's metres, as gdaldem does, instead of on the ground.
     *
     * @param value how the cells of a Web Mercator DEM are measured
     * @return the new job
     */
    public ReliefJob withMercatorScale(MercatorScale value) {
        return new ReliefJob(input, product, scene, window, size, sun, body, value, execution, memory);
    }

    /**
     * A copy with another {@code execution}.
     *
     * @param value threads and tile size
     * @return the new job
     */
    public ReliefJob withExecution(RenderSettings value) {
        return new ReliefJob(input, product, scene, window, size, sun, body, mercatorScale, value, memory);
    }

    /**
     * A copy with another memory budget.
     *
     * @param bytes the most heap bytes the job may hold at once, or 0 for half the heap's maximum
     * @return the new job
     */
    public ReliefJob withMemory(long bytes) {
        return new ReliefJob(input, product, scene, window, size, sun, body, mercatorScale, execution, bytes);
    }

    /**
     * {@return the memory budget in bytes: {@link #memory()} when given (at most the heap's maximum), else half the
     * heap's maximum}; the readers' and encoders' buffers and the JVM's own take the rest.
     */
    public long memoryBudget() {
        long max = Runtime.getRuntime().maxMemory();
        return memory > 0 ? Math.min(memory, max) : max / 2;
    }

    /**
     * Reads what the picture needs and renders it, in memory.
     *
     * @param listener told of progress, notices, the sun used and the end of each phase
     * @return the picture
     * @throws IOException               naming the file when it cannot be read ({@link
     *                                   io.github.jdem846.io.DemFormatException})
     * @throws IllegalArgumentException  when the window lies outside the grid, or the sun cannot be placed
     * @throws InsufficientHeapException when the grid and the picture cannot fit in the heap (written to a file
     *                                   with {@link #runAndWrite}, such a picture is rendered in tiles)
     * @throws InterruptedException      when the calling thread is interrupted
     */
    public ReliefResult run(JobListener listener) throws IOException, InterruptedException {
        Objects.requireNonNull(listener, "listener");
        requireDrawable();
        Scene s = productScene();
        DemInput in = requireInput();
        try {
            Planned planned = plan(in, s, listener);
            PicturePlan plan = planned.plan();
            InsufficientHeapException.requireFits(plan.gridCells(), plan.width(), plan.height(),
                    JobMemory.of(product, s).perPixel(), Runtime.getRuntime().maxMemory());
            return renderInMemory(in, planned, s, listener);
        } catch (IOException e) {
            throw Interrupts.interruptedOr(e);
        } catch (java.io.UncheckedIOException e) {   // a draped image that cannot be read
            throw Interrupts.interruptedOr(e.getCause());
        }
    }

    /**
     * Renders the product of the whole of {@code dem}, a grid already in memory ({@link #input()} is not read):
     * the tint spans the grid's own range and no halo is needed; a Web Mercator grid is measured as {@link
     * #mercatorScale()} says, as one read from a file.
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
        Scene s = productScene();
        CellWindow whole = CellWindow.whole(dem.width(), dem.height());
        Dem measured = dem.withGeometry(mercatorScale.apply(dem.geometry()));
        requireDrapeCovers(s, measured.geometry());
        Sun.Lighting lighting = lighting(measured.geometry(), listener);
        AreaRenderer renderer = new AreaRenderer(product, s, lighting, execution);
        return result(null, dem.geometry(), renderer.render(measured, whole, 0, 0, listener), lighting, listener);
    }

    /**
     * Runs the job and writes the product to {@code file} ({@link ReliefResult#write}); an output that would
     * replace or delete a file of the input is refused before anything is read ({@link InputProtection}). A
     * picture whose grid, layers and pixels need more than the {@linkplain #memoryBudget() memory budget}, or more
     * than one Java array holds, is rendered in tiles, each read with the halo its stages need, and written band
     * of rows by band of rows; the file is the same, byte for byte (docs/scale.md). Nothing is written under
     * {@code file} unless the whole picture is.
     *
     * @param file     the image file (its extension chooses the format)
     * @param options  how to write it
     * @param listener told of progress, notices, the sun used and the end of each phase
     * @return the files written
     * @throws IOException               when the input cannot be read or the output cannot be written
     * @throws InsufficientHeapException when not even one tile and its halo fit in the memory budget
     * @throws InterruptedException      when the calling thread is interrupted
     */
    public WriteResult runAndWrite(Path file, WriteOptions options, JobListener listener)
            throws IOException, InterruptedException {
        Objects.requireNonNull(file, "file");
        Objects.requireNonNull(options, "options");
        requireDrawable();
        checkOutput(file, options);
        WriteOptions o = (product == Product.HILLSHADE || product == Product.SKY_VIEW) && options.noData() == null
                ? options.withNoData(0) : options;
        return runAndWrite((picture, rgba) -> {
            GeoReference geo = GeoReference.of(picture);
            return rgba ? ImageOutput.openRgba(file, picture.width(), picture.height(), geo, o)
                    : ImageOutput.openGray(file, picture.width(), picture.height(), geo, o);
        }, result -> result.write(file, options, listener), listener);
    }

    /**
     * Runs a {@link Product#SKY_VIEW} job and writes the factor itself, 0..1, as a float32 GeoTIFF with no-data NaN
     * (declared), georeferenced as the gray product. The grid and the values are held in memory at once (no tiles:
     * the memory budget does not apply), as {@link #run(JobListener)} holds them.
     *
     * @param file     the GeoTIFF (.tif, .tiff)
     * @param options  how to write it; its no-data value is replaced by NaN
     * @param listener told of progress, notices and the end of each phase
     * @return the files written
     * @throws IllegalArgumentException  for another product or another format than GeoTIFF
     * @throws IOException               when the input cannot be read or the output cannot be written
     * @throws InsufficientHeapException when the grid and the values cannot fit in the heap
     * @throws InterruptedException      when the calling thread is interrupted
     */
    public WriteResult runAndWriteValues(Path file, WriteOptions options, JobListener listener)
            throws IOException, InterruptedException {
        Objects.requireNonNull(file, "file");
        Objects.requireNonNull(options, "options");
        Objects.requireNonNull(listener, "listener");
        if (product != Product.SKY_VIEW) {
            throw new IllegalArgumentException("only the sky-view factor is written as float32 values, not the "
                    + stageName() + " product");
        }
        if (!isGeoTiff(file)) {
            throw new IllegalArgumentException("float32 values can only be written as GeoTIFF (.tif, .tiff), not '"
                    + file + "'");
        }
        requireDrawable();
        checkOutput(file, options);
        Scene s = productScene();
        DemInput in = requireInput();
        WriteResult written;
        try {
            Planned planned = plan(in, s, listener);
            PicturePlan plan = planned.plan();
            InsufficientHeapException.requireFits(plan.gridCells(), plan.width(), plan.height(),
                    JobMemory.of(product, s).perPixel(), Runtime.getRuntime().maxMemory());
            DemLoader.Loaded loaded = DemLoader.load(in, plan, false, planned.statistics(), listener);
            listener.phaseDone("read");
            for (String notice : loaded.info().notices()) {
                listener.notice(notice);
            }
            CellWindow area = loaded.area();
            float[] factor = new io.github.jdem846.render.Renderer(execution).skyView(loaded.dem(), s, area,
                    listener);
            listener.phaseDone(stageName());
            GridGeometry geometry = loaded.dem().geometry().window(area.col(), area.row(), area.width(),
                    area.height());
            written = ImageOutput.writeFloat(file, factor, area.width(), area.height(), GeoReference.of(geometry),
                    options.withNoData(Double.NaN));
        } catch (IOException e) {
            throw Interrupts.interruptedOr(e);
        }
        written.notices().forEach(listener::notice);
        listener.phaseDone("write");
        return written;
    }

    /**
     * {@return true when {@code file} is named as a GeoTIFF (.tif, .tiff, any case)}
     *
     * @param file the output file
     */
    public static boolean isGeoTiff(Path file) {
        Path name = file.getFileName();
        String n = name == null ? "" : name.toString().toLowerCase(Locale.ROOT);
        return n.endsWith(".tif") || n.endsWith(".tiff");
    }

    /**
     * Where and how large the picture {@link #run} or {@link #runAndWrite} would make, from the file's header (and,
     * for cast shadows, its statistics), without rendering.
     *
     * @param picture      the grid of the picture's pixels, as {@link ReliefResult#geometry()} gives it
     * @param bytes        the heap the picture takes rendered at once (its grid, layers and pixels)
     * @param fitsInMemory whether that fits the {@linkplain #memoryBudget() memory budget} and one Java array: if not,
     *                     {@link #runAndWrite} renders it in tiles
     */
    public record Footprint(GridGeometry picture, long bytes, boolean fitsInMemory) {
    }

    /**
     * Plans the picture without rendering it ({@link Footprint}).
     *
     * @return its grid and memory
     * @throws IOException          when the DEM cannot be read
     * @throws InterruptedException when the calling thread is interrupted
     */
    public Footprint footprint() throws IOException, InterruptedException {
        requireDrawable();
        Scene s = productScene();
        try {
            PicturePlan plan = plan(requireInput(), s, JobListener.NONE).plan();
            return new Footprint(plan.pictureGeometry(), inMemoryBytes(plan, s), fitsInMemory(plan, s));
        } catch (IOException e) {
            throw Interrupts.interruptedOr(e);
        }
    }

    /** Opens the image a picture of {@code picture}'s size and place is written to. */
    @FunctionalInterface
    interface SinkOpener {
        ImageSink open(GridGeometry picture, boolean rgba) throws IOException;
    }

    /** Writes a picture rendered in memory at once. */
    @FunctionalInterface
    interface ResultWriter {
        WriteResult write(ReliefResult result) throws IOException;
    }

    /**
     * {@link #runAndWrite(Path, WriteOptions, JobListener)} into any image: a picture that fits the budget is
     * rendered in memory and handed to {@code whole}, a larger one is rendered in tiles into {@code sink}.
     */
    WriteResult runAndWrite(SinkOpener sink, ResultWriter whole, JobListener listener)
            throws IOException, InterruptedException {
        return runAndWrite(sink, whole, listener, TileLayout::choose);
    }

    /** The input files; a job made without them ({@code input} null) only renders grids in memory. */
    private DemInput requireInput() {
        if (input == null) {
            throw new IllegalStateException("this job has no DEM file: make it with ReliefJob.of(path), or render a"
                    + " Dem in memory with run(dem, listener)");
        }
        return input;
    }

    /** Chooses how a picture is cut into tiles: {@link TileLayout#choose}, or smaller tiles for tests. */
    @FunctionalInterface
    interface LayoutChooser {
        /** As {@link TileLayout#choose}. */
        TileLayout choose(PicturePlan plan, int[] halo, int unit, JobMemory needs, long budget);
    }

    /** {@link #runAndWrite(SinkOpener, ResultWriter, JobListener)} with the tiles {@code layouts} chooses. */
    WriteResult runAndWrite(SinkOpener sink, ResultWriter whole, JobListener listener, LayoutChooser layouts)
            throws IOException, InterruptedException {
        Objects.requireNonNull(listener, "listener");
        requireDrawable();
        Scene s = productScene();
        WriteResult written;
        DemInput in = requireInput();
        try {
            Planned planned = plan(in, s, listener);
            if (fitsInMemory(planned.plan(), s)) {
                written = whole.write(renderInMemory(in, planned, s, listener));
            } else {
                written = renderInTiles(in, planned, s, sink, listener, layouts);
            }
        } catch (IOException e) {
            throw Interrupts.interruptedOr(e);
        } catch (java.io.UncheckedIOException e) {   // a draped image that cannot be read
            throw Interrupts.interruptedOr(e.getCause());
        }
        written.notices().forEach(listener::notice);
        listener.phaseDone("write");
        return written;
    }

    /** The plan of the picture and the file's statistics, streamed at most once, when asked for. */
    private record Planned(PicturePlan plan, DemLoader.StreamedStatistics statistics) {
    }

    /** Plans the read: the window with the halo the scene's stages need, from the file's header. */
    private Planned plan(DemInput files, Scene s, JobListener listener) throws IOException {
        DemLoader.Halo halo = s.hillshade() == null ? DemLoader.Halo.NONE : DemLoader.Halo.uniform(1);
        if (s.hasShadows()) {
            halo = halo.union(shadowHalo(s));
        }
        DemInfo read = DemReader.inspect(files).withDefaultEllipsoid(body.ellipsoid());
        DemInfo info = read.withGeometry(mercatorScale.apply(read.geometry()));
        if (s.hasAmbient() || product == Product.SKY_VIEW) {
            halo = halo.union(DemLoader.Halo.uniform(SkyView.haloCells(info.geometry(), s.skyViewOptions())));
        }
        DemLoader.StreamedStatistics statistics = new DemLoader.StreamedStatistics(files, listener);
        return new Planned(DemLoader.plan(info, body.ellipsoid(), window, size, halo, statistics), statistics);
    }

    /** True when the picture's grid, layers and pixels fit the memory budget and each fits in one Java array. */
    private boolean fitsInMemory(PicturePlan plan, Scene s) {
        long read = plan.resampled() ? (long) plan.decimatedWidth() * plan.decimatedHeight() : 0;
        return plan.fitsOneArray() && read <= PicturePlan.MAX_ARRAY && inMemoryBytes(plan, s) <= memoryBudget();
    }

    /** The heap the picture takes rendered at once: its grid (and the read it is resampled from), layers, pixels. */
    private long inMemoryBytes(PicturePlan plan, Scene s) {
        long read = plan.resampled() ? (long) plan.decimatedWidth() * plan.decimatedHeight() : 0;
        return JobMemory.of(product, s).render(JobMemory.gridBytes(plan.gridCells(), read, plan.enlarged()),
                plan.pixels());
    }

    /** Whether the scene needs the whole file's statistics: a tint's range, the cast shadows' lowest terrain. */
    private static boolean needsStatistics(Scene s) {
        return s.tint() != null || s.hasShadows();
    }

    /** Loads the picture's grid with its halo and renders it. */
    private ReliefResult renderInMemory(DemInput files, Planned planned, Scene s, JobListener listener)
            throws IOException, InterruptedException {
        DemLoader.Loaded loaded = DemLoader.load(files, planned.plan(), needsStatistics(s), planned.statistics(),
                listener);
        listener.phaseDone("read");
        for (String notice : loaded.info().notices()) {
            listener.notice(notice);
        }
        ScaleNotice.of(planned.plan().info().geometry(), s).ifPresent(listener::notice);
        Scene scene = forWholeFile(s, loaded.fileStatistics());
        CellWindow area = loaded.area();
        requireDrapeCovers(scene, planned.plan().pictureGeometry());
        Sun.Lighting lighting = lighting(planned.plan().pictureGeometry(), listener);
        AreaRenderer renderer = new AreaRenderer(product, scene, lighting, execution);
        AreaRenderer.Pixels pixels = renderer.render(loaded.dem(), area, area.col(), area.row(), listener);
        GridGeometry geometry = loaded.dem().geometry().window(area.col(), area.row(), area.width(),
                area.height());
        return result(loaded.info(), geometry, pixels, lighting, listener);
    }

    /** Renders the picture tile by tile into the sink {@code opener} opens, and commits it. */
    private WriteResult renderInTiles(DemInput files, Planned planned, Scene s, SinkOpener opener,
                                      JobListener listener, LayoutChooser layouts)
            throws IOException, InterruptedException {
        PicturePlan plan = planned.plan();
        ElevationStatistics statistics = needsStatistics(s) ? planned.statistics().get() : null;
        listener.phaseDone("read");
        List<String> notices = new ArrayList<>(plan.info().notices());
        ScaleNotice.of(plan.info().geometry(), s).ifPresent(notices::add);
        Scene scene = forWholeFile(s, statistics);
        GridGeometry picture = plan.pictureGeometry();
        requireDrapeCovers(scene, picture);
        Sun.Lighting lighting = lighting(picture, listener);
        int[] halo = TileHalo.of(plan, scene, statistics, lighting);
        int unit = sun.perTile() ? execution.tileSize() : RenderSettings.MIN_TILE_SIZE;
        AreaRenderer renderer = new AreaRenderer(product, scene, lighting, execution);
        TiledWriter tiles = TiledWriter.plan(files, plan, renderer, halo, unit, JobMemory.of(product, s),
                memoryBudget(), layouts, scene.hasShadows());
        notices.add(tiles.notice(inMemoryBytes(plan, s), memoryBudget()));
        String stage = stageName();
        try (ImageSink sink = opener.open(picture, renderer.rgba())) {
            tiles.write(sink, stage, listener, notices);
            listener.phaseDone(stage);
            return sink.commit();
        }
    }

    /** The result of a picture rendered in memory; tells the listener the product's phase ended. */
    private ReliefResult result(DemInfo source, GridGeometry geometry, AreaRenderer.Pixels pixels,
                                Sun.Lighting lighting, JobListener listener) {
        listener.phaseDone(stageName());
        SunPosition position = lighting == null ? null : lighting.sun();
        return pixels.argb() != null ? ReliefResult.rgba(this, source, geometry, pixels.argb(), position)
                : ReliefResult.gray(this, source, geometry, pixels.gray(), position);
    }

    /** Refuses a drape that cannot be placed on the picture (a relief's or a tint's), before any cell is drawn. */
    private void requireDrapeCovers(Scene s, GridGeometry picture) {
        if (s.drape() != null && (product == Product.RELIEF || product == Product.TINT)) {
            s.drape().requireCovers(picture);
        }
    }

    /** The light over the picture (null for a tint, which is not lit); the listener hears the sun by time. */
    private Sun.Lighting lighting(GridGeometry picture, JobListener listener) {
        if (product == Product.TINT) {
            return null;
        }
        Sun.Lighting lighting = sun.over(picture, body, execution.tileSize());
        if (lighting.sun() != null) {
            listener.sun(lighting.sun());
        }
        return lighting;
    }

    /** The product's phase name: "render", "hillshade", "tint" or "shadows". */
    private String stageName() {
        return product == Product.RELIEF ? "render" : product == Product.SKY_VIEW ? "skyview"
                : product.name().toLowerCase(Locale.ROOT);
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
            case HILLSHADE -> scene.withTint(null).withShadows(ShadowAlgorithm.NONE).withAmbient(0);
            case TINT -> scene.withHillshade(null).withShadows(ShadowAlgorithm.NONE).withAmbient(0);
            case SHADOWS -> scene.withTint(null).withHillshade(null).withAmbient(0);
            // an ambient weight above 0 marks the sky view as a stage (its halo, its memory), whatever it is
            case SKY_VIEW -> scene.withTint(null).withHillshade(null).withShadows(ShadowAlgorithm.NONE)
                    .withAmbient(scene.hasAmbient() ? scene.ambient() : 1);
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
     * The scene for a grid read from a file: a percent tint spans the whole file's range, and the sweep is given
     * the file's lowest elevation, so that a window, a tile or a reduced copy of the file gets the same floor as
     * the whole file ({@link ShadowOptions#terrainMinimum()}); unchanged when the statistics were not needed.
     */
    private static Scene forWholeFile(Scene s, ElevationStatistics file) {
        if (file == null) {
            return s;
        }
        Scene scene = s.withTintRange(file);
        return s.hasShadows() ? scene.withShadowOptions(s.shadowOptions().withTerrainMinimum(file.min())) : scene;
    }
}
