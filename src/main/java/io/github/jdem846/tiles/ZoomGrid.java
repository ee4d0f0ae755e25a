package io.github.jdem846.tiles;

import io.github.jdem846.geo.WebMercator;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;

/**
 * The whole Web Mercator world at one zoom as one grid of 256·2^z pixels a side, row 0 at the north edge, with
 * metric cell sizes measured on the ground ({@link GridGeometry#withGroundCellSizes()}). Every tile grid is a window
 * of it, so that neighbouring tiles share their cells' positions bit for bit and the shadow sweep lays its lines
 * the same way in each ({@link GridGeometry#placement()}).
 */
final class ZoomGrid {

    private final int z;
    private final double cell;
    private final GridGeometry world;

    ZoomGrid(int z) {
        this.z = z;
        int side = WebMercatorTile.SIZE << z;
        this.cell = WebMercatorTile.pixelSize(z);
        this.world = new GridGeometry(side, side, -WebMercator.HALF_WORLD, WebMercator.HALF_WORLD, cell, cell,
                WebMercator.CRS, PixelAnchor.CORNER).withGroundCellSizes();
    }

    int zoom() {
        return z;
    }

    /** @return pixels on a side of the world at this zoom */
    long side() {
        return (long) WebMercatorTile.SIZE << z;
    }

    /** @return Web Mercator x of the centre of global pixel column {@code col} */
    double centerX(long col) {
        return -WebMercator.HALF_WORLD + (col + 0.5) * cell;
    }

    /** @return Web Mercator y of the centre of global pixel row {@code row} */
    double centerY(long row) {
        return WebMercator.HALF_WORLD - (row + 0.5) * cell;
    }

    /** @return Web Mercator x of the west edge of global column {@code col} */
    double edgeX(long col) {
        return -WebMercator.HALF_WORLD + col * cell;
    }

    /** @return Web Mercator y of the north edge of global row {@code row} */
    double edgeY(long row) {
        return WebMercator.HALF_WORLD - row * cell;
    }

    /** @return the geometry of the {@code w × h} pixels from global ({@code col}, {@code row}) (may reach past the world) */
    GridGeometry window(int col, int row, int w, int h) {
        return world.window(col, row, w, h);
    }
}
