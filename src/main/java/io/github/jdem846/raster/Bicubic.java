package io.github.jdem846.raster;

/**
 * Bicubic interpolation between cell centres ({@link Upsampling#CATMULL_ROM}, {@link
 * Upsampling#CLAMPED_CATMULL_ROM}, {@link Upsampling#MONOTONE_CUBIC}): four cells along x in each of four rows,
 * then the four row values along y. A neighbour beyond the grid's edge or no-data is extended linearly from the two
 * cells next to it (2·p0 − p1), which keeps a plane a plane up to the edge; when a cell of the inner 2 × 2 is
 * no-data the value is bilinear over those that are data.
 */
final class Bicubic {

    /** Cells read by (column, row), inside the grid. */
    @FunctionalInterface
    interface Cells {
        float get(int col, int row);
    }

    private Bicubic() {
    }

    /**
     * The interpolated value at (x, y), in cell-centre coordinates: inside the grid, or up to half a cell beyond
     * its outer cell centres (the outer half of the edge cells), where it goes on linearly with the slope at the
     * last centre.
     *
     * @param cells  the grid's cells
     * @param width  columns
     * @param height rows
     * @param x      column coordinate
     * @param y      row coordinate
     * @param kernel the cubic: any {@link Upsampling} but {@link Upsampling#BILINEAR}
     * @return the value, NaN when no corner of the inner 2 × 2 is data
     */
    static float at(Cells cells, int width, int height, double x, double y, Upsampling kernel) {
        int c = Math.max(0, Math.min(width - 2, (int) Math.floor(x)));
        int r = Math.max(0, Math.min(height - 2, (int) Math.floor(y)));
        int c1 = Math.min(c + 1, width - 1);
        int r1 = Math.min(r + 1, height - 1);
        if (Float.isNaN(cells.get(c, r)) || Float.isNaN(cells.get(c1, r)) || Float.isNaN(cells.get(c, r1))
                || Float.isNaN(cells.get(c1, r1))) {
            return DemResampler.bilinearOfData(cells, width, height, Math.max(0, Math.min(width - 1, x)),
                    Math.max(0, Math.min(height - 1, y)));
        }
        boolean monotone = kernel == Upsampling.MONOTONE_CUBIC;
        double tx = x - c;
        double ty = y - r;
        double inner0 = row(cells, width, c, r, tx, monotone);
        double inner1 = row(cells, width, c, r1, tx, monotone);
        double above = r - 1 >= 0 ? row(cells, width, c, r - 1, tx, monotone) : Double.NaN;
        double below = r + 2 < height ? row(cells, width, c, r + 2, tx, monotone) : Double.NaN;
        double v = cubic(Double.isNaN(above) ? 2 * inner0 - inner1 : above, inner0, inner1,
                Double.isNaN(below) ? 2 * inner1 - inner0 : below, ty, monotone);
        boolean inside = tx >= 0 && tx <= 1 && ty >= 0 && ty <= 1;
        return (float) (kernel == Upsampling.CLAMPED_CATMULL_ROM && inside ? clamped(cells, width, height, c, r, v)
                : v);
    }

    /**
     * {@code v} within the lowest and highest cells of the 4 × 4 around cell (c, r) that are data (not beyond the
     * outer cell centres, where the surface goes on linearly).
     */
    private static double clamped(Cells cells, int width, int height, int c, int r, double v) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (int j = Math.max(0, r - 1); j <= Math.min(height - 1, r + 2); j++) {
            for (int i = Math.max(0, c - 1); i <= Math.min(width - 1, c + 2); i++) {
                float p = cells.get(i, j);
                if (!Float.isNaN(p)) {
                    lo = Math.min(lo, p);
                    hi = Math.max(hi, p);
                }
            }
        }
        return v < lo ? lo : v > hi ? hi : v;
    }

    /** Row {@code r} interpolated at {@code c + t}; NaN when one of its two inner cells is no-data. */
    private static double row(Cells cells, int width, int c, int r, double t, boolean monotone) {
        double p0 = cells.get(c, r);
        double p1 = c + 1 < width ? cells.get(c + 1, r) : p0;
        if (Double.isNaN(p0) || Double.isNaN(p1)) {
            return Double.NaN;
        }
        double left = c - 1 >= 0 ? cells.get(c - 1, r) : Double.NaN;
        double right = c + 2 < width ? cells.get(c + 2, r) : Double.NaN;
        return cubic(Double.isNaN(left) ? 2 * p0 - p1 : left, p0, p1, Double.isNaN(right) ? 2 * p1 - p0 : right, t,
                monotone);
    }

    /**
     * The cubic through p0 (t = 0) and p1 (t = 1): Catmull-Rom, or monotone. Below 0 or above 1 (only in the edge
     * cells, where the neighbour beyond is the linear extension, so that the tangent there is p1 − p0 for both
     * cubics) it goes on along that tangent.
     */
    private static double cubic(double pm1, double p0, double p1, double p2, double t, boolean monotone) {
        if (t < 0) {
            return p0 + t * (p1 - p0);
        }
        if (t > 1) {
            return p1 + (t - 1) * (p1 - p0);
        }
        return monotone ? monotone(pm1, p0, p1, p2, t) : catmullRom(pm1, p0, p1, p2, t);
    }

    /** The Catmull-Rom cubic through p0 (t = 0) and p1 (t = 1), tangents (p1 − pm1)/2 and (p2 − p0)/2. */
    static double catmullRom(double pm1, double p0, double p1, double p2, double t) {
        double t2 = t * t;
        double t3 = t2 * t;
        return 0.5 * ((-t3 + 2 * t2 - t) * pm1 + (3 * t3 - 5 * t2 + 2) * p0 + (-3 * t3 + 4 * t2 + t) * p1
                + (t3 - t2) * p2);
    }

    /**
     * The cubic Hermite through p0 (t = 0) and p1 (t = 1) whose tangent at each is the harmonic mean of the slopes
     * on either side, or 0 where they differ in sign (Fritsch and Butland, 1984): it never leaves [p0, p1], and
     * keeps a plane a plane.
     */
    static double monotone(double pm1, double p0, double p1, double p2, double t) {
        double s = p1 - p0;
        double d0 = tangent(p0 - pm1, s);
        double d1 = tangent(s, p2 - p1);
        double t2 = t * t;
        double t3 = t2 * t;
        return (2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * d0 + (-2 * t3 + 3 * t2) * p1 + (t3 - t2) * d1;
    }

    /** The harmonic mean of two slopes of one sign, else 0. */
    private static double tangent(double before, double after) {
        return before * after > 0 ? 2 * before * after / (before + after) : 0;
    }
}
