package io.github.jdem846.output;

import io.github.jdem846.internal.SpareArrays;
import java.util.Arrays;
import java.util.zip.Deflater;

/**
 * The compressed data of one TIFF strip or tile: its rows with the horizontal differencing predictor when asked,
 * as one zlib stream (Deflate, compression 8, the stream GDAL calls DEFLATE) at level {@value #LEVEL}. One instance
 * per file reuses its deflaters ({@link SpareDeflaters}) and output buffers across blocks and threads: a 4000² mask
 * has 250 strips of 64 KB. {@link #end()} frees the deflaters.
 */
final class TiffBlocks {

    /**
     * The deflate level: 1, the fastest, as for PNG. Against zlib's default (6) on 4000² pictures: a gray hillshade
     * 1.3× faster and 1.5 % larger, a shadow mask 7× faster and 44 % larger (1.58 against 1.10 MB of 16 MB);
     * docs/performance.md, "Writing PNG and GeoTIFF".
     */
    static final int LEVEL = 1;

    private final SpareDeflaters deflaters = new SpareDeflaters(LEVEL, false);
    private final SpareArrays<byte[]> buffers = SpareArrays.bytes();

    /**
     * Applies the predictor to the rows of {@code raw} in place, when asked, and deflates them.
     *
     * @param raw       the block's rows, one after another, {@code rows × rowBytes} from index 0
     * @param step      bytes between a sample and the same sample of the pixel to its left (samples per pixel)
     * @param predictor apply TIFF 6.0 section 14's horizontal differencing (8-bit samples only)
     * @return the zlib stream
     */
    byte[] deflate(byte[] raw, int rows, int rowBytes, int step, boolean predictor) {
        if (predictor) {
            for (int r = 0; r < rows; r++) {
                difference(raw, r * rowBytes, rowBytes, step);
            }
        }
        int n = rows * rowBytes;
        Deflater deflater = deflaters.take();
        byte[] buffer = buffers.take((int) Math.min(Integer.MAX_VALUE - 16, deflateBound(n)));
        try {
            deflater.setInput(raw, 0, n);
            deflater.finish();
            int length = 0;
            while (!deflater.finished()) {
                if (length == buffer.length) {
                    buffer = Arrays.copyOf(buffer, (int) Math.min(Integer.MAX_VALUE - 16, 2L * buffer.length));
                }
                length += deflater.deflate(buffer, length, buffer.length - length);
            }
            return Arrays.copyOf(buffer, length);
        } finally {
            deflaters.give(deflater);
            buffers.give(buffer);
        }
    }

    /**
     * The horizontal differencing of one row in place: each sample minus the same sample of the pixel to its left,
     * mod 256. One sample per pixel goes left to right with the previous sample carried (faster under the
     * first-tier JIT, 15–35 % in a microbenchmark, than the loop from the right, which other steps use).
     */
    private static void difference(byte[] raw, int base, int rowBytes, int step) {
        if (step == 1) {
            byte previous = raw[base];
            for (int i = base + 1; i < base + rowBytes; i++) {
                byte current = raw[i];
                raw[i] = (byte) (current - previous);
                previous = current;
            }
            return;
        }
        for (int i = base + rowBytes - 1; i >= base + step; i--) {
            raw[i] = (byte) (raw[i] - raw[i - step]);
        }
    }

    /** Frees the deflaters; a later {@link #deflate} makes new ones. */
    void end() {
        deflaters.end();
    }

    /**
     * An upper bound of the bytes {@link #deflate} makes of {@code n} bytes: zlib's deflateBound for the default
     * window and memory level (stored blocks at worst), plus the zlib header and checksum.
     */
    static long deflateBound(long n) {
        return n + (n >> 12) + (n >> 14) + (n >> 25) + 13 + 6;
    }
}
