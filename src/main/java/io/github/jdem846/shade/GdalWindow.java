package io.github.jdem846.shade;

/**
 * The 3×3 window around a cell exactly as gdaldem 3.6 builds it with {@code -compute_edges}
 * ({@code GDALGeneric3x3Processing} and {@code ComputeVal} in apps/gdaldem_lib.cpp), indices
 * <pre>
 *   0 1 2      NW N NE
 *   3 4 5  =   W  C  E
 *   6 7 8      SW S SE
 * </pre>
 * <ul>
 *   <li>inside the grid: the 9 cells;</li>
 *   <li>first and last column (rows 1 … H−2): the missing column is extrapolated, 2·edge − next, row by row;</li>
 *   <li>first and last row: the missing row is extrapolated, 2·edge − next, column by column, and in these rows
 *       a missing column (the four corner cells) is the edge column repeated, not extrapolated (gdaldem's quirk:
 *       the corner cells get half the east–west gradient);</li>
 *   <li>an extrapolation from a no-data value is no-data; then every no-data value in the window is replaced by
 *       the centre (the centre itself no-data → the cell is no-data).</li>
 * </ul>
 * Generalisation where gdaldem writes no-data: a grid 1 cell wide or high repeats the edge (zero gradient along
 * that axis).
 */
final class GdalWindow {

    private GdalWindow() {
    }

    /**
     * Fills {@code win} for cell ({@code c}, {@code r}) of the row-major grid {@code v} ({@code width × height},
     * NaN = no-data).
     *
     * @return false when the centre is no-data ({@code win} is then undefined)
     */
    static boolean fill(float[] v, int width, int height, int c, int r, double[] win) {
        final int at = r * width + c;
        final double centre = v[at];
        if (centre != centre) {
            return false;
        }
        if (c < 1 || c > width - 2 || r < 1 || r > height - 2) {
            return fillAtEdge(v, width, height, c, r, centre, win);
        }
        // Inside the grid: the nine cells. Kept small, so that the JIT inlines it into the kernels' loops.
        int i = at - width - 1;
        final double w0 = v[i];
        final double w1 = v[i + 1];
        final double w2 = v[i + 2];
        i += width;
        final double w3 = v[i];
        final double w5 = v[i + 2];
        i += width;
        final double w6 = v[i];
        final double w7 = v[i + 1];
        final double w8 = v[i + 2];
        win[0] = w0;
        win[1] = w1;
        win[2] = w2;
        win[3] = w3;
        win[4] = centre;
        win[5] = w5;
        win[6] = w6;
        win[7] = w7;
        win[8] = w8;
        final double sum = w0 + w1 + w2 + w3 + w5 + w6 + w7 + w8;
        if (sum != sum) {
            replaceNoData(win, centre); // a NaN, or +∞ and −∞ together (then nothing to replace)
        }
        return true;
    }

    /** {@link #fill} for a cell on the first or last row or column. */
    private static boolean fillAtEdge(float[] v, int width, int height, int c, int r, double centre,
                                      double[] win) {
        if (height == 1 || r == 0 || r == height - 1) {
            final int jmin = c == 0 ? c : c - 1;
            final int jmax = c == width - 1 ? c : c + 1;
            if (height == 1) {
                rowAt(v, width, 0, jmin, c, jmax, win, 0);
                rowAt(v, width, 0, jmin, c, jmax, win, 3);
                rowAt(v, width, 0, jmin, c, jmax, win, 6);
            } else if (r == 0) {
                rowAt(v, width, 0, jmin, c, jmax, win, 3);
                rowAt(v, width, 1, jmin, c, jmax, win, 6);
                win[0] = interpol(win[3], win[6]);
                win[1] = interpol(win[4], win[7]);
                win[2] = interpol(win[5], win[8]);
            } else {
                rowAt(v, width, r - 1, jmin, c, jmax, win, 0);
                rowAt(v, width, r, jmin, c, jmax, win, 3);
                win[6] = interpol(win[3], win[0]);
                win[7] = interpol(win[4], win[1]);
                win[8] = interpol(win[5], win[2]);
            }
        } else {
            // Rows 1 … H−2 on the first or last column.
            for (int k = 0; k < 3; k++) {
                final int row = (r - 1 + k) * width;
                final double mid = v[row + c];
                final double west;
                final double east;
                if (width == 1) {
                    west = mid;
                    east = mid;
                } else if (c == 0) {
                    east = v[row + 1];
                    west = interpol(mid, east);
                } else {
                    west = v[row + c - 1];
                    east = c == width - 1 ? interpol(mid, west) : v[row + c + 1];
                }
                win[3 * k] = west;
                win[3 * k + 1] = mid;
                win[3 * k + 2] = east;
            }
        }
        replaceNoData(win, centre);
        return true;
    }

    /** Every no-data value of the window becomes the centre's. */
    private static void replaceNoData(double[] win, double centre) {
        for (int k = 0; k < 9; k++) {
            if (Double.isNaN(win[k])) {
                win[k] = centre;
            }
        }
    }

    private static void rowAt(float[] v, int width, int row, int jmin, int j, int jmax, double[] win, int at) {
        final int base = row * width;
        win[at] = v[base + jmin];
        win[at + 1] = v[base + j];
        win[at + 2] = v[base + jmax];
    }

    /** gdaldem's INTERPOL: the value beyond {@code a}, away from {@code b}, on their line; no-data if either is. */
    private static double interpol(double a, double b) {
        return 2 * a - b; // NaN propagates
    }
}
