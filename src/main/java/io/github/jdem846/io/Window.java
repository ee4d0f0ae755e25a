package io.github.jdem846.io;

import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.GridRequestException;

/**
 * A part of a grid to read: a rectangle of cells, or a world bounding box in the grid's CRS units.
 * {@link #resolve} turns either into the cells to read.
 */
public sealed interface Window permits Window.Cells, Window.World {

    /**
     * The cells {@code [col, col+width) × [row, row+height)}; row 0 is north.
     *
     * @param col    first column, ≥ 0
     * @param row    first row (north), ≥ 0
     * @param width  columns, ≥ 1
     * @param height rows, ≥ 1
     * @return the window
     */
    static Cells cells(int col, int row, int width, int height) {
        return new Cells(col, row, width, height);
    }

    /**
     * The cells that intersect a world box, in the grid's CRS units.
     *
     * @param west  minimum x
     * @param south minimum y
     * @param east  maximum x, above {@code west}
     * @param north maximum y, above {@code south}
     * @return the window
     */
    static World world(double west, double south, double east, double north) {
        return new World(west, south, east, north);
    }

    /**
     * The cells of {@code grid} this window covers.
     *
     * @throws GridRequestException when the window is outside the grid (cells) or does not intersect it (world);
     *                               the message gives the grid's size or extent
     * @param grid the grid to read from
     * @return the cells to read
     */
    Cells resolve(GridGeometry grid);

    /**
     * A rectangle of cells; it must lie inside the grid.
     *
     * @param col    first column, ≥ 0
     * @param row    first row (north), ≥ 0
     * @param width  columns, ≥ 1
     * @param height rows, ≥ 1
     */
    record Cells(int col, int row, int width, int height) implements Window {
        /**
         * Checks that the first cell is at or after (0, 0) and the window at least one cell.
         *
         * @param col first column, ≥ 0
         * @param row first row (north), ≥ 0
         * @param width columns, ≥ 1
         * @param height rows, ≥ 1
         */
        public Cells {
            if (col < 0 || row < 0 || width < 1 || height < 1) {
                throw new IllegalArgumentException("a cell window needs col, row ≥ 0 and width, height ≥ 1, got "
                        + width + "×" + height + " at (" + col + ", " + row + ")");
            }
        }

        @Override
        public Cells resolve(GridGeometry grid) {
            if ((long) col + width > grid.width() || (long) row + height > grid.height()) {
                throw new GridRequestException(GridRequestException.Part.WINDOW, "window of " + width + "×" + height
                        + " cells at column " + col + ", row " + row + " is not inside the " + grid.width() + "×"
                        + grid.height() + " grid");
            }
            return this;
        }
    }

    /**
     * A world bounding box in the grid's CRS units; every cell it touches is read, clipped to the grid.
     *
     * @param west  minimum x
     * @param south minimum y
     * @param east  maximum x
     * @param north maximum y
     */
    record World(double west, double south, double east, double north) implements Window {
        /**
         * Checks that the edges are finite with west &lt; east and south &lt; north.
         *
         * @param west minimum x
         * @param south minimum y
         * @param east maximum x
         * @param north maximum y
         */
        public World {
            if (!(west < east) || !(south < north) || !Double.isFinite(west) || !Double.isFinite(east)
                    || !Double.isFinite(south) || !Double.isFinite(north)) {
                throw new IllegalArgumentException("a world window needs finite west < east and south < north, got"
                        + " west " + west + ", south " + south + ", east " + east + ", north " + north);
            }
        }

        @Override
        public Cells resolve(GridGeometry grid) {
            double c0 = (west - grid.originX()) / grid.cellWidth();
            double c1 = (east - grid.originX()) / grid.cellWidth();
            double r0 = (grid.originY() - north) / grid.cellHeight();
            double r1 = (grid.originY() - south) / grid.cellHeight();
            int col0 = (int) Math.max(0, Math.floor(snap(c0)));
            int col1 = (int) Math.min(grid.width(), Math.ceil(snap(c1)));
            int row0 = (int) Math.max(0, Math.floor(snap(r0)));
            int row1 = (int) Math.min(grid.height(), Math.ceil(snap(r1)));
            if (col1 <= col0 || row1 <= row0) {
                throw new GridRequestException(GridRequestException.Part.WINDOW, "world window west " + west
                        + ", south " + south + ", east " + east + ", north " + north + " does not intersect the "
                        + "grid's extent west " + grid.originX() + ", south " + grid.southY() + ", east "
                        + grid.eastX() + ", north " + grid.originY());
            }
            return new Cells(col0, row0, col1 - col0, row1 - row0);
        }

        /** Rounds values within 1e-9 cell of a whole number to it, so exact cell edges select no extra cell. */
        private static double snap(double cells) {
            double r = Math.rint(cells);
            return Math.abs(cells - r) < 1e-9 ? r : cells;
        }
    }
}
