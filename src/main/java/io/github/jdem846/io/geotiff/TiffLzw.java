package io.github.jdem846.io.geotiff;

import java.io.IOException;

/**
 * Decompresses one strip or tile of TIFF LZW (TIFF 6.0 §13: codes of 9 to 12 bits, most significant bit first,
 * Clear = 256, EndOfInformation = 257, the code width growing one code early) into a byte array.
 *
 * <p>Why not TwelveMonkeys, which reads the rest of the file: its LZW decoder pulls every compressed byte through a
 * synchronized {@code BufferedInputStream.read()}, which took half the time of a 4000² LZW read (JFR,
 * docs/performance.md), and the decoder class is not public, so it cannot be handed another stream. The old-style,
 * bit-reversed LZW of pre-6.0 writers is left to TwelveMonkeys ({@link #isNewStyle}). {@code TiffReferenceDecodeTest}
 * compares every LZW file of testdata bit for bit with TwelveMonkeys' own decoding.
 *
 * <p>Each table entry is kept as a run of the output (start, length): an entry is the previous string plus the first
 * byte of the next, which the output already holds in a row.
 */
final class TiffLzw {

    private static final int CLEAR = 256;
    private static final int END = 257;
    private static final int FIRST_FREE = 258;
    private static final int MAX_CODES = 4096;

    private TiffLzw() {
    }

    /** True when the data start with a Clear code of the TIFF 6.0 kind (a first byte of 0x80). */
    static boolean isNewStyle(byte[] src, int length) {
        return length >= 2 && (src[0] & 0xFF) == 0x80 && (src[1] & 0x80) == 0;
    }

    /**
     * Decompresses {@code src[0, length)} into {@code dst}, at most {@code dst.length} bytes.
     *
     * @return the number of bytes written
     * @throws IOException when a code is not in the table (corrupt data)
     */
    static int decode(byte[] src, int length, byte[] dst) throws IOException {
        int[] start = new int[MAX_CODES];
        int[] size = new int[MAX_CODES];
        int free = FIRST_FREE;
        int width = 9;
        int previousAt = -1;     // where the previous string was written; -1 right after a Clear
        int previousSize = 0;
        int out = 0;
        long bits = 0;
        int bitCount = 0;
        int in = 0;
        while (out < dst.length) {
            while (bitCount < width && in < length) {
                bits = bits << 8 | (src[in++] & 0xFF);
                bitCount += 8;
            }
            if (bitCount < width) {
                break;           // the data end without an EndOfInformation code
            }
            int code = (int) (bits >>> (bitCount - width)) & ((1 << width) - 1);
            bitCount -= width;
            if (code == CLEAR) {
                free = FIRST_FREE;
                width = 9;
                previousAt = -1;
                continue;
            }
            if (code == END) {
                break;
            }
            int at = out;
            int n;
            if (code < CLEAR) {
                dst[out++] = (byte) code;
                n = 1;
            } else if (code >= FIRST_FREE && code < free) {
                out = copy(dst, start[code], size[code], out);
                n = size[code];
            } else if (code == free && previousAt >= 0) {
                // the string being defined: the previous one and its own first byte
                out = copy(dst, previousAt, previousSize, out);
                if (out < dst.length) {
                    dst[out++] = dst[previousAt];
                }
                n = previousSize + 1;
            } else {
                throw new IOException("LZW code " + code + " is not in the table of " + free + " entries");
            }
            if (previousAt >= 0 && free < MAX_CODES) {
                // the previous string and the first byte of this one: a run of the output
                start[free] = previousAt;
                size[free] = previousSize + 1;
                free++;
                if (free >= (1 << width) - 1 && width < 12) {
                    width++;
                }
            }
            previousAt = at;
            previousSize = n;
        }
        return out;
    }

    /** Copies the run {@code dst[from, from + n)} to {@code dst[to…]}, cut at the end of {@code dst}. */
    private static int copy(byte[] dst, int from, int n, int to) {
        int m = Math.min(n, dst.length - to);
        System.arraycopy(dst, from, dst, to, m);
        return to + m;
    }
}
