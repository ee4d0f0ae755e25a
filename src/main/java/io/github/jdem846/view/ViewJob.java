package io.github.jdem846.view;

import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.LoadedDem;
import io.github.jdem846.io.ReadRequest;
import io.github.jdem846.io.Window;
import io.github.jdem846.job.JobListener;
import io.github.jdem846.job.Product;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.job.ReliefResult;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.overlay.Overlay;
import io.github.jdem846.overlay.OverlayPainter;
import io.github.jdem846.output.WriteResult;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.OutputSize;
import io.github.jdem846.render.RenderedRelief;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;

/**
 * A perspective view of a DEM file, from file to pixels: the picture of {@code relief} (its product, normally the
 * relief, with its input, window, scene, sun, body and threads; its size is not used) rendered as the texture, a
 * gray product as gray, and the terrain drawn under it by
 * {@link PerspectiveRenderer}.
 *
 * <p>What the picture cannot show is not computed: the terrain is read box-averaged to at most about one cell per
 * picture pixel ({@link #meshDecimation}), and finer only near the camera, where a coarser cell would look larger
 * than a pixel, and only in the part the camera sees (levels of detail); the relief texture, cast shadows included, is rendered only for the
 * cells the camera sees, at most at about {@value #TEXTURE_PIXELS_PER_PIXEL} texture pixels per picture pixel
 * ({@link #textureSize}).
 *
 * <pre>{@code
 * RenderedView view = new ViewJob(ReliefJob.of(Path.of("dem.tif")), Camera.defaults(),
 *         ViewOptions.defaults().withExaggeration(2)).run(JobListener.NONE);
 * view.write(Path.of("view.png"), WriteOptions.defaults());
 * }</pre>
 *
 * <p>Overlays ({@link #withOverlays}) are drawn onto the relief texture before it is draped, in the texture's
 * grid (the DEM's CRS), so their lines follow the terrain; their widths and radii are in texture pixels.
 *
 * @param relief   the relief picture draped on the terrain, and the DEM it comes from
 * @param camera   where the camera stands and the picture's size
 * @param options  exaggeration, background, globe
 * @param overlays vector overlays drawn onto the relief texture, in order (empty for none)
 */
public record ViewJob(ReliefJob relief, Camera camera, ViewOptions options, List<Overlay> overlays) {

    /** Most texture pixels per picture pixel, 4. */
    public static final int TEXTURE_PIXELS_PER_PIXEL = 4;

    /**
     * Checks that the relief, camera, options and overlays are given.
     *
     * @param relief the relief picture draped on the terrain, and the DEM it comes from
     * @param camera where the camera stands and the picture's size
     * @param options exaggeration, background, globe
     * @param overlays vector overlays drawn onto the relief texture, in order (empty for none)
     */
    public ViewJob {
        Objects.requireNonNull(relief, "relief");
        Objects.requireNonNull(camera, "camera");
        Objects.requireNonNull(options, "options");
        overlays = List.copyOf(overlays);
    }

    /**
     * A view without overlays.
     *
     * @param relief the relief picture draped on the terrain, and the DEM it comes from
     * @param camera where the camera stands and the picture's size
     * @param options exaggeration, background, globe
     */
    public ViewJob(ReliefJob relief, Camera camera, ViewOptions options) {
        this(relief, camera, options, List.of());
    }

    /**
     * A copy drawing {@code value} onto the relief texture.
     *
     * @param value the overlays, in drawing order
     * @return the new job
     */
    public ViewJob withOverlays(List<Overlay> value) {
        return new ViewJob(relief, camera, options, value);
    }

    /**
     * Reads the DEM, renders its relief and draws the view.
     *
     * @param listener told of progress, notices, the sun used and the end of each phase ("terrain": the
     *                 grid of the mesh read; "read" and "render": the relief; "view")
     * @return the picture
     * @throws IOException          when the DEM cannot be read
     * @throws InterruptedException when the calling thread is interrupted
     * @throws io.github.jdem846.raster.GridRequestException when the window does not fit the grid
     * @throws IllegalArgumentException in globe mode, for a grid whose CRS gives no latitude and longitude
     */
    public RenderedView run(JobListener listener) throws IOException, InterruptedException {
        Objects.requireNonNull(listener, "listener");
        relief.requireDrawable();
        if (relief.input() == null) {
            throw new IllegalStateException("this view has no DEM file: make its relief with ReliefJob.of(path)");
        }
        DemInfo info = DemReader.inspect(relief.input());
        Window.Cells cells = relief.window() == null ? Window.cells(0, 0, info.geometry().width(),
                info.geometry().height()) : relief.window().resolve(info.geometry());
        Dem terrain = readTerrain(cells);
        listener.phaseDone("terrain");
        Window seen = visibleWindow(terrain);
        if (seen == null) {
            throw new IllegalArgumentException(camera.lookAt() != null
                    ? "the camera sees none of the terrain: it looks away from it; give a look-at point on the terrain"
                    : "the camera sees none of the terrain: it looks away from it or stands too close; step back"
                            + " with a larger distance");
        }
        Window.Cells seenCells = seen.resolve(info.geometry());
        ReliefResult picture = relief.withWindow(seen)
                .withSize(textureSize(seenCells.width(), seenCells.height(), camera)).run(listener);
        RenderedRelief texture = new RenderedRelief(picture.width(), picture.height(), argbOf(picture),
                picture.geometry());
        if (!overlays.isEmpty()) {
            texture = OverlayPainter.of(overlays, texture.geometry()).paint(texture);
        }
        RenderedView view = new PerspectiveRenderer(relief.execution()).render(terrain, fileSource(cells),
                meshDecimation(cells.width(), cells.height(), camera), texture, camera, options, listener);
        listener.phaseDone("view");
        return view;
    }

    /**
     * Runs the job and writes the picture to {@code file}, all or nothing; an output that would replace a file of
     * the input is refused first.
     *
     * @param file     the image file (.png, or .tif for an RGBA TIFF without georeferencing)
     * @param options  how to write it (no sidecars: a perspective view has no place on the ground)
     * @param listener told of progress, notices and phases
     * @return the files written
     * @throws IOException          when the input cannot be read or the output cannot be written
     * @throws InterruptedException when the calling thread is interrupted
     */
    public WriteResult runAndWrite(Path file, WriteOptions options, JobListener listener)
            throws IOException, InterruptedException {
        Objects.requireNonNull(file, "file");
        Objects.requireNonNull(options, "options");
        WriteOptions noSidecars = options.withSidecars(WriteOptions.Sidecars.NONE);
        relief.checkOutput(file, noSidecars);
        RenderedView view = run(listener);
        WriteResult written = view.write(file, noSidecars);
        written.notices().forEach(listener::notice);
        listener.phaseDone("write");
        return written;
    }

    /**
     * The picture's pixels as ARGB: a gray product (a hillshade, a shadow mask) becomes opaque gray, a hillshade's
     * 0 (no-data) transparent.
     */
    private static int[] argbOf(ReliefResult picture) {
        if (picture.argb() != null) {
            return picture.argb();
        }
        byte[] gray = picture.gray();
        boolean zeroIsNoData = picture.job().product() == Product.HILLSHADE;
        int[] argb = new int[gray.length];
        for (int i = 0; i < gray.length; i++) {
            int v = gray[i] & 255;
            argb[i] = zeroIsNoData && v == 0 ? 0 : 0xFF000000 | v << 16 | v << 8 | v;
        }
        return argb;
    }

    /**
     * The part of the file the camera sees, as a world window: the cells it sees and half a cell around, so that
     * the relief (and its cast shadows) is rendered only there; shadows cast from outside still fall into it,
     * since the relief reads the halo its stages need.
     */
    private Window visibleWindow(Dem terrain) {
        int[] box = PerspectiveRenderer.visibleCells(terrain, camera, options);
        if (box == null) {
            return null;
        }
        GridGeometry g = terrain.geometry();
        double west = g.originX() + box[0] * g.cellWidth();
        double east = g.originX() + (box[2] + 2) * g.cellWidth();
        double north = g.originY() - box[1] * g.cellHeight();
        double south = g.originY() - (box[3] + 2) * g.cellHeight();
        return Window.world(west, south, east, north);
    }

    /** The terrain: the window, box-averaged to about one cell per picture pixel, measured as the relief is. */
    private Dem readTerrain(Window.Cells cells) throws IOException {
        return read(cells, meshDecimation(cells.width(), cells.height(), camera));
    }

    /** The window's cells at any resolution, for the levels of detail. */
    private TerrainSource fileSource(Window.Cells cells) {
        return new TerrainSource() {
            @Override
            public int width() {
                return cells.width();
            }

            @Override
            public int height() {
                return cells.height();
            }

            @Override
            public Dem read(int col, int row, int w, int h, int factor) throws IOException {
                return ViewJob.this.read(Window.cells(cells.col() + col, cells.row() + row, w, h), factor);
            }
        };
    }

    /** Cells of the file box-averaged by {@code factor}, measured as the relief is. */
    private Dem read(Window window, int factor) throws IOException {
        LoadedDem loaded = DemReader.load(relief.input(), new ReadRequest(window, factor));
        Dem dem = loaded.dem();
        GridGeometry g = relief.mercatorScale().apply(dem.geometry().withDefaultEllipsoid(
                relief.body().ellipsoid()));
        return dem.withGeometry(g);
    }

    /**
     * The box-averaging factor of the terrain: 1 while the window has at most about as many cells as the picture
     * has pixels, else the smallest that brings it there.
     *
     * @param cols   the window's columns
     * @param rows   the window's rows
     * @param camera the picture's size
     * @return the factor, ≥ 1
     */
    public static int meshDecimation(int cols, int rows, Camera camera) {
        double ratio = (double) cols * rows / ((double) camera.width() * camera.height());
        return Math.max(1, (int) Math.ceil(Math.sqrt(ratio)));
    }

    /**
     * The relief texture's size: the window's full resolution while it has between one cell per picture pixel and
     * {@value #TEXTURE_PIXELS_PER_PIXEL}; scaled down to {@value #TEXTURE_PIXELS_PER_PIXEL} texture pixels per
     * picture pixel for a larger window; for a smaller one, resampled up to about one texture pixel per picture
     * pixel (at most {@value #MAX_UPSAMPLING} × per side), so that hillshade and shadows are not drawn as blocks.
     *
     * @param cols   the window's columns
     * @param rows   the window's rows
     * @param camera the picture's size
     * @return the size
     */
    public static OutputSize textureSize(int cols, int rows, Camera camera) {
        double cellsPerPixel = (double) cols * rows / ((double) camera.width() * camera.height());
        if (cellsPerPixel > TEXTURE_PIXELS_PER_PIXEL) {
            return OutputSize.scale(Math.sqrt(TEXTURE_PIXELS_PER_PIXEL / cellsPerPixel));
        }
        return cellsPerPixel >= 1 ? OutputSize.FULL
                : OutputSize.scale(Math.min(MAX_UPSAMPLING, Math.sqrt(1 / cellsPerPixel)));
    }

    /** Most a small window's relief is enlarged, per side: 4 times. */
    public static final int MAX_UPSAMPLING = 4;
}
