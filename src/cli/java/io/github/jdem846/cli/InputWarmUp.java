package io.github.jdem846.cli;

import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.ReadRequest;
import io.github.jdem846.io.Window;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Reads the input's header and first rows on a daemon thread while picocli parses the command line, so that the
 * reader's slow first steps overlap with it: the decoder's classes and first compilations and, only when the file
 * needs them, Apache SIS's (about 0.3 s on first use: a {@code .prj} or projected GeoTIFF of a CRS other than the
 * common ones known without it). A lat/lon or UTM GeoTIFF, an SRTM tile or a file without CRS never starts SIS,
 * which would otherwise take a core from the command for nothing (docs/performance.md, "Start-up"). The input is
 * the first argument that names an existing DEM file; without one (the bundled sample, {@code --version}, a typo)
 * nothing is done. When the command will need latitude/longitude ({@link #needsLatLon}), the file's CRS is also
 * resolved by SIS here. For a grid of 16 to 256 MiB that the command reads whole, the heap memory it will take is
 * also mapped ahead ({@link #touchGridMemory}). Any failure here is ignored: the command reads the file again and
 * reports its own errors. Runs only with {@code -Djdem846.warmUp=on} ({@link WarmUpThread}).
 */
final class InputWarmUp {

    private InputWarmUp() {
    }

    /** Starts the warm-up thread for the command line {@code args} and returns at once. */
    static void start(String[] args) {
        String[] copy = args.clone();
        WarmUpThread.start("jdem846-input-warm-up", () -> run(copy));
    }

    /** Time the reader warm-up may take: about picocli's start-up, after which the command reads for itself. */
    private static final long READ_WARM_UP_NANOS = 250_000_000L;

    /**
     * Heap the reader warm-up may take: 64 MiB, less on small heaps. A file whose first rows need more (one huge
     * strip) is not warmed up: the reader refuses the read before it allocates ({@link ReadRequest#memoryLimit()}).
     */
    static long warmUpMemoryLimit() {
        return Math.min(64L << 20, Runtime.getRuntime().maxMemory() / 16);
    }

    private static void run(String[] args) {
        try {
            Optional<DemInfo> dem = firstDem(args);
            if (dem.isPresent() && needsLatLon(args)) {
                dem.get().geometry().geoLocator();   // SIS's CRS and transform, as the command will
            }
            if (dem.isPresent()) {
                if (readsWholeGrid(args)) {
                    touchGridMemory(dem.get());
                }
                warmUpReader(dem.get());
            }
        } catch (IOException | RuntimeException | LinkageError e) {
            // ignored: see the class comment
        }
    }

    /**
     * Allocates, and drops at once, an array of the grid's size ({@link #gridMemoryToTouch}), so that the kernel
     * maps the heap memory a grid of that size takes while picocli starts, on the core it leaves idle. The command's
     * own grid, allocated after the garbage collection that start-up brings, then mostly lands on memory already
     * mapped: on a 2-vCPU VM allocating the 4000² grid (64 MB) took 90–200 ms on fresh memory and 0.5–25 ms after
     * this, about half of the read (docs/performance.md, "Reading GeoTIFF and other encodings").
     *
     * @return the cells allocated, 0 when none
     */
    static int touchGridMemory(DemInfo info) {
        long bytes = gridMemoryToTouch(info, Runtime.getRuntime().maxMemory());
        if (bytes == 0) {
            return 0;
        }
        float[] grid = new float[(int) (bytes / Float.BYTES)];
        return grid.length;
    }

    /** The commands that render a picture of the grid in memory, reading it whole (unless told a window or size). */
    private static final java.util.Set<String> WHOLE_GRID_COMMANDS = java.util.Set.of("hillshade", "render", "tint",
            "shadows", "skyview");

    /**
     * True when the command reads its grid whole into memory, so that its memory is worth touching ahead: not
     * {@code info} (statistics are streamed), {@code tiles} or {@code view} (parts and reduced grids), {@code sun}.
     */
    static boolean readsWholeGrid(String[] args) {
        return args.length > 0 && WHOLE_GRID_COMMANDS.contains(args[0]);
    }

    /** Grids from this size on have their memory touched ahead: below, the mapping costs a few milliseconds. */
    private static final long MIN_TOUCHED_GRID = 16L << 20;

    /** The largest grid whose memory is touched ahead (64 M cells). */
    private static final long MAX_TOUCHED_GRID = 256L << 20;

    /**
     * Bytes of the float32 grid of {@code info} when its memory is worth touching ahead: from 16 to 256 MiB, and
     * at most an eighth of {@code maxHeap}; 0 otherwise.
     */
    static long gridMemoryToTouch(DemInfo info, long maxHeap) {
        long bytes = (long) info.width() * info.height() * Float.BYTES;
        return bytes >= MIN_TOUCHED_GRID && bytes <= Math.min(MAX_TOUCHED_GRID, maxHeap / 8) ? bytes : 0;
    }

    /**
     * Reads the file's first rows a few times, so that the decoder's classes are loaded and its loops on their way
     * to compiled code before the command's own read (a cold 4000² Deflate read took 0.83 s, 0.62 s after one such
     * read, 0.46 s after twenty; docs/performance.md). At most an eighth of the file per read, {@link
     * #warmUpCells} cells (none for a small file) and {@link #READ_WARM_UP_NANOS} of time in all, and {@link
     * #warmUpMemoryLimit()} of heap, on the core picocli's start-up leaves idle.
     */
    private static void warmUpReader(DemInfo info) throws IOException {
        Path dem = Path.of(info.source());
        ReadRequest firstRows = firstRows(info);
        Window.Cells window = (Window.Cells) firstRows.window();
        long perRead = (long) window.width() * window.height();
        long budget = warmUpCells(info, perRead);
        long start = System.nanoTime();
        for (long cells = perRead; cells <= budget && System.nanoTime() - start < READ_WARM_UP_NANOS;
                cells += perRead) {
            DemReader.read(dem, firstRows);
        }
    }

    /**
     * Cells the reader warm-up may read in all, in reads of {@code perRead} cells: a quarter of the file's, and
     * none when the file holds fewer than {@link #MIN_READS_IN_FILE} such reads. A small file is read by the
     * command sooner than the warm-up could compile the decoder's loops, and reading its first rows again and again
     * took a core from the command: Big Tujunga's hillshade (1197 × 643) took 0.47 s with 250 ms of such reads, 0.41
     * s with two, 0.36 s with none (docs/performance.md, "Start-up").
     */
    static long warmUpCells(DemInfo info, long perRead) {
        long cells = (long) info.width() * info.height();
        return cells < MIN_READS_IN_FILE * perRead ? 0 : cells / 4;
    }

    /** The reader is warmed up only on files of at least this many first-rows reads. */
    private static final long MIN_READS_IN_FILE = 16;

    /** What the warm-up reads: up to 512 × 256 cells at the top left, within {@link #warmUpMemoryLimit()}. */
    static ReadRequest firstRows(DemInfo info) {
        int w = Math.min(info.width(), 512);
        int h = (int) Math.max(1, Math.min(256, (long) info.width() * info.height() / 8 / w));
        return ReadRequest.of(Window.cells(0, 0, w, Math.min(h, info.height())))
                .withMemoryLimit(warmUpMemoryLimit());
    }

    /**
     * True when the command will locate the grid in latitude/longitude, which needs Apache SIS also for a CRS the
     * reader knows without it (a UTM zone): {@code info}, a sun by date and time, a world file's {@code .prj}.
     */
    static boolean needsLatLon(String[] args) {
        if (args.length > 0 && args[0].equals("info")) {
            return true;
        }
        for (String arg : args) {
            if (arg.equals("--sun-time") || arg.startsWith("--sun-time=") || arg.equals("--world-file")) {
                return true;
            }
        }
        return false;
    }

    /**
     * Reads the header (and CRS) of the first argument that names an existing DEM file, as the command's reader
     * will: the warm-up itself. Options, missing files and files that are not DEMs (a colour table, an earlier
     * output) are skipped.
     *
     * @return that file, or empty when no argument names one
     */
    static Optional<Path> readFirstDem(String[] args) {
        return firstDem(args).map(info -> Path.of(info.source()));
    }

    /** The header of the first argument that names an existing DEM file (read once, used for all the warm-up). */
    private static Optional<DemInfo> firstDem(String[] args) {
        for (String arg : args) {
            if (arg.startsWith("-") || !isFile(arg)) {
                continue;
            }
            try {
                return Optional.of(DemReader.inspect(Path.of(arg)));
            } catch (IOException | RuntimeException e) {
                // not a DEM: try the next argument
            }
        }
        return Optional.empty();
    }

    private static boolean isFile(String arg) {
        try {
            return Files.isRegularFile(Path.of(arg));
        } catch (InvalidPathException e) {
            return false;
        }
    }
}
