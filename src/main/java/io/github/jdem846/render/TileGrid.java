package io.github.jdem846.render;

/**
 * The split of a {@code width × height} raster into square tiles of {@code tileSize} cells (the last row and column
 * of tiles may be smaller).
 *
 * @param width    raster width, ≥ 1
 * @param height   raster height, ≥ 1
 * @param tileSize tile edge in cells, ≥ 1
 */
record TileGrid(int width, int height, int tileSize) {

    TileGrid {
        if (width < 1 || height < 1 || tileSize < 1) {
            throw new IllegalArgumentException("bad tile grid " + width + "×" + height + " / " + tileSize);
        }
    }

    int columns() {
        return (width + tileSize - 1) / tileSize;
    }

    int rows() {
        return (height + tileSize - 1) / tileSize;
    }

    int count() {
        return columns() * rows();
    }

    /** Column of the first cell of tile {@code index}. */
    int col0(int index) {
        return (index % columns()) * tileSize;
    }

    /** Row of the first cell of tile {@code index}. */
    int row0(int index) {
        return (index / columns()) * tileSize;
    }

    int tileWidth(int index) {
        return Math.min(tileSize, width - col0(index));
    }

    int tileHeight(int index) {
        return Math.min(tileSize, height - row0(index));
    }
}
