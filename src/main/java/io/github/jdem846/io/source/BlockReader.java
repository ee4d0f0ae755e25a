package io.github.jdem846.io.source;

import io.github.jdem846.io.Window;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.raster.NoData;
import java.io.IOException;

/**
 * Reads a window of a {@link RasterSource} band by band and hands over output rows, applying the no-data rule
 * (declared value → NaN), then the file's {@link ValueScale}, and, for decimation {@code d > 1}, the box filter:
 * each output cell is the mean of the valid cells of its {@code d × d} block (partial at the east and south edges),
 * NaN when none is valid. Only one band of rows is held at a time, so the memory used is independent of the height
 * of the window. On the way it takes the statistics of the window's cells at full resolution, so that a decimated
 * read of a whole file needs no second pass for the file's elevation range.
 */
public final class BlockReader {

    /** Receives output rows in order. */
    public interface RowSink {
        /** Row {@code outRow} of the output, {@code values[0..width)} (the array is reused afterwards). */
        void accept(int outRow, float[] values) throws IOException;
    }

    private BlockReader() {
    }

    /**
     * Bytes {@link #read} takes for this window beyond its output: the float32 band buffer and what the source
     * decodes at once ({@link RasterSource#blockBytes}); saturated, never negative.
     */
    public static long bandBytes(RasterSource source, Window.Cells window, int d) {
        return MemoryGuard.saturatedAdd(MemoryGuard.saturatedMultiply(4L * window.width(),
                bandRows(source, window, d)), source.blockBytes());
    }

    /** Rows of the band buffer {@link #read} allocates for this window. */
    public static int bandRows(RasterSource source, Window.Cells window, int d) {
        return bandRows(source.naturalRowBlock(), d, window.width(), window.height(), source.bandCells());
    }

    /** Output width of a window of {@code w} columns at decimation {@code d}. */
    public static int outputSize(int w, int d) {
        return (int) ((w + (long) d - 1) / d);
    }

    /**
     * Reads {@code window} of {@code source} at decimation {@code d} into {@code sink}.
     *
     * @param noData the declared no-data value, NaN for none
     * @return min, max and valid count of the window's cells at full resolution (no-data rule and value scale
     *         applied)
     */
    public static ElevationStatistics read(RasterSource source, Window.Cells window, int d, double noData, RowSink sink)
            throws IOException {
        int w = window.width();
        int h = window.height();
        int outW = outputSize(w, d);
        int outH = outputSize(h, d);
        int bandRows = bandRows(source.naturalRowBlock(), d, w, h, source.bandCells());
        float[] band = new float[bandRows * w];
        float[] out = new float[outW];
        double[] sum = d > 1 ? new double[outW] : null;
        int[] count = d > 1 ? new int[outW] : null;
        float nd = NoData.toFloat32(noData);
        boolean hasNoData = !Double.isNaN(noData);
        ValueScale scale = source.valueScale();
        ValidRange range = new ValidRange(nd, hasNoData, scale);
        float min = Float.POSITIVE_INFINITY;
        float max = Float.NEGATIVE_INFINITY;
        long valid = 0;
        int outRow = 0;
        for (int r0 = 0; r0 < h; r0 += bandRows) {
            int n = Math.min(bandRows, h - r0);
            source.readRows(window.col(), window.row() + r0, w, n, band);
            if (d == 1) {
                for (int r = 0; r < n; r++) {
                    range.take(band, r * w, (r + 1) * w);
                    System.arraycopy(band, r * w, out, 0, w);
                    sink.accept(outRow++, out);
                }
                continue;
            }
            if (hasNoData) {
                for (int i = 0; i < n * w; i++) {
                    if (band[i] == nd) {
                        band[i] = Float.NaN;
                    }
                }
            }
            if (!scale.isIdentity()) {
                scale.apply(band, n * w);
            }
            // Bands hold whole blocks (bandRows is a multiple of d), except the last, partial one.
            for (int b0 = 0; b0 < n; b0 += d) {
                java.util.Arrays.fill(sum, 0);
                java.util.Arrays.fill(count, 0);
                int bn = Math.min(d, n - b0);
                for (int r = b0; r < b0 + bn; r++) {
                    int base = r * w;
                    for (int c = 0; c < w; c++) {
                        float v = band[base + c];
                        if (v == v) {
                            int o = c / d;
                            sum[o] += v;
                            count[o]++;
                            min = v < min ? v : min;
                            max = v > max ? v : max;
                        }
                    }
                }
                for (int o = 0; o < outW; o++) {
                    out[o] = count[o] > 0 ? (float) (sum[o] / count[o]) : Float.NaN;
                    valid += count[o];
                }
                sink.accept(outRow++, out);
            }
        }
        if (outRow != outH) {
            throw new IllegalStateException("produced " + outRow + " rows, expected " + outH);
        }
        return d == 1 ? range.statistics((long) w * h) : ElevationStatistics.ofRange(min, max, valid, (long) w * h);
    }

    /** Told of the rows {@link #readInto} has finished. */
    @FunctionalInterface
    public interface RowsDone {
        /** {@code rows} more rows are final. */
        void add(long rows);
    }

    /**
     * What {@link #read} gives at decimation 1, written straight into {@code dst} from {@code at} on (the window's
     * rows one after the other): the source decodes each band into place ({@link RasterSource#readRows(int, int,
     * int, int, float[], int)}), where the no-data rule and the value scale are applied and the statistics taken,
     * with no band buffer and no copies.
     *
     * @param noData   the declared no-data value, NaN for none
     * @param rowsDone told of each row finished
     * @return min, max and valid count of the window's cells (no-data rule and value scale applied)
     */
    public static ElevationStatistics readInto(RasterSource source, Window.Cells window, double noData, float[] dst,
                                               int at, RowsDone rowsDone) throws IOException {
        int w = window.width();
        int h = window.height();
        if (at < 0 || (long) at + (long) w * h > dst.length) {
            throw new IllegalArgumentException("a " + w + " × " + h + " window from " + at + " does not fit "
                    + dst.length + " cells");
        }
        int bandRows = bandRows(source.naturalRowBlock(), 1, w, h, source.bandCells());
        ValidRange range = new ValidRange(NoData.toFloat32(noData), !Double.isNaN(noData), source.valueScale());
        for (int r0 = 0; r0 < h; r0 += bandRows) {
            int n = Math.min(bandRows, h - r0);
            int base = at + r0 * w;
            source.readRows(window.col(), window.row() + r0, w, n, dst, base);
            for (int r = 0; r < n; r++) {
                range.take(dst, base + r * w, base + (r + 1) * w);
                rowsDone.add(1);
            }
        }
        return range.statistics((long) w * h);
    }

    /**
     * Rows per band: a multiple of {@code d} (so blocks never straddle bands) and of the format's natural block
     * (so strips and tiles are decoded about once), near {@code targetCells} cells, at most the window height
     * rounded up to {@code d}; the whole window when one strip covers it. At most {@link Integer#MAX_VALUE}
     * (a band that large is refused before it is allocated, {@link MemoryGuard#requireBandFits}).
     */
    public static int bandRows(int natural, int d, int w, int h, long targetCells) {
        long cap = Math.min(Integer.MAX_VALUE, ((long) h + d - 1) / d * d);
        if (natural >= h) {
            return (int) cap; // one strip holds the whole window: decode it once
        }
        long unit = lcm(Math.max(1, natural), d);
        if (unit > cap) {
            unit = d;
        }
        long rows = Math.max(unit, (targetCells / Math.max(1, w)) / unit * unit);
        return (int) Math.max(1, Math.min(rows, cap));
    }

    private static long lcm(long a, long b) {
        long x = a;
        long y = b;
        while (y != 0) {
            long t = x % y;
            x = y;
            y = t;
        }
        return a / x * b;
    }
}
