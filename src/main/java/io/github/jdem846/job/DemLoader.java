package io.github.jdem846.job;

import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.LoadedDem;
import io.github.jdem846.io.ReadRequest;
import io.github.jdem846.io.Window;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.DemResampler;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.OutputSize;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.shadow.CellWindow;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;

/**
 * Reads exactly the part of a DEM file a picture needs: the window (or the whole grid) plus a halo of cells that
 * the stages read around it, at the output resolution. Shrinking reads a decimated grid (box average, only the
 * blocks needed are decoded) and finishes with an area-weighted resample to the exact size, so no stage ever runs
 * at full resolution for a smaller picture; a larger picture reads the cells it covers and enlarges them with a
 * smooth interpolation ({@link DemResampler#DEFAULT_UPSAMPLING}), with anti-aliased no-data edges. The read is
 * planned from the header first ({@link #plan}); the grid planned is then loaded whole ({@link #load(DemInput,
 * PicturePlan, boolean, FileStatistics)}) or piece by piece for a picture rendered in tiles ({@link #loadRegion}),
 * with the same values.
 */
final class DemLoader {

    /** The elevation statistics of a whole file, streamed on the first call and kept for the others. */
    @FunctionalInterface
    public interface FileStatistics {
        /** Min, max and valid count of the whole file at full resolution. */
        ElevationStatistics get() throws IOException;
    }

    /** Cells of halo a stage needs around the output window, in DEM cells. */
    @FunctionalInterface
    public interface Halo {
        /**
         * The halo in source cells on each side: {west, north, east, south}.
         *
         * @param statistics the whole file's elevation statistics, streamed only if asked for (once per load)
         * @param info       the file's header
         * @param window     the cells of the output window
         */
        int[] cells(FileStatistics statistics, DemInfo info, Window.Cells window) throws IOException;

        /** No halo. */
        Halo NONE = (statistics, info, window) -> new int[4];

        /** The same number of cells on every side. */
        static Halo uniform(int cells) {
            return (statistics, info, window) -> new int[] {cells, cells, cells, cells};
        }

        /**
         * The halo a windowed render with cast shadows must read toward the sun ({@link
         * io.github.jdem846.shadow.ShadowHalo}); the file's maximum is streamed once, only when a window is given.
         */
        static Halo shadows(io.github.jdem846.light.LightDirection light,
                            io.github.jdem846.shadow.ShadowOptions options) {
            return ShadowHaloSource.of(light, options);
        }

        /** The larger of this halo and {@code other} on each side. */
        default Halo union(Halo other) {
            return (statistics, info, window) -> {
                int[] a = cells(statistics, info, window);
                int[] b = other.cells(statistics, info, window);
                return new int[] {Math.max(a[0], b[0]), Math.max(a[1], b[1]), Math.max(a[2], b[2]),
                    Math.max(a[3], b[3])};
            };
        }
    }

    /**
     * The loaded grid with its halo, and where the output window sits inside it.
     *
     * @param info    the file's header
     * @param dem     the grid at output resolution, halo included
     * @param col     first column of the output window within {@code dem}
     * @param row     first row of the output window within {@code dem}
     * @param width   output width in pixels
     * @param height  output height in pixels
     * @param fileStatistics elevation range of the whole file at full resolution (so that percent tints of a
     *                       window or a reduced picture match the full picture), or {@code null} when not asked for
     */
    public record Loaded(DemInfo info, Dem dem, int col, int row, int width, int height,
                         ElevationStatistics fileStatistics) {

        /** @return the output window's cells within {@code dem} */
        public CellWindow area() {
            return new CellWindow(col, row, width, height);
        }

        /** @return true when the grid holds nothing but the output window */
        public boolean hasNoHalo() {
            return col == 0 && row == 0 && width == dem.width() && height == dem.height();
        }

        /** @return the output window of the grid itself */
        public Dem windowDem() {
            return hasNoHalo() ? dem : dem.crop(col, row, width, height);
        }
    }

    /**
     * Cells read around the window of an enlarged picture: the interpolation's two on either side and one for the
     * stages' own halo of one pixel, so that the window's pixels are those of the whole file's picture.
     */
    static final int ENLARGEMENT_HALO = 3;

    private DemLoader() {
    }

    /**
     * Loads {@code file} for a picture of {@code window} (null = the whole grid) at {@code size}, with {@code halo}.
     *
     * @param fileStatistics also give the whole file's elevation range (taken during the read when it covers the
     *                       whole file, decimated or not; otherwise streamed in a pass of its own, without holding
     *                       the grid)
     */
    public static Loaded load(Path file, Window window, OutputSize size, Halo halo, boolean fileStatistics)
            throws IOException {
        return load(file, window, size, halo, fileStatistics, Ellipsoid.WGS84);
    }

    /**
     * As {@link #load(Path, Window, OutputSize, Halo, boolean)}, on {@code body} when the file names no ellipsoid
     * ({@link io.github.jdem846.raster.GridGeometry#withDefaultEllipsoid(Ellipsoid)}): metric cell sizes of a
     * geographic grid, halos and the curvature radius then follow the body.
     */
    public static Loaded load(Path file, Window window, OutputSize size, Halo halo, boolean fileStatistics,
                              Ellipsoid body) throws IOException {
        return load(file, window, size, halo, fileStatistics, body, 0);
    }

    /**
     * As {@link #load(Path, Window, OutputSize, Halo, boolean, Ellipsoid)}, for a caller that will also hold
     * {@code bytesPerPixel} per output pixel (e.g. 4 for an ARGB picture). Once the header is read, and before any
     * cell is, the load is refused when the grid at output resolution and that picture cannot fit in the Java heap
     * even when it is empty.
     *
     * @throws io.github.jdem846.raster.GridRequestException when the window or the size do not fit the grid
     * @throws InsufficientHeapException                      when the grid and the picture exceed the heap's maximum
     */
    public static Loaded load(Path file, Window window, OutputSize size, Halo halo, boolean fileStatistics,
                              Ellipsoid body, int bytesPerPixel) throws IOException {
        return load(DemInput.of(file), window, size, halo, fileStatistics, body, bytesPerPixel);
    }

    /** As {@link #load(Path, Window, OutputSize, Halo, boolean, Ellipsoid, int)} for one file or a mosaic. */
    public static Loaded load(DemInput file, Window window, OutputSize size, Halo halo, boolean fileStatistics,
                              Ellipsoid body, int bytesPerPixel) throws IOException {
        Objects.requireNonNull(body, "body");
        DemInfo info = DemReader.inspect(file).withDefaultEllipsoid(body);
        StreamedStatistics streamed = new StreamedStatistics(file, RenderProgress.NONE);
        PicturePlan plan = plan(info, body, window, size, halo, streamed);
        long maxHeap = Runtime.getRuntime().maxMemory();
        InsufficientHeapException.requireFits(plan.gridCells(), plan.width(), plan.height(), bytesPerPixel, maxHeap);
        return load(file, plan, fileStatistics, streamed, RenderProgress.NONE);
    }

    /**
     * Plans the picture of {@code window} (null = the whole grid) at {@code size} with {@code halo}, from the
     * header alone (the halo may stream the file's statistics through {@code statistics}).
     *
     * @param info the file's header, on {@code body}
     * @throws io.github.jdem846.raster.GridRequestException when the window or the size do not fit the grid
     */
    static PicturePlan plan(DemInfo info, Ellipsoid body, Window window, OutputSize size, Halo halo,
                            FileStatistics statistics) throws IOException {
        Objects.requireNonNull(size, "size");
        Objects.requireNonNull(halo, "halo");
        Window.Cells win = window == null ? Window.cells(0, 0, info.width(), info.height())
                : window.resolve(info.geometry());
        int[] px = size.pixelsFor(win.width(), win.height());
        double fx = (double) win.width() / px[0];
        double fy = (double) win.height() / px[1];
        int[] h = halo.cells(statistics, info, win).clone();
        if (fx < 1 && fy < 1) {
            // an enlargement interpolates from two cells on either side, and its stages read one pixel further
            for (int i = 0; i < 4; i++) {
                h[i] = Math.max(h[i], ENLARGEMENT_HALO);
            }
        }
        // Halo in source cells, rounded up to whole output pixels so the window keeps pixel-aligned edges.
        int west = haloCells(h[0], fx, win.col());
        int north = haloCells(h[1], fy, win.row());
        int east = haloCells(h[2], fx, info.width() - win.col() - win.width());
        int south = haloCells(h[3], fy, info.height() - win.row() - win.height());
        Window.Cells read = Window.cells(win.col() - west, win.row() - north, win.width() + west + east,
                win.height() + north + south);
        // (saturated at the int range: a grid larger than one Java array is rendered in tiles or refused)
        int outW = (int) Math.min(Integer.MAX_VALUE, Math.max(1, Math.round(read.width() / fx)));
        int outH = (int) Math.min(Integer.MAX_VALUE, Math.max(1, Math.round(read.height() / fy)));
        int decimation = (int) Math.max(1, Math.floor(Math.min(fx, fy) + 1e-9));
        int col = (int) Math.round(west / fx);
        int row = (int) Math.round(north / fy);
        int w = Math.min(px[0], outW - col);
        int hgt = Math.min(px[1], outH - row);
        return new PicturePlan(info, body, win, read, decimation, outW, outH, new CellWindow(col, row, w, hgt));
    }

    /**
     * Loads the grid {@code plan} describes.
     *
     * @param fileStatistics also give the whole file's elevation range (taken during the read when it covers the
     *                       whole file, decimated or not; otherwise from {@code streamed}, in a pass of its own
     *                       without holding the grid, if it has not streamed them yet)
     * @param progress       told of the rows read ({@link DemReader#load(DemInput, ReadRequest, RenderProgress)})
     */
    static Loaded load(DemInput file, PicturePlan plan, boolean fileStatistics, FileStatistics streamed,
                       RenderProgress progress) throws IOException {
        Window.Cells read = plan.read();
        DemInfo info = plan.info();
        LoadedDem loaded = DemReader.load(file, new ReadRequest(read, plan.decimation()), progress);
        Dem read0 = loaded.dem();
        Dem onBody = read0.withGeometry(plan.measured(read0.geometry().withDefaultEllipsoid(plan.body())));
        Dem dem = DemResampler.resample(onBody, plan.gridWidth(), plan.gridHeight());
        ElevationStatistics stats = null;
        if (fileStatistics) {
            // a read of the whole file, decimated or not, took the file's range on the way
            boolean wholeFile = read.width() == info.width() && read.height() == info.height();
            stats = wholeFile ? loaded.sourceStatistics() : streamed.get();
        }
        CellWindow a = plan.area();
        return new Loaded(loaded.info().withDefaultEllipsoid(plan.body()), dem, a.col(), a.row(), a.width(),
                a.height(), stats);
    }

    /**
     * The cells {@code region} of the grid {@code plan} describes (its coordinates: halo included), read from the
     * file without the rest: the same values, bit for bit, as those cells of {@link #load}'s grid. A decimated
     * read starts on a whole block of the plan's read, so the block means are the same; a resampled grid is
     * resampled from the part of the decimated read that region needs ({@link DemResampler#resampleRegion}). The
     * grid's geometry is {@code plan.gridGeometry().window(region)}.
     */
    static LoadedDem loadRegion(DemInput file, PicturePlan plan, CellWindow region) throws IOException {
        Window.Cells read = plan.read();
        int d = plan.decimation();
        GridGeometry geometry = plan.gridGeometry().window(region.col(), region.row(), region.width(),
                region.height());
        if (!plan.resampled()) {
            // whole blocks of the plan's read (the last one may be partial, as in the whole read)
            int c0 = read.col() + region.col() * d;
            int r0 = read.row() + region.row() * d;
            int c1 = (int) Math.min(read.col() + (long) read.width(), read.col() + (long) region.colEnd() * d);
            int r1 = (int) Math.min(read.row() + (long) read.height(), read.row() + (long) region.rowEnd() * d);
            LoadedDem part = DemReader.load(file, new ReadRequest(Window.cells(c0, r0, c1 - c0, r1 - r0), d));
            return new LoadedDem(part.info(), part.dem().withGeometry(geometry), part.sourceStatistics());
        }
        int[] cols = DemResampler.sourceSpan(plan.decimatedWidth(), plan.gridWidth(), region.col(),
                region.width());
        int[] rows = DemResampler.sourceSpan(plan.decimatedHeight(), plan.gridHeight(), region.row(),
                region.height());
        int c0 = read.col() + cols[0] * d;
        int r0 = read.row() + rows[0] * d;
        int c1 = (int) Math.min(read.col() + (long) read.width(), read.col() + (long) cols[1] * d);
        int r1 = (int) Math.min(read.row() + (long) read.height(), read.row() + (long) rows[1] * d);
        LoadedDem read0 = DemReader.load(file, new ReadRequest(Window.cells(c0, r0, c1 - c0, r1 - r0), d));
        Dem part = read0.dem();
        Dem resampled = DemResampler.resampleRegion(part, cols[0], rows[0], plan.decimatedWidth(),
                plan.decimatedHeight(), plan.gridWidth(), plan.gridHeight(), region.col(), region.row(),
                region.width(), region.height(), geometry, DemResampler.DEFAULT_UPSAMPLING);
        return new LoadedDem(read0.info(), resampled, read0.sourceStatistics());
    }

    /** {@link FileStatistics} of one file: streamed at most once. */
    static final class StreamedStatistics implements FileStatistics {
        private final DemInput file;
        private final RenderProgress progress;
        private ElevationStatistics statistics;

        /** @param progress told of the rows streamed ({@link DemReader#statistics(DemInput, RenderProgress)}) */
        StreamedStatistics(DemInput file, RenderProgress progress) {
            this.file = file;
            this.progress = progress;
        }

        @Override
        public ElevationStatistics get() throws IOException {
            if (statistics == null) {
                statistics = DemReader.statistics(file, progress);
            }
            return statistics;
        }
    }

    /** Halo cells on one side: whole output pixels' worth, at most what the grid has on that side. */
    private static int haloCells(int cells, double factor, int available) {
        if (cells <= 0 || available <= 0) {
            return 0;
        }
        long pixels = (long) Math.ceil(cells / factor);
        long source = (long) Math.ceil(pixels * factor);
        // keep whole pixels: step down by whole pixels when the grid edge is nearer
        while (source > available && pixels > 0) {
            pixels--;
            source = Math.round(pixels * factor);
        }
        return (int) Math.max(0, Math.min(available, source));
    }
}
