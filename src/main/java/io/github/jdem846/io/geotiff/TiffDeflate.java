package io.github.jdem846.io.geotiff;

import java.io.IOException;
import java.util.zip.DataFormatException;
import java.util.zip.Inflater;

/**
 * Inflates one strip or tile of TIFF Deflate (compression 8 or 32946: a zlib stream, RFC 1950) into exactly the
 * block's decoded size, and checks that the stream is whole: it must yield that many bytes, no more, then end with
 * its Adler-32 checksum, which {@link Inflater} verifies, right at the end of the block's stored bytes. So a block
 * overwritten in the middle (the checksum no longer matches, or the codes become invalid), cut short, or inflating
 * beyond its declared size (a decompression bomb) is refused instead of read as garbage; at most the block's size
 * is ever written. TwelveMonkeys stops reading a block once its rows are full, so it never sees the checksum.
 */
final class TiffDeflate {

    private TiffDeflate() {
    }

    /**
     * Inflates {@code src[0, length)} into all of {@code dst}.
     *
     * @param src    the stored bytes of the block
     * @param length how many of them
     * @param dst    the decoded block, filled completely
     * @throws IOException when the stream is corrupt, ends before filling {@code dst}, holds more, or is followed
     *                     by stray bytes (the message says which)
     */
    static void decode(byte[] src, int length, byte[] dst) throws IOException {
        Inflater inflater = new Inflater();
        try {
            inflater.setInput(src, 0, length);
            int out = 0;
            while (out < dst.length) {
                int n = inflater.inflate(dst, out, dst.length - out);
                out += n;
                if (n == 0 && out < dst.length) {
                    if (inflater.needsDictionary()) {
                        throw new IOException("the Deflate stream asks for a preset dictionary, which TIFF has not");
                    }
                    if (inflater.finished() || inflater.needsInput()) {
                        throw new IOException("the Deflate stream ends after " + out + " of the block's "
                                + dst.length + " bytes");
                    }
                }
            }
            // the block is full: the stream must end here, checksum included, with nothing after it
            int more = inflater.inflate(new byte[1]);
            if (more > 0) {
                throw new IOException("the Deflate stream holds more than the block's " + dst.length + " bytes");
            }
            if (!inflater.finished()) {
                throw new IOException("the Deflate stream does not end after the block's " + dst.length
                        + " bytes (cut short?)");
            }
            if (inflater.getRemaining() > 0) {
                throw new IOException(inflater.getRemaining() + " stray bytes follow the end of the Deflate stream");
            }
        } catch (DataFormatException e) {
            throw new IOException("corrupt Deflate data (" + e.getMessage() + ")", e);
        } finally {
            inflater.end();
        }
    }
}
