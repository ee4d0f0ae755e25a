package io.github.jdem846.output;

import java.io.ByteArrayOutputStream;
import java.util.zip.Deflater;

/**
 * The compressed data of one TIFF strip or tile: its rows with the horizontal differencing predictor when asked,
 * as one zlib stream (Deflate, compression 8, the stream GDAL calls DEFLATE) at level {@value #LEVEL}.
 */
final class TiffBlocks {

    /**
     * The deflate level: 1, the fastest, as for PNG. Against zlib's default (6) on 4000² pictures: a gray hillshade
     * 1.3× faster and 1.5 % larger, a shadow mask 7× faster and 44 % larger (1.58 against 1.10 MB of 16 MB);
     * docs/performance.md, "Writing PNG and GeoTIFF".
     */
    static final int LEVEL = 1;

    private TiffBlocks() {
    }

    /**
     * Applies the predictor to the rows of {@code raw} in place, when asked, and deflates them.
     *
     * @param raw       the block's rows, one after another, {@code rows × rowBytes} from index 0
     * @param step      bytes between a sample and the same sample of the pixel to its left (samples per pixel)
     * @param predictor apply TIFF 6.0 section 14's horizontal differencing (8-bit samples only)
     * @return the zlib stream
     */
    static byte[] deflate(byte[] raw, int rows, int rowBytes, int step, boolean predictor) {
        if (predictor) {
            // Each sample minus the same sample of the pixel to its left, mod 256; right to left, so in place.
            for (int r = 0; r < rows; r++) {
                int base = r * rowBytes;
                for (int i = base + rowBytes - 1; i >= base + step; i--) {
                    raw[i] = (byte) (raw[i] - raw[i - step]);
                }
            }
        }
        int n = rows * rowBytes;
        Deflater deflater = new Deflater(LEVEL);
        try {
            deflater.setInput(raw, 0, n);
            deflater.finish();
            ByteArrayOutputStream out = new ByteArrayOutputStream(n / 4 + 64);
            byte[] buffer = new byte[1 << 16];
            while (!deflater.finished()) {
                out.write(buffer, 0, deflater.deflate(buffer));
            }
            return out.toByteArray();
        } finally {
            deflater.end();
        }
    }

    /**
     * An upper bound of the bytes {@link #deflate} makes of {@code n} bytes: zlib's deflateBound for the default
     * window and memory level (stored blocks at worst), plus the zlib header and checksum.
     */
    static long deflateBound(long n) {
        return n + (n >> 12) + (n >> 14) + (n >> 25) + 13 + 6;
    }
}
