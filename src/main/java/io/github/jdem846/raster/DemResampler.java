package io.github.jdem846.raster;

/**
 * Resamples a DEM to an exact output size over the same extent, so that stages run at the output resolution
 * instead of computing at full size and shrinking the picture.
 *
 * <p>Shrinking is an area-weighted box filter: each output cell is the mean of the input cells it overlaps,
 * weighted by overlap area, over valid cells only (NaN when all of them are no-data). Enlarging is bilinear between
 * cell centres, edges clamped; a no-data corner makes the output cell no-data only when it carries the largest
 * weight, otherwise the valid corners are renormalised.
 */
public final class DemResampler {

    private DemResampler() {
    }

    /** Most cells of a resampled grid: the longest Java array. */
    static final long MAX_CELLS = Integer.MAX_VALUE - 8L;

    /**
     * {@code dem} resampled to {@code width × height} cells (returned as is when the size already matches).
     *
     * @throws IllegalArgumentException unless the size is at least 1×1 and at most {@link #MAX_CELLS} cells
     */
    public static Dem resample(Dem dem, int width, int height) {
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("output size must be at least 1×1, got " + width + "×" + height);
        }
        if ((long) width * height > MAX_CELLS) {
            throw new IllegalArgumentException("a grid of " + width + "×" + height + " = " + (long) width * height
                    + " cells is more than one Java array can hold (at most " + MAX_CELLS + ")");
        }
        if (width == dem.width() && height == dem.height()) {
            return dem;
        }
        GridGeometry g = dem.geometry();
        double sx = (double) dem.width() / width;
        double sy = (double) dem.height() / height;
        GridGeometry out = new GridGeometry(width, height, g.originX(), g.originY(), g.cellWidth() * sx,
                g.cellHeight() * sy, g.crs(), g.declaredAnchor());
        float[] values = new float[width * height];
        for (int r = 0; r < height; r++) {
            for (int c = 0; c < width; c++) {
                values[r * width + c] = (sx >= 1 && sy >= 1) ? boxMean(dem, c, r, sx, sy)
                        : sample(dem, (c + 0.5) * sx - 0.5, (r + 0.5) * sy - 0.5, sx, sy, c, r);
            }
        }
        return new Dem(values, out, dem.declaredNoData());
    }

    /** Mixed or enlarging scales: box mean along an axis that shrinks, bilinear along one that grows. */
    private static float sample(Dem dem, double x, double y, double sx, double sy, int c, int r) {
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
    static float bilinear(Dem dem, double x, double y) {
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

    private static float boxMean(Dem dem, int c, int r, double sx, double sy) {
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
