package io.github.jdem846.tiles;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.CellWindow;
import io.github.jdem846.shadow.ShadowHalo;

/**
 * Draws the tiles of one zoom: each tile's grid is a window of the {@link ZoomGrid} holding the tile and the halo its
 * stages read (one pixel for hillshade normals; toward the sun as far as the DEM's highest terrain can shade the tile
 * for cast shadows, {@link ShadowHalo}), sampled from the DEM ({@link SourceWindow}) and rendered by the ordinary
 * {@link Renderer} over the tile's own pixels, so shadows and slopes run on across tile seams.
 */
final class TileRasterizer {

    /** Largest halo tried on a side, in pixels: beyond it the zoom is refused (see {@link #need}). */
    static final int MAX_HALO = 1 << 15;

    private final ZoomGrid zoom;
    private final Scene scene;
    private final ElevationStatistics range;
    private final RenderSettings settings;

    /**
     * @param scene    the scene with its light, tint range and the DEM's lowest elevation set ({@link TileJob})
     * @param range    the whole DEM's elevations (for the shadow halo)
     * @param settings the renderer's settings for one tile (one thread)
     */
    TileRasterizer(ZoomGrid zoom, Scene scene, ElevationStatistics range, RenderSettings settings) {
        this.zoom = zoom;
        this.scene = scene;
        this.range = range;
        this.settings = settings;
    }

    /** @return the global pixels of {@code tile} itself */
    static CellWindow core(WebMercatorTile tile) {
        return new CellWindow(tile.x() * WebMercatorTile.SIZE, tile.y() * WebMercatorTile.SIZE, WebMercatorTile.SIZE,
                WebMercatorTile.SIZE);
    }

    /**
     * The global pixels a tile's stages read: the tile and its halo.
     *
     * @throws IllegalArgumentException when cast shadows would need a halo over {@link #MAX_HALO} pixels (a sun
     *                                  very low for this zoom), or an endless one (soft shadows with the sun's lower
     *                                  limb below the horizon)
     */
    CellWindow need(WebMercatorTile tile) {
        return need(core(tile));
    }

    /** {@link #need(WebMercatorTile)} of any block {@code core} of global pixels. */
    CellWindow need(CellWindow core) {
        int base = scene.hasAmbient() ? skyHalo(core) : scene.hillshade() != null ? 1 : 0;
        CellWindow need = grow(core, base);
        if (!scene.hasShadows() || range.isEmpty()) {
            return need;
        }
        double dist = ShadowHalo.distanceMeters(range.max(), range.min(), scene.shadowLight(),
                scene.shadowOptions());
        if (Double.isInfinite(dist)) {
            throw new IllegalArgumentException("soft shadows with the sun's lower limb at or below the horizon cover "
                    + "everything and have no end toward the sun: raise --sun-elevation for map tiles");
        }
        // ShadowHalo sizes the halo inside a grid it may not leave: try ever larger grids around the tile until the
        // halo no longer touches their sides (rows stop at the world's north and south edges, where cells shrink
        // toward nothing on the ground; columns may run past the antimeridian, where there is no data)
        long side = zoom.side();
        for (int e = 64; ; e *= 4) {
            int r0 = (int) Math.max(0, (long) core.row() - e);
            int r1 = (int) Math.min(side, (long) core.rowEnd() + e);
            GridGeometry around = zoom.window(core.col() - e, r0, core.width() + 2 * e, r1 - r0);
            CellWindow w = ShadowHalo.window(around, range.max(), range.min(), scene.shadowLight(),
                    scene.shadowOptions(), new CellWindow(e, core.row() - r0, core.width(), core.height()));
            boolean clipped = w.col() == 0 || w.colEnd() == around.width() || w.row() == 0 && r0 > 0
                    || w.rowEnd() == around.height() && r1 < side;
            if (!clipped) {
                CellWindow shadows = new CellWindow(core.col() - e + w.col(), r0 + w.row(), w.width(), w.height());
                return union(need, shadows);
            }
            if (e >= MAX_HALO) {
                throw new IllegalArgumentException("cast shadows at zoom " + zoom.zoom() + " would need more than "
                        + MAX_HALO + " pixels of terrain toward the sun around each tile: use a lower --zoom or a "
                        + "higher sun");
            }
        }
    }

    /**
     * The sky-view halo of {@code core} ({@link io.github.jdem846.shadow.SkyView#haloCells}): with a search radius,
     * measured in the smallest pixels (on the ground) of the rows it covers, grown until they cover the halo itself.
     */
    private int skyHalo(CellWindow core) {
        io.github.jdem846.shadow.SkyViewOptions o = scene.skyViewOptions();
        if (!o.bounded()) {
            return io.github.jdem846.shadow.SkyView.HALO_CELLS;
        }
        long side = zoom.side();
        int h = 0;
        while (true) {
            int r0 = (int) Math.max(0, (long) core.row() - h);
            int r1 = (int) Math.min(side, (long) core.rowEnd() + h);
            int next = io.github.jdem846.shadow.SkyView.haloCells(zoom.window(core.col(), r0, 1, r1 - r0), o);
            if (next <= h || h >= MAX_HALO) {
                return Math.min(h, MAX_HALO);
            }
            h = next;
        }
    }

    /**
     * Renders {@code tile} from {@code source}.
     *
     * @param need the tile's halo window ({@link #need})
     * @return the tile's ARGB pixels, or null when it holds no data at all
     */
    int[] render(WebMercatorTile tile, CellWindow need, SourceWindow source) throws InterruptedException {
        return render(core(tile), need, source);
    }

    /** {@link #render(WebMercatorTile, CellWindow, SourceWindow)} of any block {@code core} of global pixels. */
    int[] render(CellWindow core, CellWindow need, SourceWindow source) throws InterruptedException {
        float[] values = source.sample(zoom, need.col(), need.row(), need.width(), need.height());
        CellWindow area = new CellWindow(core.col() - need.col(), core.row() - need.row(), core.width(),
                core.height());
        if (!hasData(values, need.width(), area)) {
            return null;
        }
        GridGeometry g = zoom.window(need.col(), need.row(), need.width(), need.height());
        Dem dem = Dem.ofNormalized(values, g, Double.NaN);
        return new Renderer(settings).render(dem, scene, area, RenderProgress.NONE).argb();
    }

    private static boolean hasData(float[] values, int width, CellWindow area) {
        for (int r = area.row(); r < area.rowEnd(); r++) {
            for (int c = area.col(); c < area.colEnd(); c++) {
                if (!Float.isNaN(values[r * width + c])) {
                    return true;
                }
            }
        }
        return false;
    }

    private static CellWindow grow(CellWindow w, int n) {
        return new CellWindow(w.col() - n, w.row() - n, w.width() + 2 * n, w.height() + 2 * n);
    }

    static CellWindow union(CellWindow a, CellWindow b) {
        int c0 = Math.min(a.col(), b.col());
        int r0 = Math.min(a.row(), b.row());
        int c1 = Math.max(a.colEnd(), b.colEnd());
        int r1 = Math.max(a.rowEnd(), b.rowEnd());
        return new CellWindow(c0, r0, c1 - c0, r1 - r0);
    }
}
