package io.github.jdem846.projection;

import io.github.jdem846.output.ImageSink;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.RenderSettings;
import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.Future;

/**
 * Warps a picture laid on a grid into a {@link MapProjection}: each output pixel's centre is taken back through
 * the inverse projection to the grid's CRS, to a fractional pixel of the picture, and given the bilinear blend of
 * the four pixels around it. An RGBA picture's pixels are weighted by their alpha (premultiplied), so that
 * transparent no-data does not darken the edge; a gray picture's no-data pixels are left out of the blend (the
 * others' weights renormalised), as {@code gdalwarp -r bilinear -srcnodata} does. An output pixel whose point lies
 * off the projection's map (its forward projection does not come back within half a pixel) or outside the
 * picture's outer edges is transparent (gray: no-data, or 0 without one). A longitude/latitude picture spanning
 * 360° wraps around at its east and west edges.
 *
 * <p>Every pixel depends only on its own position, so the result is the same, byte for byte, for any number of
 * threads, and for a picture warped whole or {@linkplain #warpBands band by band}.
 */
public final class PictureWarp {

    private static final int ROWS_PER_TASK = 16;

    private PictureWarp() {
    }

    /**
     * Warps {@code argb} into {@code extent} of {@code projection}.
     *
     * @param argb       the picture, non-premultiplied 0xAARRGGBB, row 0 north; not modified
     * @param source     the grid the picture covers (one pixel per cell; its CRS must be known)
     * @param projection the projection of the output
     * @param extent     the output's extent in the projection's units
     * @param width      output pixels across
     * @param height     output pixels down
     * @param execution  threads, or a shared pool
     * @return the output, non-premultiplied 0xAARRGGBB, row 0 north
     * @throws InterruptedException when the calling thread is interrupted
     */
    public static int[] warp(int[] argb, GridGeometry source, MapProjection projection, ProjectedExtent extent,
                             int width, int height, RenderSettings execution) throws InterruptedException {
        checkSizes(argb.length, source, width, height);
        Rows rows = new Rows(GridMapping.of(source, projection), extent, width, height);
        Rgba sampler = new Rgba(argb, source, 0);
        int[] out = new int[width * height];
        rows.forEach(0, height, (row, col, sx, sy) -> out[row * width + col] = sampler.sample(sx, sy), execution);
        return out;
    }

    /**
     * Warps an 8-bit gray picture into {@code extent} of {@code projection}.
     *
     * @param gray       the picture, 0..255, row 0 north; not modified
     * @param noData     the gray value marking no-data (left out of the blend, and given to pixels off the map or
     *                   outside the picture), or null for none (then those pixels are 0)
     * @param source     the grid the picture covers (one pixel per cell; its CRS must be known)
     * @param projection the projection of the output
     * @param extent     the output's extent in the projection's units
     * @param width      output pixels across
     * @param height     output pixels down
     * @param execution  threads, or a shared pool
     * @return the output, row 0 north
     * @throws InterruptedException when the calling thread is interrupted
     */
    public static byte[] warpGray(byte[] gray, Integer noData, GridGeometry source, MapProjection projection,
                                  ProjectedExtent extent, int width, int height, RenderSettings execution)
            throws InterruptedException {
        checkSizes(gray.length, source, width, height);
        Rows rows = new Rows(GridMapping.of(source, projection), extent, width, height);
        Gray sampler = new Gray(gray, noData, source, 0);
        byte[] out = new byte[width * height];
        rows.forEach(0, height, (row, col, sx, sy) -> out[row * width + col] = (byte) sampler.sample(sx, sy),
                execution);
        return out;
    }

    /** Rows of a picture read on demand, for {@link #warpBands}. */
    public interface RowReader {

        /** {@return true for RGBA pixels, false for 8-bit gray} */
        boolean rgba();

        /**
         * Reads rows of an RGBA picture.
         *
         * @param first the first row
         * @param count how many
         * @return {@code count} full rows, non-premultiplied 0xAARRGGBB
         * @throws IOException when they cannot be read
         */
        int[] rgbaRows(int first, int count) throws IOException;

        /**
         * Reads rows of a gray picture.
         *
         * @param first the first row
         * @param count how many
         * @return {@code count} full rows of 0..255 samples
         * @throws IOException when they cannot be read
         */
        byte[] grayRows(int first, int count) throws IOException;
    }

    /**
     * Warps a picture read row window by row window into {@code sink}, band of output rows after band: for each
     * band the rows of the picture its pixels fall between are read, at most about half of {@code budget} bytes,
     * and the band (its pixels and their points in the picture's CRS, 16 bytes each) at most about a quarter. The pixels are those {@link #warp} or {@link #warpGray} give.
     *
     * @param source     the picture (as many rows as {@code grid} has)
     * @param noData     a gray picture's no-data value, or null (ignored for RGBA)
     * @param grid       the grid the picture covers
     * @param projection the projection of the output
     * @param extent     the output's extent
     * @param sink       the output, opened for {@code source}'s kind of pixels, its size the warp's
     * @param budget     the memory budget in bytes
     * @param execution  threads, or a shared pool
     * @throws IOException              when the picture cannot be read or the output written
     * @throws IllegalArgumentException when one output row needs more rows of the picture than the budget holds
     * @throws InterruptedException     when the calling thread is interrupted
     */
    public static void warpBands(RowReader source, Integer noData, GridGeometry grid, MapProjection projection,
                                 ProjectedExtent extent, ImageSink sink, long budget, RenderSettings execution)
            throws IOException, InterruptedException {
        int width = sink.width();
        int height = sink.height();
        checkSizes((long) grid.width() * grid.height(), grid, width, height);
        Rows rows = new Rows(GridMapping.of(grid, projection), extent, width, height);
        int pixelBytes = source.rgba() ? 4 : 1;
        GridPoint locator = new GridPoint(grid, 0);
        long maxWindowRows = Math.max(1, budget / 2 / ((long) grid.width() * pixelBytes));
        int bandRows = (int) Math.max(1, Math.min(height, budget / 4 / ((long) width * (pixelBytes + 16))));
        int first = 0;
        while (first < height) {
            int last = Math.min(height, first + bandRows);
            int[] lowest = new int[last - first];
            int[] highest = new int[last - first];
            Arrays.fill(lowest, Integer.MAX_VALUE);
            Arrays.fill(highest, Integer.MIN_VALUE);
            int top = first;
            double[] points = new double[2 * width * (last - first)];
            rows.forEach(first, last, (row, col, sx, sy) -> {
                int i = 2 * ((row - top) * width + col);
                points[i] = sx;
                points[i + 1] = sy;
                int r = locator.topRow(sx, sy);
                if (r != Integer.MIN_VALUE) {
                    lowest[row - top] = Math.min(lowest[row - top], r);
                    highest[row - top] = Math.max(highest[row - top], Math.min(grid.height() - 1, r + 1));
                }
            }, execution);
            int r0 = Arrays.stream(lowest).min().orElse(Integer.MAX_VALUE);
            int r1 = Arrays.stream(highest).max().orElse(Integer.MIN_VALUE);
            long windowRows = r1 >= r0 ? r1 - r0 + 1L : 0;
            if (windowRows > maxWindowRows) {
                if (last - first > 1) {
                    bandRows = Math.max(1, (last - first) / 2);
                    continue;
                }
                throw new IllegalArgumentException(String.format(java.util.Locale.ROOT, "row %d of the projected "
                        + "picture needs %d rows of the %d-pixel-wide rendered picture, more than the memory budget "
                        + "of %d MiB holds: give a larger memory budget", first, windowRows, grid.width(),
                        budget >> 20));
            }
            int n = last - first;
            if (source.rgba()) {
                Rgba sampler = new Rgba(windowRows == 0 ? new int[0] : source.rgbaRows(r0, (int) windowRows), grid,
                        windowRows == 0 ? 0 : r0);
                int[] band = new int[n * width];
                inTasks(n, i -> band[i] = sampler.sample(points[2 * i], points[2 * i + 1]), width, execution);
                sink.appendRgba(band, n);
            } else {
                Gray sampler = new Gray(windowRows == 0 ? new byte[0] : source.grayRows(r0, (int) windowRows),
                        noData, grid, windowRows == 0 ? 0 : r0);
                byte[] band = new byte[n * width];
                inTasks(n, i -> band[i] = (byte) sampler.sample(points[2 * i], points[2 * i + 1]), width,
                        execution);
                sink.appendGray(band, n);
            }
            first = last;
        }
    }

    /** Runs {@code pixel} for each index of {@code rows × width} pixels, in tasks of rows on the threads. */
    private static void inTasks(int rows, java.util.function.IntConsumer pixel, int width, RenderSettings execution)
            throws InterruptedException {
        List<Callable<Void>> tasks = new ArrayList<>();
        for (int r0 = 0; r0 < rows; r0 += ROWS_PER_TASK) {
            int from = r0 * width;
            int to = Math.min(rows, r0 + ROWS_PER_TASK) * width;
            tasks.add(() -> {
                for (int i = from; i < to; i++) {
                    pixel.accept(i);
                }
                return null;
            });
        }
        run(tasks, execution);
    }

    private static void checkSizes(long pixels, GridGeometry source, int width, int height) {
        if (pixels != (long) source.width() * source.height()) {
            throw new IllegalArgumentException("the picture has " + pixels + " pixels, its grid "
                    + source.width() + " × " + source.height());
        }
        if (width < 1 || height < 1 || (long) width * height > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("a projected picture needs 1 to 2^31 pixels, got " + width + " × "
                    + height);
        }
    }

    /** Told each output pixel's point in the source grid's CRS (NaN off the projection's map). */
    @FunctionalInterface
    private interface PixelVisitor {
        void visit(int row, int col, double sx, double sy);
    }

    /** The output's rows and their pixels' points in the source CRS. */
    private static final class Rows {
        private final GridMapping mapping;
        private final ProjectedExtent extent;
        private final int width;
        private final double pw;
        private final double ph;
        private final double tolerance;

        Rows(GridMapping mapping, ProjectedExtent extent, int width, int height) {
            this.mapping = mapping;
            this.extent = extent;
            this.width = width;
            this.pw = extent.width() / width;
            this.ph = extent.height() / height;
            this.tolerance = 0.5 * Math.max(pw, ph);
        }

        /**
         * Visits every pixel of rows [first, last), in tasks of {@value #ROWS_PER_TASK} rows on the threads; each
         * row's points are projected as one batch, so that they do not depend on how the rows are grouped.
         */
        void forEach(int first, int last, PixelVisitor visitor, RenderSettings execution)
                throws InterruptedException {
            List<Callable<Void>> tasks = new ArrayList<>();
            for (int r0 = first; r0 < last; r0 += ROWS_PER_TASK) {
                int from = r0;
                int to = Math.min(last, r0 + ROWS_PER_TASK);
                tasks.add(() -> {
                    double[] xy = new double[2 * width];
                    double[] back = new double[2 * width];
                    for (int row = from; row < to; row++) {
                        double y = extent.north() - (row + 0.5) * ph;
                        for (int col = 0; col < width; col++) {
                            xy[2 * col] = extent.west() + (col + 0.5) * pw;
                            xy[2 * col + 1] = y;
                        }
                        mapping.toSource(xy, width);
                        System.arraycopy(xy, 0, back, 0, 2 * width);
                        mapping.toTarget(back, width);
                        for (int col = 0; col < width; col++) {
                            double x = extent.west() + (col + 0.5) * pw;
                            boolean onMap = Math.abs(back[2 * col] - x) <= tolerance
                                    && Math.abs(back[2 * col + 1] - y) <= tolerance;
                            visitor.visit(row, col, onMap ? xy[2 * col] : Double.NaN,
                                    onMap ? xy[2 * col + 1] : Double.NaN);
                        }
                    }
                    return null;
                });
            }
            run(tasks, execution);
        }
    }

    private static void run(List<Callable<Void>> tasks, RenderSettings execution) throws InterruptedException {
        ForkJoinPool shared = execution.pool();
        ForkJoinPool pool = shared != null ? shared : new ForkJoinPool(execution.parallelism());
        try {
            List<Future<Void>> futures = new ArrayList<>();
            for (Callable<Void> task : tasks) {
                futures.add(pool.submit(task));
            }
            try {
                for (Future<Void> f : futures) {
                    f.get();
                }
            } catch (InterruptedException e) {
                futures.forEach(f -> f.cancel(false));
                throw e;
            } catch (ExecutionException e) {
                if (e.getCause() instanceof RuntimeException r) {
                    throw r;
                }
                throw new IllegalStateException(e.getCause());
            }
        } finally {
            if (shared == null) {
                pool.shutdownNow();
            }
        }
    }

    /**
     * A point of the grid's CRS as the four pixels around it: columns c0, c1 and rows r0, r1 (clamped at the
     * edges, wrapped around a 360° longitude/latitude grid) and their weights; the pixels held are the picture's
     * rows from {@code firstRow} on.
     */
    private static class GridPoint {
        final int w;
        final int h;
        final int firstRow;
        private final double originX;
        private final double originY;
        private final double cellWidth;
        private final double cellHeight;
        private final boolean wraps;

        GridPoint(GridGeometry g, int firstRow) {
            this.w = g.width();
            this.h = g.height();
            this.firstRow = firstRow;
            this.originX = g.originX();
            this.originY = g.originY();
            this.cellWidth = g.cellWidth();
            this.cellHeight = g.cellHeight();
            this.wraps = g.crs().isGeographic() && Math.abs(w * cellWidth - 360) < cellWidth / 2;
        }

        /** {@return the upper of the two rows sampled at the point, or MIN_VALUE when it is outside the picture} */
        final int topRow(double sx, double sy) {
            double[] uv = uv(sx, sy);
            return uv == null ? Integer.MIN_VALUE : Math.max(0, (int) Math.floor(uv[1]));
        }

        /** {@return the fractional pixel (u, v) of the point, or null outside the picture} */
        final double[] uv(double sx, double sy) {
            if (Double.isNaN(sx) || Double.isNaN(sy)) {
                return null;
            }
            double u = (sx - originX) / cellWidth - 0.5;
            double v = (originY - sy) / cellHeight - 0.5;
            if (wraps) {
                u = u - w * Math.floor((u + 0.5) / w); // into [−0.5, w − 0.5)
            }
            if (!(u >= -0.5 && u <= w - 0.5 && v >= -0.5 && v <= h - 0.5)) {
                return null;
            }
            return new double[] {u, v};
        }

        /** {@return the indices of the four pixels around (u, v) in the rows held: top left, top right, bottom left, bottom right} */
        final int[] corners(double u, double v) {
            int c0 = (int) Math.floor(u);
            int r0 = (int) Math.floor(v);
            int c1 = c0 + 1;
            int r1 = r0 + 1;
            if (wraps) {
                c0 = Math.floorMod(c0, w);
                c1 = Math.floorMod(c1, w);
            } else {
                c0 = Math.max(0, c0);
                c1 = Math.min(w - 1, c1);
            }
            r0 = Math.max(0, r0) - firstRow;
            r1 = Math.min(h - 1, r1) - firstRow;
            return new int[] {r0 * w + c0, r0 * w + c1, r1 * w + c0, r1 * w + c1};
        }

        static double[] weights(double u, double v) {
            double fx = u - Math.floor(u);
            double fy = v - Math.floor(v);
            return new double[] {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
        }
    }

    /** Bilinear, alpha-weighted sampling of an RGBA picture. */
    private static final class Rgba extends GridPoint {
        private final int[] argb;

        Rgba(int[] argb, GridGeometry g, int firstRow) {
            super(g, firstRow);
            this.argb = argb;
        }

        int sample(double sx, double sy) {
            double[] uv = uv(sx, sy);
            if (uv == null) {
                return 0;
            }
            int[] at = corners(uv[0], uv[1]);
            double[] wt = weights(uv[0], uv[1]);
            double a = 0;
            double red = 0;
            double green = 0;
            double blue = 0;
            for (int k = 0; k < 4; k++) {
                int px = argb[at[k]];
                double wa = wt[k] * (px >>> 24);
                a += wa;
                red += wa * ((px >> 16) & 0xFF);
                green += wa * ((px >> 8) & 0xFF);
                blue += wa * (px & 0xFF);
            }
            int alpha = (int) Math.round(a);
            if (alpha == 0) {
                return 0;
            }
            return alpha << 24 | channel(red / a) << 16 | channel(green / a) << 8 | channel(blue / a);
        }
    }

    /** Bilinear sampling of a gray picture, no-data left out and the others' weights renormalised. */
    private static final class Gray extends GridPoint {
        private final byte[] gray;
        private final int noData;
        private final boolean hasNoData;

        Gray(byte[] gray, Integer noData, GridGeometry g, int firstRow) {
            super(g, firstRow);
            this.gray = gray;
            this.hasNoData = noData != null;
            this.noData = noData != null ? noData : 0;
        }

        int sample(double sx, double sy) {
            double[] uv = uv(sx, sy);
            if (uv == null) {
                return noData;
            }
            int[] at = corners(uv[0], uv[1]);
            double[] wt = weights(uv[0], uv[1]);
            double sum = 0;
            double weight = 0;
            for (int k = 0; k < 4; k++) {
                int value = gray[at[k]] & 0xFF;
                if (!(hasNoData && value == noData) && wt[k] > 0) {
                    sum += wt[k] * value;
                    weight += wt[k];
                }
            }
            return weight == 0 ? noData : channel(sum / weight);
        }
    }

    private static int channel(double v) {
        return (int) Math.max(0, Math.min(255, Math.round(v)));
    }
}
