package io.github.jdem846.output;

import java.io.IOException;
import java.util.Arrays;

/**
 * The overview levels of a COG, reduced row by row from the full-resolution rows as they arrive. Each level is half
 * the one before, rounded down (at least 1), as GDAL's COG driver sizes them: level k is {@code w_k × h_k} with
 * {@code w_k = max(1, ⌊w_(k−1) / 2⌋)}. Its pixel (x, y) is the mean of the full-resolution pixels of the box
 * {@code [x·2^k, (x+1)·2^k) × [y·2^k, (y+1)·2^k)}, the last column and row of boxes reaching to the image's edge
 * (so an odd column or row left over by a halving joins the last box instead of being dropped): a box average of
 * the full-resolution pixels, not of the rounded pixels of the level above. It is exact because each level keeps
 * sums, not means, and the sums of level k − 1 add up to those of level k; a level holds the sums of one row. Means
 * are rounded half up.
 *
 * <ul>
 *   <li>Gray without no-data: the mean of all pixels of the box.</li>
 *   <li>Gray with a no-data value (a hillshade's 0): the mean of the box's valid pixels only, so no-data never
 *       darkens (or brightens) valid ones; a box without valid pixels is no-data. A mean that rounds to the
 *       no-data value becomes the value next to it, so that it stays valid: the one above, unless the exact mean
 *       is below the no-data value (or it is 255).</li>
 *   <li>RGBA (non-premultiplied, alpha = coverage): the colour is the alpha-weighted mean, Σ(c·a) / Σa, so
 *       transparent pixels, whatever colour bits they carry, add nothing to the colour; the alpha is the plain
 *       mean of the alphas (transparent pixels count as 0), so an edge half covered is half transparent. A box
 *       whose alphas are all 0 is (0, 0, 0, 0).</li>
 * </ul>
 */
final class OverviewPyramid {

    /** Takes the rows of the levels, each level's from the top down; the row's array is reused afterwards. */
    @FunctionalInterface
    interface Output {
        void row(int level, Pixels row) throws IOException;
    }

    private final Level[] levels;
    private final boolean rgba;
    private final int noData;
    private final Output output;

    /**
     * @param levels          the number of overview levels (0 for none)
     * @param samplesPerPixel 4 (RGBA) or 1 (gray), 8 bits each
     * @param noData          the gray no-data value 0..255, or {@code null}
     */
    OverviewPyramid(int width, int height, int levels, int samplesPerPixel, Integer noData, Output output) {
        this.rgba = samplesPerPixel == 4;
        this.noData = rgba || noData == null ? -1 : noData;
        this.output = output;
        this.levels = new Level[levels + 1];
        int w = width;
        int h = height;
        for (int k = 1; k <= levels; k++) {
            int sourceHeight = h;
            w = half(w);
            h = half(h);
            this.levels[k] = new Level(k, w, h, sourceHeight, rgba ? 4 : 1);
        }
    }

    /** @return half of a level's size, rounded down, at least 1: the size of the next level */
    static int half(int size) {
        return Math.max(1, size / 2);
    }

    /** Adds the next full-resolution row, in the file's layout (R, G, B, A or gray bytes). */
    void add(byte[] row, int width) throws IOException {
        if (levels.length == 1) {
            return;
        }
        Level first = levels[1];
        int last = first.width - 1;
        if (rgba) {
            for (int x = 0; x < width; x++) {
                int j = 4 * x;
                long a = row[j + 3] & 0xFF;
                int to = Math.min(x >> 1, last);
                int at = 4 * to;
                first.sums[at] += (row[j] & 0xFF) * a;
                first.sums[at + 1] += (row[j + 1] & 0xFF) * a;
                first.sums[at + 2] += (row[j + 2] & 0xFF) * a;
                first.sums[at + 3] += a;
                first.counts[to]++;
            }
        } else {
            for (int x = 0; x < width; x++) {
                int v = row[x] & 0xFF;
                if (v != noData) {
                    int to = Math.min(x >> 1, last);
                    first.sums[to] += v;
                    first.counts[to]++;
                }
            }
        }
        first.sourceRowAdded();
    }

    /** @return whether every level has given all its rows */
    boolean isComplete() {
        for (int k = 1; k < levels.length; k++) {
            if (levels[k].rowsOut != levels[k].height) {
                return false;
            }
        }
        return true;
    }

    /** One overview level: the sums of the row being made from the rows of the level above. */
    private final class Level {
        final int index;
        final int width;
        final int height;
        final int sourceHeight;
        final int channels;
        final long[] sums;
        final long[] counts;
        final byte[] out;
        int sourceRows;
        int rowsOut;

        Level(int index, int width, int height, int sourceHeight, int channels) {
            this.index = index;
            this.width = width;
            this.height = height;
            this.sourceHeight = sourceHeight;
            this.channels = channels;
            this.sums = new long[width * channels];
            this.counts = new long[width];
            this.out = new byte[width * channels];
        }

        /** Adds the sums of a row of the level above (of {@code sourceWidth} pixels). */
        void add(long[] sourceSums, long[] sourceCounts, int sourceWidth) throws IOException {
            for (int x = 0; x < sourceWidth; x++) {
                int to = Math.min(x >> 1, width - 1);
                int from = x * channels;
                for (int c = 0; c < channels; c++) {
                    sums[to * channels + c] += sourceSums[from + c];
                }
                counts[to] += sourceCounts[x];
            }
            sourceRowAdded();
        }

        /**
         * After a row of the level above: a row of this level is done after its two, the last one after all rows
         * left (two or three).
         */
        void sourceRowAdded() throws IOException {
            sourceRows++;
            boolean done = rowsOut < height - 1 ? sourceRows == 2 * (rowsOut + 1) : sourceRows == sourceHeight;
            if (!done) {
                return;
            }
            rowsOut++;
            for (int x = 0; x < width; x++) {
                if (rgba) {
                    mean(x);
                } else {
                    out[x] = (byte) grayMean(sums[x], counts[x]);
                }
            }
            output.row(index, new Pixels.Encoded(out, width, 1, channels, 8));
            if (index + 1 < levels.length) {
                levels[index + 1].add(sums, counts, width);
            }
            Arrays.fill(sums, 0);
            Arrays.fill(counts, 0);
        }

        private void mean(int x) {
            int j = 4 * x;
            long alphas = sums[j + 3];
            if (alphas == 0) {
                Arrays.fill(out, j, j + 4, (byte) 0);
                return;
            }
            long n = counts[x];
            out[j] = (byte) ((sums[j] + alphas / 2) / alphas);
            out[j + 1] = (byte) ((sums[j + 1] + alphas / 2) / alphas);
            out[j + 2] = (byte) ((sums[j + 2] + alphas / 2) / alphas);
            out[j + 3] = (byte) ((alphas + n / 2) / n);
        }

        private int grayMean(long sum, long n) {
            if (n == 0) {
                return Math.max(noData, 0);
            }
            int mean = (int) ((sum + n / 2) / n);
            if (mean != noData) {
                return mean;
            }
            return sum >= (long) noData * n && noData < 255 ? noData + 1 : noData - 1;
        }
    }
}
