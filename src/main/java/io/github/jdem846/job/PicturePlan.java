package io.github.jdem846.job;

import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.Window;
import io.github.jdem846.io.source.BlockReader;
import io.github.jdem846.raster.DemResampler;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.shadow.CellWindow;

/**
 * What a picture reads, planned from the file's header before any cell is read: the cells of the file read
 * ({@code read}: the window and the halo its stages need around it), the decimation of that read, the size of the
 * grid it becomes at the picture's resolution (the "grid": decimated, then resampled to exactly that size), and
 * where the picture lies in that grid. Rendering in memory loads the whole grid; rendering in tiles loads pieces
 * of it ({@link DemLoader#loadRegion}) whose cells are those of the whole grid, bit for bit.
 *
 * @param info       the file's header, on {@code body}
 * @param body       the ellipsoid of a file that names none
 * @param window     the picture's cells in the file
 * @param read       the file's cells read: the window and its halo
 * @param decimation the read's block size (1 = every cell)
 * @param gridWidth  columns of the grid at the picture's resolution
 * @param gridHeight rows of the grid at the picture's resolution
 * @param area       the picture's pixels within the grid
 */
record PicturePlan(DemInfo info, Ellipsoid body, Window.Cells window, Window.Cells read, int decimation, int gridWidth,
                   int gridHeight, CellWindow area) {

    /** @return pixels across */
    int width() {
        return area.width();
    }

    /** @return pixels down */
    int height() {
        return area.height();
    }

    /** @return cells of the grid at the picture's resolution, halo included */
    long gridCells() {
        return (long) gridWidth * gridHeight;
    }

    /** @return the picture's pixels */
    long pixels() {
        return area.cellCount();
    }

    /** @return columns of the decimated read */
    int decimatedWidth() {
        return BlockReader.outputSize(read.width(), decimation);
    }

    /** @return rows of the decimated read */
    int decimatedHeight() {
        return BlockReader.outputSize(read.height(), decimation);
    }

    /** @return true when the decimated read is resampled to the grid's size (a picture not in whole blocks) */
    boolean resampled() {
        return gridWidth != decimatedWidth() || gridHeight != decimatedHeight();
    }

    /** @return true when the grid has more cells than the read on both axes: an enlarged grid, with a coverage */
    boolean enlarged() {
        return gridWidth > decimatedWidth() && gridHeight > decimatedHeight();
    }

    /** @return true when the grid is the file's cells themselves: one pixel per cell */
    boolean fullResolution() {
        return decimation == 1 && !resampled();
    }

    /**
     * The geometry of the grid at the picture's resolution, as a load of it has it: the read window of the file,
     * decimated, resampled.
     *
     * @return the grid's geometry
     */
    GridGeometry gridGeometry() {
        GridGeometry g = info.geometry().window(read.col(), read.row(), read.width(), read.height());
        if (decimation > 1) {
            g = g.decimate(decimation, decimation);
        }
        return resampled() ? DemResampler.resampledGeometry(g, gridWidth, gridHeight) : g;
    }

    /**
     * A geometry read from the file, measured as the plan's header is: with ground cell sizes when the header has
     * them ({@link MercatorScale#GROUND}).
     *
     * @param g a geometry of the file's cells as the reader gives it
     * @return {@code g}, with ground cell sizes if the plan measures cells on the ground
     */
    GridGeometry measured(GridGeometry g) {
        return info.geometry().hasGroundCellSizes() && !g.hasGroundCellSizes() ? g.withGroundCellSizes() : g;
    }

    /** @return the geometry of the picture: the grid's, cut to {@link #area} */
    GridGeometry pictureGeometry() {
        return gridGeometry().window(area.col(), area.row(), area.width(), area.height());
    }

    /** @return true when the picture and its grid each fit in one Java array */
    boolean fitsOneArray() {
        return gridCells() <= MAX_ARRAY && pixels() <= MAX_ARRAY;
    }

    /** The longest Java array (a little below {@link Integer#MAX_VALUE} on common JVMs). */
    static final long MAX_ARRAY = Integer.MAX_VALUE - 8L;
}
