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
 * requested cells are read, through positional {@link FileChannel} reads into a direct buffer of at most 1 MiB,
 * converted from there in bulk.
 */
public final class RawRasterSource implements RasterSource {

    private final DemInfo info;
    private final Path file;
    private final FileChannel channel;
    private final long offset;
    private final long rowStride;
    private final SampleType type;
    private final ByteOrder order;
    private final SampleDecoder decoder = new SampleDecoder();
    private ByteBuffer buffer = ByteBuffer.allocateDirect(0);

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

    /**
     * Bytes read at once when rows are adjacent in the file; a longer row is read in pieces of this size. Small
     * enough that the buffer stays in the processor's cache between the read and the conversion.
     */
    private static final int CHUNK = 1 << 20;

    @Override
    public void readRows(int col, int row, int width, int rows, float[] dst) throws IOException {
        readRows(col, row, width, rows, dst, 0);
    }

    /**
     * Reads the rows into {@code dst} from {@code at} on: each run of bytes is read into a direct buffer (the
     * file's bytes are copied once, by the read itself) and converted from there in bulk ({@link SampleDecoder}).
     */
    @Override
    public void readRows(int col, int row, int width, int rows, float[] dst, int at) throws IOException {
        int bytes = type.bytes();
        long rowBytes = (long) width * bytes;
        boolean contiguous = col == 0 && width == info.width() && rowStride == rowBytes;
        if (rowBytes > CHUNK) {
            // a row longer than a chunk (its byte count may pass 2³¹): column pieces, row by row
            int pieceCells = CHUNK / bytes;
            for (int r = 0; r < rows; r++) {
                for (int c = 0; c < width; c += pieceCells) {
                    int n = Math.min(pieceCells, width - c);
                    read(position(row + r, col + c), n * bytes);
                    decoder.decode(buffer, type, dst, at + r * width + c, n);
                }
            }
            return;
        }
        // Read whole rows in one go when they are adjacent in the file, otherwise row by row.
        int rowsPerRead = contiguous ? Math.max(1, Math.min(rows, CHUNK / Math.max(1, (int) rowBytes))) : 1;
        for (int r = 0; r < rows; r += rowsPerRead) {
            int n = Math.min(rowsPerRead, rows - r);
            read(position(row + r, col), n * (int) rowBytes);
            decoder.decode(buffer, type, dst, at + r * width, n * width);
        }
    }

    /** The file offset of cell ({@code col}, {@code row}) of band 1. */
    private long position(int row, int col) {
        return offset + (long) row * rowStride + (long) col * type.bytes();
    }

    /** Reads {@code length} bytes at {@code position} into {@link #buffer}, flipped for decoding. */
    private void read(long position, int length) throws IOException {
        if (buffer.capacity() < length) {
            buffer = ByteBuffer.allocateDirect(Math.max(length, Math.min(CHUNK, 2 * buffer.capacity())));
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

    /** About one {@link #CHUNK} of float32 cells: a band is read, converted and finished while in the cache. */
    @Override
    public long bandCells() {
        return 1L << 18;
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
