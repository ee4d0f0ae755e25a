package io.github.jdem846.shade;

/**
 * Where the row kernels ({@link HornRows}, {@link JDem846Rows}) apply in one rectangle of a grid: the runs of cells
 * whose whole 3×3 window lies inside the grid and holds only finite numbers (no no-data, no infinity). Every other
 * cell takes its method's per-cell path. Each input row of the rectangle (and its halo) is tested once; only a
 * band of three rows with a non-finite value in it is looked at column by column.
 */
final class FiniteWindows {

    private final float[] v;
    private final int width;
    private final int height;
    private final int row0;
    /** Interior columns of the rectangle: [first, end). */
    private final int first;
    private final int end;
    /** finiteRow[i]: row {@code row0 − 1 + i} is finite over columns [first − 1, end + 1). */
    private final boolean[] finiteRow;

    /**
     * @param v     the grid, row-major, NaN = no-data
     * @param width grid width
     * @param height grid height
     * @param col0  first column of the rectangle
     * @param row0  first row of the rectangle
     * @param w     columns of the rectangle
     * @param h     rows of the rectangle
     * @param allFinite every cell of the grid is known to be finite: no row is looked at
     */
    FiniteWindows(float[] v, int width, int height, int col0, int row0, int w, int h, boolean allFinite) {
        this.v = v;
        this.width = width;
        this.height = height;
        this.row0 = row0;
        this.first = Math.max(col0, 1);
        this.end = Math.min(col0 + w, width - 1);
        this.finiteRow = new boolean[h + 2];
        if (first < end) {
            for (int i = 0; i < h + 2; i++) {
                final int row = row0 - 1 + i;
                finiteRow[i] = row >= 0 && row < height
                        && (allFinite || allFinite(v, row * width + first - 1, row * width + end + 1));
            }
        }
    }

    /** The size {@link #runs} needs for a rectangle {@code w} cells wide. */
    static int runsLength(int w) {
        return w + 2;
    }

    /**
     * The runs of row {@code r} (a row of the rectangle) as pairs of columns [start, end) in {@code runs}, left to
     * right.
     *
     * @param runs receives the pairs; at least {@link #runsLength} long
     * @return the number of ints written, twice the number of runs
     */
    int runs(int r, int[] runs) {
        if (r < 1 || r > height - 2 || first >= end) {
            return 0;
        }
        final int i = r - row0;
        if (finiteRow[i] && finiteRow[i + 1] && finiteRow[i + 2]) {
            runs[0] = first;
            runs[1] = end;
            return 2;
        }
        final int top = (r - 1) * width;
        int n = 0;
        int start = -1;
        boolean previous = finiteColumn(top, first - 1);
        boolean current = finiteColumn(top, first);
        for (int c = first; c < end; c++) {
            final boolean next = finiteColumn(top, c + 1);
            final boolean clean = previous && current && next;
            if (clean && start < 0) {
                start = c;
            } else if (!clean && start >= 0) {
                runs[n++] = start;
                runs[n++] = c;
                start = -1;
            }
            previous = current;
            current = next;
        }
        if (start >= 0) {
            runs[n++] = start;
            runs[n++] = end;
        }
        return n;
    }

    /** Column {@code c} of the three rows from {@code top} is finite. */
    private boolean finiteColumn(int top, int c) {
        return Float.isFinite(v[top + c]) && Float.isFinite(v[top + width + c])
                && Float.isFinite(v[top + 2 * width + c]);
    }

    private static boolean allFinite(float[] v, int from, int to) {
        for (int i = from; i < to; i++) {
            if (!Float.isFinite(v[i])) {
                return false;
            }
        }
        return true;
    }
}
