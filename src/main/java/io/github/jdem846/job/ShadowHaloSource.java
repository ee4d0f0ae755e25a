package io.github.jdem846.job;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.shadow.CellWindow;
import io.github.jdem846.shadow.ShadowHalo;
import io.github.jdem846.shadow.ShadowOptions;

/**
 * The halo a windowed render with cast shadows must read: toward the sun, as far as the highest terrain of the file
 * could still shade the window ({@link ShadowHalo}); nothing for a sun at or below the horizon or at the zenith.
 * The file's range is streamed once (no grid is held in memory) and only when a window is given. The sweep must
 * then be given the file's minimum ({@link ShadowOptions#withTerrainMinimum}) to equal the whole file's mask.
 */
final class ShadowHaloSource {

    private ShadowHaloSource() {
    }

    /** The shadow halo for {@code light} and {@code options}. */
    static DemLoader.Halo of(LightDirection light, ShadowOptions options) {
        return (statistics, info, window) -> {
            boolean whole = window.col() == 0 && window.row() == 0 && window.width() == info.width()
                    && window.height() == info.height();
            double e = light.elevationDegrees();
            if (whole || e <= 0 || e >= 90) {
                return new int[4];
            }
            ElevationStatistics stats = statistics.get();
            CellWindow tile = new CellWindow(window.col(), window.row(), window.width(), window.height());
            CellWindow need = ShadowHalo.window(info.geometry(), stats.max(), stats.min(), light, options, tile);
            return new int[] {tile.col() - need.col(), tile.row() - need.row(), need.colEnd() - tile.colEnd(),
                need.rowEnd() - tile.rowEnd()};
        };
    }

}
