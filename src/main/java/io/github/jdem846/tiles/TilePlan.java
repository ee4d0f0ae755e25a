package io.github.jdem846.tiles;

import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.geo.WebMercator;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.job.JobListener;
import io.github.jdem846.output.PngBytes;
import io.github.jdem846.overlay.OverlayPainter;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.CellWindow;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * A {@link TileJob} made ready to render in parts: the DEM's elevation range, the lit scene, and the job's tiles in
 * {@link TileGroup groups} that each share one read of the DEM. {@link TileJob#run} renders every group on its
 * threads; a cluster prepares the plan once on its driver ({@link #prepare(TileJob, JobListener)}, which measures
 * the range), ships the groups and the range to its workers, and each worker prepares the same plan from the same
 * job and that range ({@link #prepare(TileJob, ElevationStatistics)}, which reads only headers) and {@link #render
 * renders} the groups it is given. A tile's bytes depend only on the job and the range, not on who renders it or in
 * what order.
 *
 * <p>Safe for use by several threads once prepared.
 */
public final class TilePlan {

    /** Tiles on a side of a group. */
    static final int GROUP = 4;

    /** One zoom's part of the plan; {@code overlays} null when the job has none. */
    private record Level(ZoomGrid grid, TileRange range, ZoomSource source, TileRasterizer rasterizer,
                         OverlayPainter overlays) {
    }

    private final TileJob job;
    private final SourceProjection projection;
    private final ElevationStatistics range;
    private final List<Level> levels;
    private final List<TileGroup> groups;

    private TilePlan(TileJob job, DemInfo info, ElevationStatistics range, JobListener listener) {
        this.job = job;
        this.range = range;
        this.projection = SourceProjection.of(info.geometry(), info.source());
        Scene scene = job.sceneFor(info, range, listener);
        RenderSettings perTile = job.execution().pool() != null ? job.execution()      // tiles share the pool
                : new RenderSettings(1, job.execution().tileSize());
        Overview overview = overview(job, projection);
        List<Level> ls = new ArrayList<>();
        for (int z = job.zooms().min(); z <= job.zooms().max(); z++) {
            ZoomGrid grid = new ZoomGrid(z);
            int own = ZoomSource.decimationFor(projection, grid);
            boolean small = Overview.isSmall(projection.grid().width(), projection.grid().height(), own);
            TileRange tiles = TileRange.covering(projection.extent(), z);
            ls.add(new Level(grid, tiles, new ZoomSource(job.input(), projection, grid, small ? overview : null),
                    new TileRasterizer(grid, draped(scene, grid, tiles), range, perTile), overlays(job, z)));
        }
        this.levels = List.copyOf(ls);
        // the deepest zoom first: its groups are the most and the largest
        List<TileGroup> gs = new ArrayList<>();
        for (int i = levels.size() - 1; i >= 0; i--) {
            gs.addAll(TileGroup.covering(levels.get(i).range(), GROUP));
        }
        this.groups = List.copyOf(gs);
    }

    /**
     * Reads the DEM's headers and measures its elevation range (one pass over its cells): for the process that
     * hands out the groups.
     *
     * @param job the tile job
     * @param listener told of the DEM's notices, the rows of the file streamed for its range (stage "statistics"),
     *                 the sun computed and the end of the "read" phase
     * @return the plan
     * @throws IOException              when the DEM cannot be read or holds no elevations (naming it)
     * @throws IllegalArgumentException when the job's settings do not make sense for map tiles ({@link
     *                                  TileJob#requireTileable()}) or the DEM's CRS is unknown
     */
    public static TilePlan prepare(TileJob job, JobListener listener) throws IOException {
        Objects.requireNonNull(job, "job");
        Objects.requireNonNull(listener, "listener");
        job.requireTileable();
        DemInfo info = inspect(job);
        for (String notice : info.notices()) {
            listener.notice(notice);
        }
        ElevationStatistics range = DemReader.statistics(job.input(), listener);
        if (range.isEmpty()) {
            throw new IOException(info.source() + " holds no elevations (every cell is no-data)");
        }
        listener.phaseDone("read");
        return new TilePlan(job, info, range, listener);
    }

    /**
     * The plan of {@code job} with the elevation range measured elsewhere ({@link #range()} of the plan prepared
     * with {@link #prepare(TileJob, JobListener)}): reads only the DEM's headers. Its tiles are the same bytes as
     * those of that plan.
     *
     * @param job the tile job
     * @param range the elevation range of the whole DEM
     * @return the plan
     * @throws IOException              when the DEM's headers cannot be read
     * @throws IllegalArgumentException as {@link #prepare(TileJob, JobListener)}, or for an empty range
     */
    public static TilePlan prepare(TileJob job, ElevationStatistics range) throws IOException {
        return prepare(job, range, JobListener.NONE);
    }

    /**
     * {@link #prepare(TileJob, ElevationStatistics)}, telling {@code listener} of the sun computed (a driver that
     * measured the range in parts reports it).
     *
     * @param job the tile job
     * @param range the elevation range of the whole DEM
     * @param listener told of the sun computed
     * @return the plan
     * @throws IOException when the DEM's headers cannot be read
     */
    public static TilePlan prepare(TileJob job, ElevationStatistics range, JobListener listener) throws IOException {
        Objects.requireNonNull(job, "job");
        Objects.requireNonNull(range, "range");
        Objects.requireNonNull(listener, "listener");
        if (range.isEmpty()) {
            throw new IllegalArgumentException("the elevation range holds no elevations");
        }
        job.requireTileable();
        return new TilePlan(job, inspect(job), range, listener);
    }

    private static DemInfo inspect(TileJob job) throws IOException {
        return DemReader.inspect(job.input()).withDefaultEllipsoid(Ellipsoid.WGS84);
    }

    /**
     * The scene for one zoom: its drape, if any, placed on the zoom's tiles ({@link
     * io.github.jdem846.render.ColorLayer#forPicture}: sampling steps measured at their centre, not at the world's)
     * and checked to cover some of them.
     *
     * @throws IllegalArgumentException when the drape cannot be placed on the tiles (naming the image)
     */
    private static Scene draped(Scene scene, ZoomGrid grid, TileRange tiles) {
        if (scene.drape() == null) {
            return scene;
        }
        int s = WebMercatorTile.SIZE;
        GridGeometry picture = grid.window(tiles.minX() * s, tiles.minY() * s, (tiles.maxX() - tiles.minX() + 1) * s,
                (tiles.maxY() - tiles.minY() + 1) * s);
        scene.drape().requireCovers(picture);
        return scene.withDrape(scene.drape().forPicture(picture));
    }

    /**
     * The whole DEM read once for the zooms at which it is small ({@link Overview}), at the finest of their
     * decimations, on first use; null when there are none.
     */
    private static Overview overview(TileJob job, SourceProjection projection) {
        int finest = Integer.MAX_VALUE;
        for (int z = job.zooms().min(); z <= job.zooms().max(); z++) {
            int d = ZoomSource.decimationFor(projection, new ZoomGrid(z));
            if (Overview.isSmall(projection.grid().width(), projection.grid().height(), d)) {
                finest = Math.min(finest, d);
            }
        }
        return finest == Integer.MAX_VALUE ? null : Overview.lazy(job.input(), finest);
    }

    /**
     * The job's overlays on the whole world at zoom {@code z} (Web Mercator pixels, row 0 at the north edge), cut at
     * the antimeridian and the Web Mercator latitude limit; null when there are none.
     */
    private static OverlayPainter overlays(TileJob job, int z) {
        if (job.overlays().isEmpty()) {
            return null;
        }
        int side = WebMercatorTile.SIZE << z;
        double cell = WebMercatorTile.pixelSize(z);
        GridGeometry world = new GridGeometry(side, side, -WebMercator.HALF_WORLD, WebMercator.HALF_WORLD, cell, cell,
                WebMercator.CRS, PixelAnchor.CORNER);
        return OverlayPainter.onMap(job.overlays(), world, 0, WebMercator.MAX_LATITUDE);
    }

    /** {@return the job planned} */
    public TileJob job() {
        return job;
    }

    /** {@return the whole DEM's elevations, which set the tint and the cast-shadow halos} */
    public ElevationStatistics range() {
        return range;
    }

    /** {@return every group of tiles, the deepest zoom's first} */
    public List<TileGroup> groups() {
        return groups;
    }

    /** {@return how many tiles the zoom levels' ranges hold, with data or not} */
    public long tileCount() {
        long n = 0;
        for (Level level : levels) {
            n += level.range().count();
        }
        return n;
    }

    /**
     * Renders the tiles of {@code group} that hold data, each encoded as PNG.
     *
     * @param group one of {@link #groups()}
     * @return the tiles with data, in the group's order (row by row); empty when none holds data
     * @throws IOException              when the DEM cannot be read
     * @throws IllegalArgumentException when {@code group} is not one of {@link #groups()}' tiles
     * @throws InterruptedException     when the calling thread is interrupted
     */
    public List<EncodedTile> render(TileGroup group) throws IOException, InterruptedException {
        Level level = levelOf(group);
        List<WebMercatorTile> tiles = group.tiles();
        List<CellWindow> needs = new ArrayList<>(tiles.size());
        CellWindow all = null;
        for (WebMercatorTile t : tiles) {
            CellWindow n = level.rasterizer().need(t);
            needs.add(n);
            all = all == null ? n : TileRasterizer.union(all, n);
        }
        SourceWindow source = level.source().read(all);
        if (source == null) {
            return List.of();
        }
        List<EncodedTile> out = new ArrayList<>();
        for (int i = 0; i < tiles.size(); i++) {
            if (Thread.currentThread().isInterrupted()) {
                throw new InterruptedException();
            }
            WebMercatorTile t = tiles.get(i);
            int[] argb = level.rasterizer().render(t, needs.get(i), source);
            if (argb != null && level.overlays() != null) {
                level.overlays().paintWindow(argb, (long) t.x() * WebMercatorTile.SIZE,
                        (long) t.y() * WebMercatorTile.SIZE, WebMercatorTile.SIZE, WebMercatorTile.SIZE);
            }
            if (argb != null) {
                out.add(new EncodedTile(t, PngBytes.rgba(argb, WebMercatorTile.SIZE, WebMercatorTile.SIZE,
                        job.pngCompression())));
            }
        }
        return Collections.unmodifiableList(out);
    }

    private Level levelOf(TileGroup group) {
        int i = group.z() - job.zooms().min();
        if (i < 0 || i >= levels.size()) {
            throw new IllegalArgumentException("tile group " + group + " is not of zoom " + job.zooms());
        }
        Level level = levels.get(i);
        TileRange r = level.range();
        if (group.minX() < r.minX() || group.maxX() > r.maxX() || group.minY() < r.minY() || group.maxY() > r.maxY()) {
            throw new IllegalArgumentException("tile group " + group + " lies outside the DEM's tiles " + r);
        }
        return level;
    }

    /** {@return what an archive's header and metadata say about these tiles} */
    public TileSink.TileSetInfo tileSetInfo() {
        String name = job.input().first().getFileName().toString();
        return new TileSink.TileSetInfo(name, "Shaded relief of " + name + " by jdem846", job.zooms(),
                projection.extent());
    }

    /**
     * The report of a finished run.
     *
     * @param output where the tiles were written
     * @param format the format they were written in
     * @param writtenByZoom tiles written at each zoom (a zoom left out wrote none)
     * @param bytes         PNG bytes written
     * @return the report
     */
    public TileReport report(Path output, TileFormat format, Map<Integer, Long> writtenByZoom, long bytes) {
        List<TileReport.Zoom> zooms = new ArrayList<>();
        for (Level level : levels) {
            int z = level.grid().zoom();
            zooms.add(new TileReport.Zoom(z, level.range(), writtenByZoom.getOrDefault(z, 0L),
                    level.source().decimation()));
        }
        return new TileReport(output, format, zooms, bytes);
    }
}
