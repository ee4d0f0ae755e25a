package io.github.jdem846.output;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Cuts the bands of rows an encoder receives, north to south, into chunks of a fixed number of rows: the segments
 * of a PNG, the strips of a TIFF, the tile rows of a COG. A chunk that lies inside one band is handed on as a view
 * of the band, without a copy; the rows of a chunk that a band begins but does not finish are copied and kept until
 * later bands complete it. So the whole picture appended as one band is encoded straight from its array, and any
 * other cut into bands gives the same chunks, holding at most one chunk of copied rows.
 */
final class RowChunks {

    /**
     * Does what is due with the chunks a band completed, in order. It must be done with them when it returns: the
     * band's arrays then belong to the caller again.
     */
    @FunctionalInterface
    interface Sink {
        void accept(List<Chunk> chunks) throws IOException;
    }

    /** Rows {@code [from, from + rows)} of {@code source}: the image's rows from {@code index × rowsPerChunk}. */
    static final class Chunk {
        private final int index;
        private final int firstRow;
        private final int rows;
        private final Pixels source;
        private final int from;
        private final byte[] above;

        private Chunk(int index, int firstRow, int rows, Pixels source, int from, byte[] above) {
            this.index = index;
            this.firstRow = firstRow;
            this.rows = rows;
            this.source = source;
            this.from = from;
            this.above = above;
        }

        /** @return the chunk's number, from 0 at the top */
        int index() {
            return index;
        }

        /** @return rows in the chunk */
        int rows() {
            return rows;
        }

        /** Row {@code r} (0 = the chunk's first) into {@code dst} at {@code offset}. */
        void row(int r, byte[] dst, int offset) {
            source.row(from + r, dst, offset);
        }

        /** Pixels {@code [x0, x0 + count)} of row {@code r} into {@code dst} at {@code offset}. */
        void row(int r, int x0, int count, byte[] dst, int offset) {
            source.row(from + r, x0, count, dst, offset);
        }

        /**
         * The image row just above the chunk into {@code dst} at {@code offset}, zeros above the first row (for
         * PNG's filters, which look one row up).
         *
         * @throws IllegalStateException when the chunks were not cut to keep it
         */
        void rowAbove(byte[] dst, int offset) {
            if (firstRow == 0) {
                Arrays.fill(dst, offset, offset + source.rowBytes(), (byte) 0);
            } else if (from > 0) {
                source.row(from - 1, dst, offset);
            } else if (above != null) {
                System.arraycopy(above, 0, dst, offset, source.rowBytes());
            } else {
                throw new IllegalStateException("the row above chunk " + index + " was not kept");
            }
        }
    }

    private final int width;
    private final int height;
    private final int samplesPerPixel;
    private final int bitsPerSample;
    private final int rowBytes;
    private final int rowsPerChunk;
    private final boolean keepAbove;
    private final Sink sink;
    /** Rows of the image appended so far. */
    private int rowsIn;
    /** The rows of the chunk in progress (the one holding row {@code rowsIn}), when a band left it unfinished. */
    private byte[] pending;
    private int pendingRows;
    /** The row above the chunk in progress, and the last row of the last band (only with {@code keepAbove}). */
    private byte[] pendingAbove;
    private byte[] lastRow;

    /**
     * @param rowsPerChunk rows of every chunk but the last
     * @param keepAbove    keep the row above each chunk ({@link Chunk#rowAbove})
     * @param sink         takes the chunks each band completes
     */
    RowChunks(int width, int height, int samplesPerPixel, int bitsPerSample, int rowsPerChunk, boolean keepAbove,
              Sink sink) {
        this.width = width;
        this.height = height;
        this.samplesPerPixel = samplesPerPixel;
        this.bitsPerSample = bitsPerSample;
        this.rowBytes = Pixels.rowBytes(width, samplesPerPixel, bitsPerSample);
        this.rowsPerChunk = rowsPerChunk;
        this.keepAbove = keepAbove;
        this.sink = sink;
        if ((long) rowsPerChunk * rowBytes > Integer.MAX_VALUE - 16) {
            throw new IllegalArgumentException(rowsPerChunk + " rows of " + width + " pixels (" + (long) rowsPerChunk
                    * rowBytes + " bytes) are more than one Java array can hold");
        }
    }

    /** @return the number of chunks: all rows, {@code rowsPerChunk} at a time */
    static int count(int height, int rowsPerChunk) {
        return (int) ((height + (long) rowsPerChunk - 1) / rowsPerChunk);
    }

    /** @return rows appended so far */
    int rowsIn() {
        return rowsIn;
    }

    /** @return rows of the image */
    int height() {
        return height;
    }

    /** @return bytes of one row, in the file's layout */
    int rowBytes() {
        return rowBytes;
    }

    /**
     * Appends the next {@code band.height()} rows of the image and hands on the chunks they complete.
     *
     * @throws IllegalArgumentException when the band's width or sample layout is not the image's
     * @throws IllegalStateException    when the rows would pass the bottom of the image
     */
    void append(Pixels band) throws IOException {
        if (band.width() != width || band.samplesPerPixel() != samplesPerPixel
                || band.bitsPerSample() != bitsPerSample) {
            throw new IllegalArgumentException("a band of " + band.width() + " pixels of " + band.samplesPerPixel()
                    + "×" + band.bitsPerSample() + " bits does not fit an image of " + width + " pixels of "
                    + samplesPerPixel + "×" + bitsPerSample + " bits");
        }
        int n = band.height();
        if ((long) rowsIn + n > height) {
            throw new IllegalStateException(n + " rows after " + rowsIn + " pass the bottom of a " + height
                    + "-row image");
        }
        List<Chunk> ready = new ArrayList<>();
        int r = 0;
        boolean pendingDone = false;
        if (pendingRows > 0) {
            int index = rowsIn / rowsPerChunk;
            int take = Math.min(n, rowsOf(index) - pendingRows);
            copy(band, 0, take);
            r = take;
            if (pendingRows == rowsOf(index)) {
                ready.add(new Chunk(index, index * rowsPerChunk, pendingRows, encoded(pendingRows), 0, pendingAbove));
                pendingDone = true;
            }
        }
        while (r < n && n - r >= rowsOf((rowsIn + r) / rowsPerChunk)) {
            int row = rowsIn + r;
            int need = rowsOf(row / rowsPerChunk);
            ready.add(new Chunk(row / rowsPerChunk, row, need, band, r, r == 0 ? lastRow : null));
            r += need;
        }
        sink.accept(ready);
        if (pendingDone) {
            pendingRows = 0;          // the pending chunk was handed on: its buffer is free again
        }
        if (r < n) {                  // a chunk this band begins but does not finish
            if (keepAbove && rowsIn + r > 0) {
                pendingAbove = pendingAbove != null ? pendingAbove : new byte[rowBytes];
                if (r > 0) {
                    band.row(r - 1, pendingAbove, 0);
                } else {
                    System.arraycopy(lastRow, 0, pendingAbove, 0, rowBytes);
                }
            }
            copy(band, r, n - r);
        }
        if (keepAbove) {
            lastRow = lastRow != null ? lastRow : new byte[rowBytes];
            band.row(n - 1, lastRow, 0);
        }
        rowsIn += n;
    }

    /** Copies band rows {@code [from, from + count)} after the pending rows. */
    private void copy(Pixels band, int from, int count) {
        if (pending == null) {
            pending = new byte[Math.multiplyExact(Math.min(rowsPerChunk, height), rowBytes)];
        }
        for (int i = 0; i < count; i++) {
            band.row(from + i, pending, (pendingRows + i) * rowBytes);
        }
        pendingRows += count;
    }

    private Pixels encoded(int rows) {
        return new Pixels.Encoded(pending, width, rows, samplesPerPixel, bitsPerSample);
    }

    private int rowsOf(int index) {
        return (int) Math.min(rowsPerChunk, height - (long) index * rowsPerChunk);
    }
}
