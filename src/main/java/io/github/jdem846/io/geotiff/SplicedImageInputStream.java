package io.github.jdem846.io.geotiff;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import javax.imageio.stream.ImageInputStreamImpl;

/**
 * A read-only image stream made of an in-memory head followed by a whole file: positions {@code [0, head.length)}
 * read the head, positions from {@code shift} on read the file at {@code position − shift}. Used to put a
 * synthetic TIFF header and image directory in front of an existing TIFF's strip and tile data.
 */
final class SplicedImageInputStream extends ImageInputStreamImpl {

    private final byte[] head;
    private final long shift;
    private final FileChannel file;
    private final long fileLength;
    private final ByteBuffer one = ByteBuffer.allocate(1);

    /**
     * @param head  the bytes at the start of the stream
     * @param shift where the file begins in the stream, ≥ {@code head.length} (the gap reads as zeros)
     * @param file  the file (not closed by this stream)
     */
    SplicedImageInputStream(byte[] head, long shift, FileChannel file) throws IOException {
        if (shift < head.length) {
            throw new IllegalArgumentException("shift " + shift + " < head length " + head.length);
        }
        this.head = head;
        this.shift = shift;
        this.file = file;
        this.fileLength = file.size();
    }

    @Override
    public long length() {
        return shift + fileLength;
    }

    @Override
    public int read() throws IOException {
        checkClosed();
        bitOffset = 0;
        if (streamPos < shift) {
            int b = streamPos < head.length ? head[(int) streamPos] & 0xFF : 0;
            streamPos++;
            return b;
        }
        one.clear();
        int n = file.read(one, streamPos - shift);
        if (n <= 0) {
            return -1;
        }
        streamPos++;
        return one.get(0) & 0xFF;
    }

    @Override
    public int read(byte[] b, int off, int len) throws IOException {
        checkClosed();
        bitOffset = 0;
        if (len == 0) {
            return 0;
        }
        if (streamPos < shift) {
            int n = (int) Math.min(len, shift - streamPos);
            for (int i = 0; i < n; i++) {
                long p = streamPos + i;
                b[off + i] = p < head.length ? head[(int) p] : 0;
            }
            streamPos += n;
            return n;
        }
        int n = file.read(ByteBuffer.wrap(b, off, len), streamPos - shift);
        if (n <= 0) {
            return -1;
        }
        streamPos += n;
        return n;
    }
}
