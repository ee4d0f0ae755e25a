package io.github.jdem846.io;

import io.github.jdem846.io.esri.BilFormat;
import io.github.jdem846.io.esri.EsriAsciiSource;
import io.github.jdem846.io.esri.GridFloatFormat;
import io.github.jdem846.io.geotiff.GeoTiffSource;
import io.github.jdem846.io.mosaic.MosaicPlanner;
import io.github.jdem846.io.mosaic.MosaicSource;
import io.github.jdem846.io.mosaic.VrtReader;
import io.github.jdem846.io.source.BlockReader;
import io.github.jdem846.io.source.HgtFormat;
import io.github.jdem846.io.source.MemoryGuard;
import io.github.jdem846.io.source.RasterSource;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.StageProgress;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;

/**
 * The one entry point for reading DEM files: GeoTIFF, ESRI GridFloat, ESRI ASCII grid, ESRI BIL and SRTM HGT,
 * recognised from their content and extension. A read may be limited to a window and decimated by box
 * averaging; only the part of the file needed is decoded where the format allows (TIFF strips/tiles, raw rows).
 *
 * <p>Several files ({@link DemInput} of more than one file) or a GDAL {@code .vrt} are read as one grid, a mosaic:
 * the files must share one CRS, one cell size and one grid; cells no file covers are no-data; overlapping cells
 * are the mean of the files' valid values (a list) or the last source's valid value (a VRT, as in GDAL). A read
 * opens only the files its window touches (docs/formats.md, "Mosaics").
 *
 * <p>Every failure is a {@link DemFormatException} whose message names the file and the problem. A grid, or a
 * read buffer, that would not fit in the heap is refused before its array is allocated; a FIFO or device is
 * refused before anything opens it (a read could block forever).
 */
public final class DemReader {

    private DemReader() {
    }

    /**
     * Reads the whole file at full resolution.
     *
     * @param file the DEM file (a {@code .hdr} stands for its data file)
     * @return the grid, no-data as NaN
     * @throws IOException naming the file when it cannot be read ({@link DemFormatException})
     */
    public static Dem read(Path file) throws IOException {
        return read(file, ReadRequest.FULL);
    }

    /**
     * Reads the window and decimation of {@code request}.
     *
     * @param file    the DEM file
     * @param request the window, the decimation and the memory limit
     * @return the grid read
     * @throws IOException              naming the file when it cannot be read
     * @throws IllegalArgumentException when the window lies outside the grid (the message gives its size)
     */
    public static Dem read(Path file, ReadRequest request) throws IOException {
        return load(file, request).dem();
    }

    /**
     * Reads the window and decimation of {@code request} of one file or a mosaic.
     *
     * @param input   the DEM file or files
     * @param request the window, the decimation and the memory limit
     * @return the grid read, no-data as NaN
     * @throws IOException              naming the file when it cannot be read
     * @throws IllegalArgumentException when the window lies outside the grid (the message gives its size)
     */
    public static Dem read(DemInput input, ReadRequest request) throws IOException {
        return load(input, request).dem();
    }

    /**
     * Reads like {@link #read(Path, ReadRequest)} and also returns the file's header information.
     *
     * @param file    the DEM file
     * @param request the window, the decimation and the memory limit
     * @return the grid with the header and the statistics of the cells read
     * @throws IOException naming the file when it cannot be read
     */
    public static LoadedDem load(Path file, ReadRequest request) throws IOException {
        return load(DemInput.of(file), request);
    }

    /**
     * Reads like {@link #load(Path, ReadRequest)} from one file or a mosaic of several.
     *
     * @param input   the DEM file or files
     * @param request the window, the decimation and the memory limit
     * @return the grid with the header and the statistics of the cells read
     * @throws IOException naming the file when it cannot be read
     */
    public static LoadedDem load(DemInput input, ReadRequest request) throws IOException {
        return load(input, request, RenderProgress.NONE);
    }

    /**
     * {@link #load(DemInput, ReadRequest)}, telling {@code progress} the rows of the grid read (stage
     * {@value RenderProgress#READ}, rows at the read's resolution, ending at the grid's height).
     *
     * @param input    the DEM file or files
     * @param request  the window, the decimation and the memory limit
     * @param progress told of the rows read, from the reading threads
     * @return the grid with the header and the statistics of the cells read
     * @throws IOException naming the file when it cannot be read
     */
    public static LoadedDem load(DemInput input, ReadRequest request, RenderProgress progress) throws IOException {
        return load(input, request, Runtime.getRuntime().availableProcessors(), MIN_CELLS_PER_PART, progress);
    }

    /** Fewest cells for a separately read part: below this, opening another reader costs more than it saves. */
    static final long MIN_CELLS_PER_PART = 1L << 21;

    /**
     * Reads like {@link #load(Path, ReadRequest)}, in up to {@code parallelism} row bands at once when the format
     * decodes rows independently ({@link RasterSource#readsRowsIndependently}), each band through its own reader
     * and with at least {@code minCellsPerPart} cells. The bands start at multiples of the decimation (and of the
     * format's row block), so the result is the same as one sequential read.
     */
    static LoadedDem load(Path file, ReadRequest request, int parallelism, long minCellsPerPart)
            throws IOException {
        return load(DemInput.of(file), request, parallelism, minCellsPerPart);
    }

    static LoadedDem load(DemInput input, ReadRequest request, int parallelism, long minCellsPerPart)
            throws IOException {
        return load(input, request, parallelism, minCellsPerPart, RenderProgress.NONE);
    }

    private static LoadedDem load(DemInput input, ReadRequest request, int parallelism, long minCellsPerPart,
                                  RenderProgress progress) throws IOException {
        Objects.requireNonNull(request, "request");
        Objects.requireNonNull(progress, "progress");
        Path file = input.first();
        try (RasterSource source = open(input)) {
            DemInfo info = source.info();
            Window.Cells cells = request.window() == null
                    ? new Window.Cells(0, 0, info.width(), info.height())
                    : request.window().resolve(info.geometry());
            int d = request.decimation();
            int outW = BlockReader.outputSize(cells.width(), d);
            int outH = BlockReader.outputSize(cells.height(), d);
            String advice = "read a window or a decimated version, or give Java more heap with -Xmx";
            // the grid alone, then its read buffer alone, then both with the strips or tiles decoded at once
            MemoryGuard.requireFits(file, outW, outH, 0, request.memoryLimit(), advice);
            requireBandFits(file, source, cells, d);
            MemoryGuard.requireFits(file, outW, outH, BlockReader.bandBytes(source, cells, d), request.memoryLimit(),
                    advice);
            float[] values = new float[outW * outH];
            double noData = info.noDataOrNaN();
            StageProgress rows = new StageProgress(progress, RenderProgress.READ, outH).start();
            // at full resolution each band is decoded straight into the grid
            ElevationStatistics stats = readInParts(input, source, cells, d, parallelism, minCellsPerPart,
                    (src, part, outRow0) -> d == 1
                            ? BlockReader.readInto(src, part, noData, values, outRow0 * outW, rows::add)
                            : BlockReader.read(src, part, d, noData, (row, v) -> {
                                System.arraycopy(v, 0, values, (outRow0 + row) * outW, outW);
                                rows.add(1);
                            }));
            rows.finish();
            GridGeometry g = info.geometry().window(cells.col(), cells.row(), cells.width(), cells.height());
            if (d > 1) {
                g = g.decimate(d, d);
            }
            // at full resolution the window's statistics are those of the grid itself: no second pass later
            Dem dem = d == 1 ? Dem.ofNormalized(values, g, noData, stats) : Dem.ofNormalized(values, g, noData);
            return new LoadedDem(source.info(), dem, stats); // with notices learned while reading
        }
    }

    /** Reads one row band of a window; its output rows start at {@code outRow0}. */
    @FunctionalInterface
    private interface PartReader {
        ElevationStatistics read(RasterSource source, Window.Cells part, int outRow0) throws IOException;
    }

    /**
     * Reads {@code cells} at decimation {@code d} in up to {@code parallelism} row bands at once when the format
     * decodes rows independently, each of at least {@code minCellsPerPart} cells and starting at a multiple of the
     * decimation and of the format's row block; fewer bands when their buffers would not fit in the heap that is
     * left.
     */
    private static ElevationStatistics readInParts(DemInput input, RasterSource source, Window.Cells cells, int d,
                                                   int parallelism, long minCellsPerPart, PartReader reader)
            throws IOException {
        int unit = d * Math.max(1, source.naturalRowBlock()) / gcd(d, Math.max(1, source.naturalRowBlock()));
        long units = (cells.height() + unit - 1) / unit;
        long byCells = (long) cells.width() * cells.height() / Math.max(1, minCellsPerPart);
        int parts = source.readsRowsIndependently()
                ? (int) Math.max(1, Math.min(Math.min(parallelism, units), byCells)) : 1;
        long bandBytes = BlockReader.bandBytes(source, cells, d);
        // Each part holds a band buffer of its own: read with fewer parts rather than run out of heap.
        while (parts > 1 && !MemoryGuard.fits(0, 0, MemoryGuard.saturatedMultiply(bandBytes, parts))) {
            parts--;
        }
        if (parts == 1) {
            return reader.read(source, cells, 0);
        }
        return readParts(input, source, cells, d, parts, (int) ((units + parts - 1) / parts) * unit, reader);
    }

    /**
     * Reads {@code cells} in bands of {@code rowsPerPart} rows at once: the first through {@code first} on the
     * calling thread, the others each through a reader of its own on a thread of its own.
     */
    private static ElevationStatistics readParts(DemInput input, RasterSource first, Window.Cells cells, int d,
                                                 int parts, int rowsPerPart, PartReader reader)
            throws IOException {
        java.util.List<Thread> threads = new java.util.concurrent.CopyOnWriteArrayList<>();
        java.util.concurrent.ExecutorService pool = java.util.concurrent.Executors.newFixedThreadPool(parts - 1,
                r -> {
                    Thread t = new Thread(r, "jdem846-read");
                    t.setDaemon(true);
                    threads.add(t);
                    return t;
                });
        try {
            java.util.List<java.util.concurrent.Future<ElevationStatistics>> others = new java.util.ArrayList<>();
            for (int p = 1; p < parts; p++) {
                int row0 = p * rowsPerPart;
                if (row0 >= cells.height()) {
                    break;
                }
                Window.Cells part = new Window.Cells(cells.col(), cells.row() + row0, cells.width(),
                        Math.min(rowsPerPart, cells.height() - row0));
                others.add(pool.submit(() -> {
                    try (RasterSource own = reopen(first, input)) {
                        return reader.read(own, part, row0 / d);
                    }
                }));
            }
            ElevationStatistics stats = reader.read(first, new Window.Cells(cells.col(), cells.row(),
                    cells.width(), Math.min(rowsPerPart, cells.height())), 0);
            for (java.util.concurrent.Future<ElevationStatistics> f : others) {
                stats = stats.merge(f.get());
            }
            return stats;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new java.io.InterruptedIOException("reading " + input + " was interrupted");
        } catch (java.util.concurrent.ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof IOException io) {
                throw io;
            }
            if (cause instanceof RuntimeException re) {
                throw re;
            }
            throw new IllegalStateException(cause);
        } finally {
            pool.shutdownNow();
            joinQuietly(threads);
        }
    }

    /**
     * Waits until the reading threads have ended (the pool's shutdown interrupts them, which stops their channel
     * reads at once), so that no thread of a read outlives the call; keeps the caller's interrupt status.
     */
    private static void joinQuietly(java.util.List<Thread> threads) {
        boolean interrupted = false;
        for (Thread t : threads) {
            while (t.isAlive()) {
                try {
                    t.join();
                } catch (InterruptedException e) {
                    interrupted = true;
                }
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * Refuses a read whose band buffer would not fit, before it is allocated: a file of huge strips or tiles (or
     * a corrupt one declaring them).
     */
    private static void requireBandFits(Path file, RasterSource source, Window.Cells cells, int d)
            throws DemFormatException {
        MemoryGuard.requireBandFits(file, cells.width(), BlockReader.bandRows(source, cells, d), "read a window,"
                + " or give Java more heap with -Xmx; for a file of huge strips, re-tile it, e.g. gdal_translate -co"
                + " TILED=YES in.tif out.tif");
    }

    private static int gcd(int a, int b) {
        return b == 0 ? a : gcd(b, a % b);
    }

    /**
     * The existing files a read of {@code file} opens: the data file first, then its header and {@code .prj} for
     * the ESRI formats; for a {@code .vrt}, the VRT and then those of each of its sources. An output must not be
     * written over any of them; see
     * {@link io.github.jdem846.output.InputProtection}.
     *
     * @param file the DEM file
     * @return the data file, then its sidecars that exist
     * @throws DemFormatException when {@code file} is missing or not a DEM this program reads
     * @throws IOException        when the file cannot be examined
     */
    public static java.util.List<Path> filesOf(Path file) throws IOException {
        return InputFiles.of(Objects.requireNonNull(file, "file"));
    }

    /**
     * The existing files a read of {@code input} opens: {@link #filesOf(Path)} of each of its files.
     *
     * @param input the DEM file or files
     * @return the data files and their sidecars that exist, without repeats
     * @throws DemFormatException when a file is missing or not a DEM this program reads
     * @throws IOException        when a file cannot be examined
     */
    public static java.util.List<Path> filesOf(DemInput input) throws IOException {
        java.util.LinkedHashSet<Path> files = new java.util.LinkedHashSet<>();
        for (Path file : input.files()) {
            files.addAll(filesOf(file));
        }
        return java.util.List.copyOf(files);
    }

    /**
     * Reads the header only.
     *
     * @param file the DEM file
     * @return format, size, data type, georeferencing, CRS and declared no-data
     * @throws IOException naming the file when it cannot be read
     */
    public static DemInfo inspect(Path file) throws IOException {
        return inspect(DemInput.of(file));
    }

    /**
     * Reads the header of one file or of a mosaic.
     *
     * @param input the DEM file or files
     * @return format, size, data type, georeferencing, CRS and declared no-data
     * @throws IOException naming the file when it cannot be read
     */
    public static DemInfo inspect(DemInput input) throws IOException {
        try (RasterSource source = open(input)) {
            return source.info();
        }
    }

    /**
     * Min, max and valid count of the whole file, streamed band by band without holding the grid in memory (so
     * it works for grids larger than the heap), in row bands read at once as {@link #load} reads them.
     *
     * @param file the DEM file
     * @return the statistics of every valid cell at full resolution
     * @throws IOException naming the file when it cannot be read
     */
    public static ElevationStatistics statistics(Path file) throws IOException {
        return statistics(DemInput.of(file));
    }

    /**
     * {@link #statistics(Path)} of one file or of a mosaic.
     *
     * @param input the DEM file or files
     * @return the statistics of every valid cell at full resolution
     * @throws IOException naming the file when it cannot be read
     */
    public static ElevationStatistics statistics(DemInput input) throws IOException {
        return statistics(input, RenderProgress.NONE);
    }

    /**
     * {@link #statistics(DemInput)}, telling {@code progress} the rows streamed (stage
     * {@value RenderProgress#STATISTICS}, ending at the grid's height).
     *
     * @param input    the DEM file or files
     * @param progress told of the rows streamed, from the reading threads
     * @return the statistics of every valid cell at full resolution
     * @throws IOException naming the file when it cannot be read
     */
    public static ElevationStatistics statistics(DemInput input, RenderProgress progress) throws IOException {
        return statistics(input, null, Runtime.getRuntime().availableProcessors(), MIN_CELLS_PER_PART,
                Objects.requireNonNull(progress, "progress"));
    }

    /** {@link #statistics(Path)} in up to {@code parallelism} bands of at least {@code minCellsPerPart} cells. */
    static ElevationStatistics statistics(Path file, int parallelism, long minCellsPerPart) throws IOException {
        return statistics(DemInput.of(file), parallelism, minCellsPerPart);
    }

    /**
     * {@link #statistics(DemInput)} of the cells of {@code window} only: one part of a range measured in parts
     * (the parts' statistics {@link ElevationStatistics#merge merged} are those of the whole).
     *
     * @param input  the DEM file or files
     * @param window cells of the grid, inside it
     * @return the statistics of the window's valid cells at full resolution
     * @throws IOException              naming the file when it cannot be read
     * @throws IllegalArgumentException when the window does not lie inside the grid
     */
    public static ElevationStatistics statistics(DemInput input, Window.Cells window) throws IOException {
        Objects.requireNonNull(window, "window");
        return statistics(input, window, Runtime.getRuntime().availableProcessors(), MIN_CELLS_PER_PART,
                RenderProgress.NONE);
    }

    static ElevationStatistics statistics(DemInput input, int parallelism, long minCellsPerPart)
            throws IOException {
        return statistics(input, null, parallelism, minCellsPerPart, RenderProgress.NONE);
    }

    private static ElevationStatistics statistics(DemInput input, Window.Cells window, int parallelism,
                                                  long minCellsPerPart, RenderProgress progress)
            throws IOException {
        Path file = input.first();
        try (RasterSource source = open(input)) {
            DemInfo info = source.info();
            double noData = info.noDataOrNaN();
            Window.Cells all = new Window.Cells(0, 0, info.width(), info.height());
            if (window != null) {
                if (window.col() < 0 || window.row() < 0 || window.width() < 1 || window.height() < 1
                        || (long) window.col() + window.width() > info.width()
                        || (long) window.row() + window.height() > info.height()) {
                    throw new IllegalArgumentException("the window " + window + " does not lie inside the "
                            + info.width() + " × " + info.height() + " grid of " + file);
                }
                all = window;
            }
            requireBandFits(file, source, all, 1);
            MemoryGuard.requireFits(file, 0, 0, BlockReader.bandBytes(source, all, 1), "give Java more heap"
                    + " with -Xmx");
            StageProgress rows = new StageProgress(progress, RenderProgress.STATISTICS, all.height()).start();
            ElevationStatistics stats = readInParts(input, source, all, 1, parallelism, minCellsPerPart,
                    (src, part, outRow0) -> BlockReader.read(src, part, 1, noData, (row, v) -> rows.add(1)));
            rows.finish();
            return stats;
        }
    }

    /** Opens the right {@link RasterSource} for one file or a mosaic (package-private for tests). */
    static RasterSource open(DemInput input) throws IOException {
        if (input.isSingleFile()) {
            return open(input.first());
        }
        return MosaicSource.open(MosaicPlanner.plan(input.files(), DemReader::open));
    }

    /** Another reader of what {@code source} reads, for a band read on another thread. */
    private static RasterSource reopen(RasterSource source, DemInput input) throws IOException {
        return source instanceof MosaicSource mosaic ? mosaic.reopen() : open(input);
    }

    /** Opens a source of a VRT: any format but a VRT (a VRT of VRTs is not read). */
    private static RasterSource openVrtSource(Path file) throws IOException {
        if (FormatDetector.detect(file).format() == DemFormat.VRT) {
            throw new DemFormatException(file, "is a VRT named as the source of another VRT; a VRT of VRTs is"
                    + " not supported (give its files instead)");
        }
        return open(file);
    }

    /** Opens the right {@link RasterSource} for the file (package-private for tests). */
    static RasterSource open(Path file) throws IOException {
        Objects.requireNonNull(file, "file");
        FormatDetector.Detected detected = FormatDetector.detect(file);
        Path data = detected.dataFile();
        try {
            return switch (detected.format()) {
                case GEOTIFF -> GeoTiffSource.open(data);
                case GRIDFLOAT -> GridFloatFormat.open(data);
                case ESRI_ASCII -> EsriAsciiSource.open(data);
                case BIL -> BilFormat.open(data);
                case SRTM_HGT -> HgtFormat.open(data);
                case VRT -> MosaicSource.open(VrtReader.plan(data, DemReader::openVrtSource));
                case MOSAIC -> throw new IllegalStateException("a file is not detected as a mosaic");
            };
        } catch (DemFormatException e) {
            throw e;
        } catch (IOException e) {
            throw new DemFormatException(data, "cannot be read: " + e.getMessage(), e);
        }
    }
}
