package io.github.jdem846.io.source;

import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.SampleType;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

/**
 * Rows of an uncompressed raster at known file offsets (GridFloat, BIL, SRTM HGT): only the bytes of the
 * requested cells are read, through positional {@link FileChannel} reads.
 */
public final class RawRasterSource implements RasterSource {

    private final DemInfo info;
    private final Path file;
    private final FileChannel channel;
    private final long offset;
    private final long rowStride;
    private final SampleType type;
    private final ByteOrder order;
    private ByteBuffer buffer = ByteBuffer.allocate(0);

    /**
     * @param info      the header information
     * @param file      the file holding the samples
     * @param offset    byte offset of row 0, column 0 of band 1
     * @param rowStride bytes from the start of one row of band 1 to the next
     * @param type      sample type
     * @param order     byte order
     */
    public RawRasterSource(DemInfo info, Path file, long offset, long rowStride, SampleType type, ByteOrder order)
            throws DemFormatException {
        this.info = info;
        this.file = file;
        this.offset = offset;
        this.rowStride = rowStride;
        this.type = type;
        this.order = order;
        try {
            this.channel = FileChannel.open(file, StandardOpenOption.READ);
        } catch (IOException e) {
            throw new DemFormatException(file, "cannot open: " + e.getMessage(), e);
        }
    }

    @Override
    public DemInfo info() {
        return info;
    }

    /** Bytes read at once when rows are adjacent in the file; a longer row is read in pieces of this size. */
    private static final int CHUNK = 1 << 22;

    @Override
    public void readRows(int col, int row, int width, int rows, float[] dst) throws IOException {
        int bytes = type.bytes();
        long rowBytes = (long) width * bytes;
        boolean contiguous = col == 0 && width == info.width() && rowStride == rowBytes;
        if (rowBytes > CHUNK) {
            // a row longer than a chunk (its byte count may pass 2³¹): column pieces, row by row
            int pieceCells = CHUNK / bytes;
            for (int r = 0; r < rows; r++) {
                for (int c = 0; c < width; c += pieceCells) {
                    int n = Math.min(pieceCells, width - c);
                    read(offset + (long) (row + r) * rowStride + (long) (col + c) * bytes, n * bytes);
                    decode(buffer, dst, r * width + c, n);
                }
            }
            return;
        }
        // Read whole rows in one go when they are adjacent in the file, otherwise row by row.
        int rowsPerRead = contiguous ? Math.max(1, Math.min(rows, CHUNK / Math.max(1, (int) rowBytes))) : 1;
        for (int r = 0; r < rows; r += rowsPerRead) {
            int n = Math.min(rowsPerRead, rows - r);
            read(offset + (long) (row + r) * rowStride + (long) col * bytes, n * (int) rowBytes);
            decode(buffer, dst, r * width, n * width);
        }
    }

    /** Reads {@code length} bytes at {@code position} into {@link #buffer}, flipped for decoding. */
    private void read(long position, int length) throws IOException {
        if (buffer.capacity() < length) {
            buffer = ByteBuffer.allocate(length);
        }
        buffer.clear().limit(length);
        readFully(position);
        buffer.flip().order(order);
    }

    private void readFully(long position) throws IOException {
        long p = position;
        while (buffer.hasRemaining()) {
            int got = channel.read(buffer, p);
            if (got < 0) {
                throw new DemFormatException(file, "ends at byte " + p + " but the header needs data up to byte "
                        + (position + buffer.limit()) + " (truncated?)");
            }
            p += got;
        }
    }

    private void decode(ByteBuffer b, float[] dst, int at, int count) {
        switch (type) {
            case FLOAT32 -> b.asFloatBuffer().get(dst, at, count);
            case INT16 -> {
                for (int i = 0; i < count; i++) {
                    dst[at + i] = b.getShort();
                }
            }
            case UINT16 -> {
                for (int i = 0; i < count; i++) {
                    dst[at + i] = b.getShort() & 0xFFFF;
                }
            }
            case INT8 -> {
                for (int i = 0; i < count; i++) {
                    dst[at + i] = b.get();
                }
            }
            case UINT8 -> {
                for (int i = 0; i < count; i++) {
                    dst[at + i] = b.get() & 0xFF;
                }
            }
            case INT32 -> {
                for (int i = 0; i < count; i++) {
                    dst[at + i] = b.getInt();
                }
            }
            case UINT32 -> {
                for (int i = 0; i < count; i++) {
                    dst[at + i] = b.getInt() & 0xFFFFFFFFL;
                }
            }
            case FLOAT64 -> {
                for (int i = 0; i < count; i++) {
                    dst[at + i] = (float) b.getDouble();
                }
            }
            default -> throw new IllegalStateException("raw " + type + " samples are not supported");
        }
    }

    @Override
    public boolean readsRowsIndependently() {
        return true;
    }

    @Override
    public void close() throws IOException {
        channel.close();
    }
}
