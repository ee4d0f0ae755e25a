package io.github.jdem846.job;

import io.github.jdem846.shadow.CellWindow;

/**
 * How a picture too large for the memory budget is cut: tiles of {@code tileWidth × tileHeight} pixels (the last
 * column and row of tiles smaller), rendered one band of tiles at a time from north to south, each from its own
 * piece of the grid: the tile and the halo its stages read around it, clipped to the grid.
 *
 * @param tileWidth  pixels across a tile
 * @param tileHeight pixels down a tile (and rows of a band)
 * @param west       grid cells read west of a tile
 * @param north      grid cells read north of a tile
 * @param east       grid cells read east of a tile
 * @param south      grid cells read south of a tile
 * @param bytes      the most heap one tile, its piece of the grid and its band of rows take ({@link JobMemory})
 */
record TileLayout(int tileWidth, int tileHeight, int west, int north, int east, int south, long bytes) {

    /** Cells of work a tile costs besides its cells (a pool started, the file opened, the header parsed). */
    private static final long CELLS_PER_TILE = 1L << 18;

    /** @return tiles across a picture of {@code width} pixels */
    int columns(int width) {
        return (int) ((width + (long) tileWidth - 1) / tileWidth);
    }

    /** @return bands down a picture of {@code height} pixels */
    int rows(int height) {
        return (int) ((height + (long) tileHeight - 1) / tileHeight);
    }

    /**
     * The piece of a {@code gridWidth × gridHeight} grid a tile is rendered from: the tile and the halo, clipped.
     *
     * @param tile the tile's pixels in the grid
     * @return the cells to load
     */
    CellWindow region(CellWindow tile, int gridWidth, int gridHeight) {
        int c0 = (int) Math.max(0, (long) tile.col() - west);
        int r0 = (int) Math.max(0, (long) tile.row() - north);
        int c1 = (int) Math.min(gridWidth, (long) tile.colEnd() + east);
        int r1 = (int) Math.min(gridHeight, (long) tile.rowEnd() + south);
        return new CellWindow(c0, r0, c1 - c0, r1 - r0);
    }

    /**
     * The layout that reads and renders the fewest cells in all (the halo is read again for every tile) within
     * {@code budget} bytes, or {@code null} when not even one tile of {@code unit × unit} pixels and its halo fit.
     *
     * @param plan   the picture
     * @param halo   {west, north, east, south} grid cells each tile needs around it
     * @param unit   tile sides are multiples of it (but for the last tiles)
     * @param needs  what the product holds
     * @param budget most bytes
     */
    static TileLayout choose(PicturePlan plan, int[] halo, int unit, JobMemory needs, long budget) {
        int h = plan.height();
        TileLayout best = null;
        double bestCost = Double.POSITIVE_INFINITY;
        for (long th = Math.min(unit, h); ; th = Math.min(h, Math.max(th + unit, roundUp(th + th / 8, unit)))) {
            TileLayout widest = widest(plan, halo, unit, needs, budget, (int) th);
            if (widest != null) {
                double cost = widest.cost(plan);
                if (cost < bestCost) {
                    best = widest;
                    bestCost = cost;
                }
            }
            if (th >= h) {
                return best;
            }
        }
    }

    /** The widest tiles of {@code th} rows that fit, or null. */
    private static TileLayout widest(PicturePlan plan, int[] halo, int unit, JobMemory needs, long budget, int th) {
        int w = plan.width();
        long steps = (w + (long) unit - 1) / unit;
        TileLayout fit = null;
        long lo = 1;
        long hi = steps;
        while (lo <= hi) {
            long mid = (lo + hi) >>> 1;
            int tw = (int) Math.min(w, mid * unit);
            TileLayout t = sized(plan, halo, needs, tw, th);
            if (t != null && t.bytes <= budget) {
                fit = t;
                lo = mid + 1;
            } else {
                hi = mid - 1;
            }
        }
        return fit;
    }

    /** Tiles of {@code tw × th} with their memory, or null when a piece would not fit in one Java array. */
    static TileLayout sized(PicturePlan plan, int[] halo, JobMemory needs, int tw, int th) {
        long regionW = Math.min(plan.gridWidth(), (long) tw + halo[0] + halo[2]);
        long regionH = Math.min(plan.gridHeight(), (long) th + halo[1] + halo[3]);
        long cells = regionW * regionH;
        long read = plan.resampled() ? readCells(plan, regionW, regionH) : 0;
        long band = (long) plan.width() * th;
        if (cells > PicturePlan.MAX_ARRAY || read > PicturePlan.MAX_ARRAY || band > PicturePlan.MAX_ARRAY) {
            return null;
        }
        long bytes = JobMemory.gridBytes(cells, read, plan.enlarged()) + (long) needs.perPixel() * tw * th
                + (long) needs.outputBytes() * band;
        return new TileLayout(tw, th, halo[0], halo[1], halo[2], halo[3], bytes);
    }

    /** Cells of the decimated read a resampled piece of {@code w × h} grid cells is made from (a margin included). */
    private static long readCells(PicturePlan plan, long w, long h) {
        double sx = (double) plan.decimatedWidth() / plan.gridWidth();
        double sy = (double) plan.decimatedHeight() / plan.gridHeight();
        return (long) ((Math.ceil(w * sx) + 5) * (Math.ceil(h * sy) + 5));
    }

    /** Cells read and rendered in all, and a constant per tile. */
    private double cost(PicturePlan plan) {
        long regionW = Math.min(plan.gridWidth(), (long) tileWidth + west + east);
        long regionH = Math.min(plan.gridHeight(), (long) tileHeight + north + south);
        return (double) columns(plan.width()) * rows(plan.height()) * (regionW * regionH + CELLS_PER_TILE);
    }

    private static long roundUp(long v, int unit) {
        return (v + unit - 1) / unit * unit;
    }
}
