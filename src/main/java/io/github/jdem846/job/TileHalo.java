package io.github.jdem846.job;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.CellWindow;
import io.github.jdem846.shadow.ShadowHalo;

/**
 * The cells a tile of a picture must be read with around it, in cells of the picture's grid: one on every side
 * for the hillshade's normals; toward the sun, as far as the highest terrain of the file could still shade the
 * tile, for cast shadows ({@link ShadowHalo#window}: (highest − lowest elevation of the file)/tan(sun elevation),
 * plus the sweep's margin). The file's lowest elevation, not the tile's, because the sweep reads lines down to a
 * floor set by it; the same for every tile, so the halo of a tile is these cells clipped to the grid.
 */
final class TileHalo {

    private TileHalo() {
    }

    /**
     * {west, north, east, south}.
     *
     * @param plan       the picture
     * @param scene      its scene (the product's stages only)
     * @param statistics the whole file's range, or null when no stage needs it
     * @param lighting   the light over the picture, or null for a tint
     */
    static int[] of(PicturePlan plan, Scene scene, ElevationStatistics statistics, Sun.Lighting lighting) {
        int[] h = new int[4];
        if (scene.hillshade() != null) {
            java.util.Arrays.fill(h, 1);
        }
        if (scene.hasAmbient()) {
            java.util.Arrays.fill(h, Math.max(h[0], io.github.jdem846.shadow.SkyView.haloCells(plan.gridGeometry(),
                    scene.skyViewOptions())));
        }
        if (!scene.hasShadows() || statistics == null || statistics.isEmpty()) {
            return h;
        }
        LightDirection light = scene.withLight(lighting.field()).shadowLight();
        GridGeometry g = plan.gridGeometry();
        // the tile in each corner: toward the sun, its halo is clipped by the grid's far side only
        for (int c : new int[] {0, g.width() - 1}) {
            for (int r : new int[] {0, g.height() - 1}) {
                CellWindow tile = new CellWindow(c, r, 1, 1);
                CellWindow need = ShadowHalo.window(g, statistics.max(), statistics.min(), light,
                        scene.shadowOptions(), tile);
                h[0] = Math.max(h[0], tile.col() - need.col());
                h[1] = Math.max(h[1], tile.row() - need.row());
                h[2] = Math.max(h[2], need.colEnd() - tile.colEnd());
                h[3] = Math.max(h[3], need.rowEnd() - tile.rowEnd());
            }
        }
        return h;
    }
}
