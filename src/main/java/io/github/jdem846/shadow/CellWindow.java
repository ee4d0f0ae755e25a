package io.github.jdem846.shadow;

/**
 * A rectangle of cells: columns [{@code col}, {@code col + width}) × rows [{@code row}, {@code row + height}).
 *
 * @param col    first column
 * @param row    first row (row 0 = north)
 * @param width  number of columns, ≥ 1
 * @param height number of rows, ≥ 1
 */
public record CellWindow(int col, int row, int width, int height) {

    /**
     * Checks that the window has at least one column and one row.
     *
     * @param col first column
     * @param row first row (row 0 = north)
     * @param width number of columns, ≥ 1
     * @param height number of rows, ≥ 1
     */
    public CellWindow {
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("a cell window needs at least 1×1 cells, got " + width + "×" + height);
        }
    }

    /**
     * The whole grid of {@code width × height} cells.
     *
     * @param width number of columns, ≥ 1
     * @param height number of rows, ≥ 1
     * @return the window from cell (0, 0) over all cells
     */
    public static CellWindow whole(int width, int height) {
        return new CellWindow(0, 0, width, height);
    }

    /**
     * One past the last column.
     *
     * @return {@code col + width}
     */
    public int colEnd() {
        return col + width;
    }

    /**
     * One past the last row.
     *
     * @return {@code row + height}
     */
    public int rowEnd() {
        return row + height;
    }

    /**
     * True when the window lies inside a grid of {@code gridWidth × gridHeight} cells.
     *
     * @param gridWidth the grid's number of columns
     * @param gridHeight the grid's number of rows
     * @return whether every cell of the window is a cell of the grid
     */
    public boolean isInside(int gridWidth, int gridHeight) {
        return col >= 0 && row >= 0 && colEnd() <= gridWidth && rowEnd() <= gridHeight;
    }

    /**
     * True when cell ({@code c}, {@code r}) is in the window.
     *
     * @param c column
     * @param r row
     * @return whether the cell is in the window
     */
    public boolean contains(int c, int r) {
        return c >= col && c < colEnd() && r >= row && r < rowEnd();
    }

    /**
     * The number of cells.
     *
     * @return {@code width × height}, as a long
     */
    public long cellCount() {
        return (long) width * height;
    }
}
