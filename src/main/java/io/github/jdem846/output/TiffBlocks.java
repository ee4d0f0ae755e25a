package io.github.jdem846.output;

import java.io.ByteArrayOutputStream;
import java.util.zip.Deflater;

/**
 * The compressed data of one TIFF strip or tile: its rows with the horizontal differencing predictor when asked,
 * as one zlib stream (Deflate, compression 8, the stream GDAL calls DEFLATE) at the default level.
 */
final class TiffBlocks {

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
        Deflater deflater = new Deflater(Deflater.DEFAULT_COMPRESSION);
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
