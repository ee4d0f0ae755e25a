package io.github.jdem846.projection;

import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.RenderSettings;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.Future;

/**
 * Warps an ARGB picture laid on a grid into a {@link MapProjection}: each output pixel's centre is taken back
 * through the inverse projection to the grid's CRS, to a fractional pixel of the picture, and given the bilinear
 * blend of the four pixels around it, weighted by their alpha (premultiplied), so that transparent no-data does
 * not darken the edge. An output pixel whose point lies off the projection's map (its forward projection does not
 * come back within half a pixel) or outside the picture's outer edges is transparent. A longitude/latitude picture
 * spanning 360° wraps around at its east and west edges.
 *
 * <p>Every pixel depends only on its own position, so the result is the same, byte for byte, for any number of
 * threads.
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
        if (argb.length != (long) source.width() * source.height()) {
            throw new IllegalArgumentException("the picture has " + argb.length + " pixels, its grid "
                    + source.width() + " × " + source.height());
        }
        if (width < 1 || height < 1 || (long) width * height > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("a projected picture needs 1 to 2^31 pixels, got " + width + " × "
                    + height);
        }
        GridMapping mapping = GridMapping.of(source, projection);
        Sampler sampler = new Sampler(argb, source);
        int[] out = new int[width * height];
        double pw = extent.width() / width;
        double ph = extent.height() / height;
        double tolerance = 0.5 * Math.max(pw, ph);
        List<Callable<Void>> tasks = new ArrayList<>();
        for (int r0 = 0; r0 < height; r0 += ROWS_PER_TASK) {
            int first = r0;
            int last = Math.min(height, r0 + ROWS_PER_TASK);
            tasks.add(() -> {
                double[] xy = new double[2 * width];
                double[] back = new double[2 * width];
                for (int row = first; row < last; row++) {
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
                        out[row * width + col] = onMap ? sampler.sample(xy[2 * col], xy[2 * col + 1]) : 0;
                    }
                }
                return null;
            });
        }
        run(tasks, execution);
        return out;
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

    /** Bilinear, alpha-weighted sampling of the picture at a point of its grid's CRS. */
    private static final class Sampler {
        private final int[] argb;
        private final int w;
        private final int h;
        private final double originX;
        private final double originY;
        private final double cellWidth;
        private final double cellHeight;
        private final boolean wraps;

        Sampler(int[] argb, GridGeometry g) {
            this.argb = argb;
            this.w = g.width();
            this.h = g.height();
            this.originX = g.originX();
            this.originY = g.originY();
            this.cellWidth = g.cellWidth();
            this.cellHeight = g.cellHeight();
            this.wraps = g.crs().isGeographic() && Math.abs(w * cellWidth - 360) < cellWidth / 2;
        }

        int sample(double sx, double sy) {
            if (Double.isNaN(sx) || Double.isNaN(sy)) {
                return 0;
            }
            double u = (sx - originX) / cellWidth - 0.5;
            double v = (originY - sy) / cellHeight - 0.5;
            if (wraps) {
                u = u - w * Math.floor((u + 0.5) / w); // into [−0.5, w − 0.5)
            }
            if (!(u >= -0.5 && u <= w - 0.5 && v >= -0.5 && v <= h - 0.5)) {
                return 0;
            }
            int c0 = (int) Math.floor(u);
            int r0 = (int) Math.floor(v);
            double fx = u - c0;
            double fy = v - r0;
            int c1 = c0 + 1;
            int r1 = r0 + 1;
            if (wraps) {
                c0 = Math.floorMod(c0, w);
                c1 = Math.floorMod(c1, w);
            } else {
                c0 = Math.max(0, c0);
                c1 = Math.min(w - 1, c1);
            }
            r0 = Math.max(0, r0);
            r1 = Math.min(h - 1, r1);
            double a = 0;
            double red = 0;
            double green = 0;
            double blue = 0;
            int[] px = {argb[r0 * w + c0], argb[r0 * w + c1], argb[r1 * w + c0], argb[r1 * w + c1]};
            double[] wt = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
            for (int k = 0; k < 4; k++) {
                double wa = wt[k] * (px[k] >>> 24);
                a += wa;
                red += wa * ((px[k] >> 16) & 0xFF);
                green += wa * ((px[k] >> 8) & 0xFF);
                blue += wa * (px[k] & 0xFF);
            }
            int alpha = (int) Math.round(a);
            if (alpha == 0) {
                return 0;
            }
            return alpha << 24 | channel(red / a) << 16 | channel(green / a) << 8 | channel(blue / a);
        }

        private static int channel(double v) {
            return (int) Math.max(0, Math.min(255, Math.round(v)));
        }
    }
}
