package io.github.jdem846.tiles;

import io.github.jdem846.job.JobListener;
import io.github.jdem846.output.PngBytes;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.CellWindow;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletionService;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorCompletionService;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicLongArray;

/**
 * One run of a {@link TileJob}: the tiles of every zoom in groups of up to {@value #GROUP} × {@value #GROUP}
 * (each group reads its part of the DEM once, at the zoom's decimation), the groups of all zooms spread over the
 * job's threads, each tile rendered on its thread, encoded and handed to the sink.
 */
final class PyramidRun {

    /** Tiles on a side of a group that shares one read of the DEM. */
    static final int GROUP = 4;

    private final TileJob job;
    private final SourceProjection projection;
    private final Scene scene;
    private final ElevationStatistics range;
    private final TileSink sink;
    private final JobListener listener;

    PyramidRun(TileJob job, SourceProjection projection, Scene scene, ElevationStatistics range, TileSink sink,
               JobListener listener) {
        this.job = job;
        this.projection = projection;
        this.scene = scene;
        this.range = range;
        this.sink = sink;
        this.listener = listener;
    }

    /** One zoom's plan. */
    private record Level(int index, ZoomGrid grid, TileRange range, ZoomSource source, TileRasterizer rasterizer) {
    }

    /** A group of tiles of one zoom. */
    private record Group(Level level, List<WebMercatorTile> tiles) {
    }

    TileReport execute(Path output, TileFormat format) throws IOException, InterruptedException {
        List<Level> levels = new ArrayList<>();
        List<Group> groups = new ArrayList<>();
        long total = 0;
        RenderSettings perTile = new RenderSettings(1, job.execution().tileSize());
        Overview overview = overview();
        for (int z = job.zooms().min(); z <= job.zooms().max(); z++) {
            ZoomGrid grid = new ZoomGrid(z);
            int own = ZoomSource.decimationFor(projection, grid);
            boolean small = Overview.isSmall(projection.grid().width(), projection.grid().height(), own);
            Level level = new Level(levels.size(), grid, TileRange.covering(projection.extent(), z),
                    new ZoomSource(job.input(), projection, grid, small ? overview : null),
                    new TileRasterizer(grid, scene, range, perTile));
            levels.add(level);
            total += level.range().count();
        }
        // the deepest zoom first: its groups are the most and the largest
        for (int i = levels.size() - 1; i >= 0; i--) {
            Level level = levels.get(i);
            TileRange r = level.range();
            for (int gy = r.minY() / GROUP; gy <= r.maxY() / GROUP; gy++) {
                for (int gx = r.minX() / GROUP; gx <= r.maxX() / GROUP; gx++) {
                    List<WebMercatorTile> tiles = new ArrayList<>();
                    for (int y = Math.max(r.minY(), gy * GROUP); y <= Math.min(r.maxY(), gy * GROUP + GROUP - 1); y++) {
                        for (int x = Math.max(r.minX(), gx * GROUP); x <= Math.min(r.maxX(), gx * GROUP + GROUP - 1);
                             x++) {
                            tiles.add(new WebMercatorTile(level.grid().zoom(), x, y));
                        }
                    }
                    groups.add(new Group(level, tiles));
                }
            }
        }
        AtomicLongArray written = new AtomicLongArray(levels.size());
        AtomicLong done = new AtomicLong();
        AtomicLong bytes = new AtomicLong();
        long all = total;
        listener.update("tiles", 0, all);
        AtomicInteger threadNumber = new AtomicInteger();
        ExecutorService pool = Executors.newFixedThreadPool(Math.min(job.execution().parallelism(),
                Math.max(1, groups.size())), r -> {
                    Thread t = new Thread(r, "jdem846-tiles-" + threadNumber.incrementAndGet());
                    t.setDaemon(true);
                    return t;
                });
        CompletionService<Void> completion = new ExecutorCompletionService<>(pool);
        List<Future<Void>> futures = new ArrayList<>();
        try {
            for (Group g : groups) {
                futures.add(completion.submit(() -> {
                    renderGroup(g, written, bytes);
                    listener.update("tiles", done.addAndGet(g.tiles().size()), all);
                    return null;
                }));
            }
            for (int i = 0; i < futures.size(); i++) {
                Future<Void> f = completion.take();
                try {
                    f.get();
                } catch (ExecutionException e) {
                    throw rethrow(e.getCause());
                }
            }
        } finally {
            pool.shutdownNow();
            boolean interrupted = Thread.interrupted();
            try {
                while (!pool.awaitTermination(10, TimeUnit.SECONDS)) {
                    // the workers stop at their next tile or stage check
                }
            } catch (InterruptedException e) {
                interrupted = true;
            }
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
        if (Thread.interrupted()) {
            throw new InterruptedException();
        }
        List<TileReport.Zoom> zooms = new ArrayList<>();
        for (Level level : levels) {
            zooms.add(new TileReport.Zoom(level.grid().zoom(), level.range(), written.get(level.index()),
                    level.source().decimation()));
        }
        return new TileReport(output, format, zooms, bytes.get());
    }

    /**
     * The whole DEM read once for the zooms at which it is small ({@link Overview}), at the finest of their
     * decimations; null when there are none.
     */
    private Overview overview() throws IOException {
        int finest = Integer.MAX_VALUE;
        for (int z = job.zooms().min(); z <= job.zooms().max(); z++) {
            int d = ZoomSource.decimationFor(projection, new ZoomGrid(z));
            if (Overview.isSmall(projection.grid().width(), projection.grid().height(), d)) {
                finest = Math.min(finest, d);
            }
        }
        return finest == Integer.MAX_VALUE ? null : Overview.read(job.input(), finest);
    }

    /** Reads the group's part of the DEM and renders, encodes and writes each of its tiles that holds data. */
    private void renderGroup(Group g, AtomicLongArray written, AtomicLong bytes)
            throws IOException, InterruptedException {
        Level level = g.level();
        List<CellWindow> needs = new ArrayList<>();
        CellWindow all = null;
        for (WebMercatorTile t : g.tiles()) {
            CellWindow n = level.rasterizer().need(t);
            needs.add(n);
            all = all == null ? n : TileRasterizer.union(all, n);
        }
        SourceWindow source = level.source().read(all);
        if (source == null) {
            return;
        }
        for (int i = 0; i < g.tiles().size(); i++) {
            if (Thread.currentThread().isInterrupted()) {
                throw new InterruptedException();
            }
            WebMercatorTile t = g.tiles().get(i);
            int[] argb = level.rasterizer().render(t, needs.get(i), source);
            if (argb == null) {
                continue;
            }
            byte[] png = PngBytes.rgba(argb, WebMercatorTile.SIZE, WebMercatorTile.SIZE, job.pngCompression());
            sink.write(t, png);
            written.incrementAndGet(level.index());
            bytes.addAndGet(png.length);
        }
    }

    private static IOException rethrow(Throwable cause) throws IOException, InterruptedException {
        if (cause instanceof IOException e) {
            throw e;
        }
        if (cause instanceof UncheckedIOException e) {
            throw e.getCause();
        }
        if (cause instanceof InterruptedException e) {
            throw e;
        }
        if (cause instanceof RuntimeException e) {
            throw e;
        }
        if (cause instanceof Error e) {
            throw e;
        }
        return new IOException(cause);
    }
}
