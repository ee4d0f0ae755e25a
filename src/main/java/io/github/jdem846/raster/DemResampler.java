package io.github.jdem846.raster;

/**
 * Resamples a DEM to an exact output size over the same extent, so that stages run at the output resolution
 * instead of computing at full size and shrinking the picture.
 *
 * <p>Shrinking is an area-weighted box filter: each output cell is the mean of the input cells it overlaps,
 * weighted by overlap area, over valid cells only (NaN when all of them are no-data). Enlarging interpolates
 * between cell centres ({@link Upsampling}, by default {@link #DEFAULT_UPSAMPLING}) and anti-aliases the edges of
 * no-data: each output cell gets a coverage, the share of it that is data ({@link Dem#coverage}), from the bilinear
 * interpolation of "is data" (1 or 0 at each cell centre) steepened so that its 0.5 line, a smooth curve around
 * the data, is crossed in about one output cell; an output cell whose coverage is 0 is no-data. Mixed scales (one
 * axis shrinking, the other growing) average along the one and interpolate bilinearly along the other, edges
 * clamped; a no-data corner then makes the output cell no-data only when it carries the largest weight.
 */
public final class DemResampler {

    private DemResampler() {
    }

    /** The interpolation of enlargements unless told otherwise (docs/scale.md says why). */
    public static final Upsampling DEFAULT_UPSAMPLING = Upsampling.CLAMPED_CATMULL_ROM;

    /** Most cells of a resampled grid: the longest Java array. */
    static final long MAX_CELLS = Integer.MAX_VALUE - 8L;

    /**
     * {@code dem} resampled to {@code width × height} cells (returned as is when the size already matches), enlarged
     * (if it is) by {@link #DEFAULT_UPSAMPLING}.
     *
     * @param dem the grid
     * @param width columns of the result
     * @param height rows of the result
     * @return the resampled grid, or {@code dem} itself
     * @throws IllegalArgumentException unless the size is at least 1×1 and at most {@link #MAX_CELLS} cells
     */
    public static Dem resample(Dem dem, int width, int height) {
        return resample(dem, width, height, DEFAULT_UPSAMPLING);
    }

    /**
     * {@code dem} resampled to {@code width × height} cells, enlarged (if it is) by {@code upsampling}.
     *
     * @param dem        the grid
     * @param width      columns after, ≥ 1
     * @param height     rows after, ≥ 1
     * @param upsampling the interpolation of an enlargement
     * @return the resampled grid ({@code dem} itself when the size already matches)
     * @throws IllegalArgumentException unless the size is at least 1×1 and at most {@link #MAX_CELLS} cells
     */
    public static Dem resample(Dem dem, int width, int height, Upsampling upsampling) {
        requireSize(width, height);
        if (width == dem.width() && height == dem.height()) {
            return dem;
        }
        return resampleRegion(dem, 0, 0, dem.width(), dem.height(), width, height, 0, 0, width, height,
                resampledGeometry(dem.geometry(), width, height), upsampling);
    }

    /**
     * The geometry of {@code g} resampled to {@code width × height} cells over the same extent (that of {@link
     * #resample}, computed the same way).
     *
     * @param g      the grid before resampling
     * @param width  columns after, ≥ 1
     * @param height rows after, ≥ 1
     * @return the new grid's geometry, a root grid of its own, with ground cell sizes when {@code g} has them
     */
    public static GridGeometry resampledGeometry(GridGeometry g, int width, int height) {
        double sx = (double) g.width() / width;
        double sy = (double) g.height() / height;
        GridGeometry resampled = new GridGeometry(width, height, g.originX(), g.originY(), g.cellWidth() * sx,
                g.cellHeight() * sy, g.crs(), g.declaredAnchor());
        return g.hasGroundCellSizes() ? resampled.withGroundCellSizes() : resampled;
    }

    /**
     * The cells {@code [col, col + w) × [row, row + h)} of a {@code fullWidth × fullHeight} grid resampled to
     * {@code width × height}, from a part of that grid only: {@code part} holds its cells from column {@code
     * partCol}, row {@code partRow} on. The values are those of the same cells of {@link #resample} of the whole
     * grid, bit for bit, when {@code part} covers what they read ({@link #sourceSpan}); this is how a picture too
     * large for memory is resampled piece by piece.
     *
     * @param part       cells of the full grid
     * @param partCol    the full grid's column of {@code part}'s first
     * @param partRow    the full grid's row of {@code part}'s first
     * @param fullWidth  columns of the full grid
     * @param fullHeight rows of the full grid
     * @param width      columns of the resampled grid
     * @param height     rows of the resampled grid
     * @param col        first column of the resampled grid wanted
     * @param row        first row wanted
     * @param w          columns wanted
     * @param h          rows wanted
     * @param geometry   the geometry of the cells wanted ({@code w × h})
     * @param upsampling the interpolation of an enlargement
     * @return the cells wanted, with their coverage when enlarged
     * @throws IllegalArgumentException when the sizes are not positive or the cells are outside the resampled grid
     */
    public static Dem resampleRegion(Dem part, int partCol, int partRow, int fullWidth, int fullHeight,
                                     int width, int height, int col, int row, int w, int h, GridGeometry geometry,
                                     Upsampling upsampling) {
        requireSize(width, height);
        int c0 = col;
        int r0 = row;
        if (c0 < 0 || r0 < 0 || w < 1 || h < 1 || (long) c0 + w > width || (long) r0 + h > height) {
            throw new IllegalArgumentException("region " + w + "×" + h + " at (" + c0 + ", " + r0
                    + ") is not inside the " + width + "×" + height + " output");
        }
        Source src = new Source(part, partCol, partRow, fullWidth, fullHeight);
        double sx = (double) fullWidth / width;
        double sy = (double) fullHeight / height;
        float[] values = new float[w * h];
        if (sx < 1 && sy < 1) {
            return enlarge(src, sx, sy, c0, r0, w, h, geometry, upsampling);
        }
        for (int r = r0; r < r0 + h; r++) {
            for (int c = c0; c < c0 + w; c++) {
                values[(r - r0) * w + c - c0] = (sx >= 1 && sy >= 1) ? boxMean(src, c, r, sx, sy)
                        : sample(src, (c + 0.5) * sx - 0.5, (r + 0.5) * sy - 0.5, sx, sy, c, r);
            }
        }
        return Dem.ofNormalized(values, geometry, part.declaredNoData());
    }

    /** The enlarged cells with their coverage (none kept when every cell is whole data or none). */
    private static Dem enlarge(Source src, double sx, double sy, int c0, int r0, int w, int h, GridGeometry geometry,
                               Upsampling upsampling) {
        float[] values = new float[w * h];
        float[] coverage = new float[w * h];
        boolean partial = false;
        // output cells per input cell along the slower axis: the coverage's 0.5 line is crossed in about one cell
        double steepness = 1 / Math.max(sx, sy);
        for (int r = r0; r < r0 + h; r++) {
            double yc = (r + 0.5) * sy - 0.5;
            double y = Math.max(0, Math.min(src.height() - 1, yc));
            for (int c = c0; c < c0 + w; c++) {
                double xc = (c + 0.5) * sx - 0.5;
                double x = Math.max(0, Math.min(src.width() - 1, xc));
                int i = (r - r0) * w + c - c0;
                double share = dataShare(src, x, y);
                float alpha = (float) Math.max(0, Math.min(1, (share - 0.5) * steepness + 0.5));
                coverage[i] = alpha;
                partial |= alpha > 0 && alpha < 1;
                if (alpha == 0) {
                    values[i] = Float.NaN;
                } else if (upsampling != Upsampling.BILINEAR) {
                    values[i] = Bicubic.at(src::get, src.width(), src.height(), xc, yc, upsampling);
                } else {
                    values[i] = bilinearOfData(src, x, y);
                }
            }
        }
        Dem dem = Dem.ofNormalized(values, geometry, src.part().declaredNoData());
        return partial ? dem.withCoverage(coverage) : dem;
    }

    /** The bilinear interpolation of "is data" at (x, y), inside the grid. */
    private static double dataShare(Source dem, double x, double y) {
        int c = (int) Math.floor(x);
        int r = (int) Math.floor(y);
        int c1 = Math.min(c + 1, dem.width() - 1);
        int r1 = Math.min(r + 1, dem.height() - 1);
        double fx = x - c;
        double fy = y - r;
        return (1 - fx) * (1 - fy) * isData(dem.get(c, r)) + fx * (1 - fy) * isData(dem.get(c1, r))
                + (1 - fx) * fy * isData(dem.get(c, r1)) + fx * fy * isData(dem.get(c1, r1));
    }

    private static double isData(float v) {
        return Float.isNaN(v) ? 0 : 1;
    }

    /** Bilinear over the corners that are data, renormalised (NaN when none is), inside the grid. */
    static float bilinearOfData(Bicubic.Cells dem, int width, int height, double x, double y) {
        int c = (int) Math.floor(x);
        int r = (int) Math.floor(y);
        int c1 = Math.min(c + 1, width - 1);
        int r1 = Math.min(r + 1, height - 1);
        double fx = x - c;
        double fy = y - r;
        double[] wts = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
        float[] vs = {dem.get(c, r), dem.get(c1, r), dem.get(c, r1), dem.get(c1, r1)};
        double sum = 0;
        double wsum = 0;
        for (int i = 0; i < 4; i++) {
            if (!Float.isNaN(vs[i]) && wts[i] > 0) {
                sum += wts[i] * vs[i];
                wsum += wts[i];
            }
        }
        return wsum == 0 ? Float.NaN : (float) (sum / wsum);
    }

    private static float bilinearOfData(Source src, double x, double y) {
        return bilinearOfData(src::get, src.width(), src.height(), x, y);
    }

    /**
     * The cells of the full grid that output cells {@code [first, first + count)} of one axis read, as
     * {start, end}: {@code full} cells resampled to {@code out}, clipped to the grid (with a cell's margin for
     * the bilinear neighbours and rounding).
     *
     * @param full  cells of the full grid along the axis
     * @param out   cells of the resampled grid along the axis
     * @param first first output cell
     * @param count output cells
     * @return {start, end} (end exclusive) in the full grid
     */
    public static int[] sourceSpan(int full, int out, int first, int count) {
        double s = (double) full / out;
        long a = (long) Math.floor(first * s) - 2;
        long b = (long) Math.ceil((first + (long) count) * s) + 2;
        return new int[] {(int) Math.max(0, a), (int) Math.min(full, b)};
    }

    private static void requireSize(int width, int height) {
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("output size must be at least 1×1, got " + width + "×" + height);
        }
        if ((long) width * height > MAX_CELLS) {
            throw new IllegalArgumentException("a grid of " + width + "×" + height + " = " + (long) width * height
                    + " cells is more than one Java array can hold (at most " + MAX_CELLS + ")");
        }
    }

    /** The full grid read through a part of it: cell (c, r) of the full grid is ({@code c − col}, {@code r − row}). */
    private record Source(Dem part, int col, int row, int width, int height) {
        float get(int c, int r) {
            return part.get(c - col, r - row);
        }
    }

    /** Mixed or enlarging scales: box mean along an axis that shrinks, bilinear along one that grows. */
    private static float sample(Source dem, double x, double y, double sx, double sy, int c, int r) {
        if (sx >= 1 || sy >= 1) {
            // one axis shrinks: average along it, interpolate along the other by splitting into a bilinear mean
            double sum = 0;
            double wsum = 0;
            double x0 = sx >= 1 ? c * sx : x;
            double x1 = sx >= 1 ? (c + 1) * sx : x;
            double y0 = sy >= 1 ? r * sy : y;
            double y1 = sy >= 1 ? (r + 1) * sy : y;
            int steps = 8;
            for (int i = 0; i < steps; i++) {
                double xi = sx >= 1 ? x0 + (i + 0.5) * (x1 - x0) / steps - 0.5 : x;
                for (int j = 0; j < steps; j++) {
                    double yj = sy >= 1 ? y0 + (j + 0.5) * (y1 - y0) / steps - 0.5 : y;
                    float v = bilinear(dem, xi, yj);
                    if (!Float.isNaN(v)) {
                        sum += v;
                        wsum++;
                    }
                }
            }
            return wsum == 0 ? Float.NaN : (float) (sum / wsum);
        }
        return bilinear(dem, x, y);
    }

    /** Bilinear value at fractional cell-centre coordinates, edges clamped, no-data corners renormalised. */
    private static float bilinear(Source dem, double x, double y) {
        int w = dem.width();
        int h = dem.height();
        x = Math.max(0, Math.min(w - 1, x));
        y = Math.max(0, Math.min(h - 1, y));
        int c0 = (int) Math.floor(x);
        int r0 = (int) Math.floor(y);
        int c1 = Math.min(c0 + 1, w - 1);
        int r1 = Math.min(r0 + 1, h - 1);
        double fx = x - c0;
        double fy = y - r0;
        double[] wts = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
        float[] vs = {dem.get(c0, r0), dem.get(c1, r0), dem.get(c0, r1), dem.get(c1, r1)};
        double sum = 0;
        double wsum = 0;
        double maxW = -1;
        boolean maxIsNoData = false;
        for (int i = 0; i < 4; i++) {
            if (wts[i] > maxW) {
                maxW = wts[i];
                maxIsNoData = Float.isNaN(vs[i]);
            }
            if (!Float.isNaN(vs[i])) {
                sum += wts[i] * vs[i];
                wsum += wts[i];
            }
        }
        if (maxIsNoData || wsum == 0) {
            return Float.NaN;
        }
        return (float) (sum / wsum);
    }

    private static float boxMean(Source dem, int c, int r, double sx, double sy) {
        double x0 = c * sx;
        double x1 = Math.min(dem.width(), (c + 1) * sx);
        double y0 = r * sy;
        double y1 = Math.min(dem.height(), (r + 1) * sy);
        double sum = 0;
        double wsum = 0;
        for (int ir = (int) Math.floor(y0); ir < y1; ir++) {
            double wy = Math.min(y1, ir + 1) - Math.max(y0, ir);
            if (wy <= 0) {
                continue;
            }
            for (int ic = (int) Math.floor(x0); ic < x1; ic++) {
                double wx = Math.min(x1, ic + 1) - Math.max(x0, ic);
                float v = dem.get(ic, ir);
                if (wx > 0 && !Float.isNaN(v)) {
                    sum += wx * wy * v;
                    wsum += wx * wy;
                }
            }
        }
        return wsum == 0 ? Float.NaN : (float) (sum / wsum);
    }
}
