package io.github.jdem846.io.source;

import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.DemInfo;
import java.io.Closeable;
import java.io.IOException;

/**
 * An open DEM file of one format: its header and random access to rows of band 1. Implementations are not
 * thread-safe.
 */
public interface RasterSource extends Closeable {

    /**
     * The header information (no pixels decoded); after a read, with any notices learned while reading (values
     * after the end of an ASCII grid).
     */
    DemInfo info();

    /**
     * Reads columns {@code [col, col+width)} of rows {@code [row, row+rows)} as float32 into {@code dst}
     * (row-major, {@code width × rows} values), exactly as stored: the no-data rule is not applied here.
     *
     * @throws DemFormatException (an IOException) when the data cannot be decoded; the message names the file
     */
    void readRows(int col, int row, int width, int rows, float[] dst) throws IOException;

    /**
     * {@link #readRows(int, int, int, int, float[])} into {@code dst[at, at + width × rows)}: straight into a
     * larger grid. This default reads into an array of its own and copies it; formats that can write in place
     * override it.
     *
     * @throws DemFormatException (an IOException) when the data cannot be decoded; the message names the file
     */
    default void readRows(int col, int row, int width, int rows, float[] dst, int at) throws IOException {
        if (at == 0) {
            readRows(col, row, width, rows, dst);
            return;
        }
        float[] own = new float[Math.multiplyExact(width, rows)];
        readRows(col, row, width, rows, own);
        System.arraycopy(own, 0, dst, at, own.length);
    }

    /**
     * The number of rows the format decodes together (TIFF strip or tile height; 1 for raw rows), so that reads
     * can be aligned to it.
     */
    default int naturalRowBlock() {
        return 1;
    }

    /**
     * About how many cells to decode per call of {@link #readRows}: small for formats with cheap random access,
     * large for decoders whose every call has a cost proportional to the whole file.
     */
    default long bandCells() {
        return 1L << 20;
    }

    /**
     * Heap bytes one call of {@link #readRows} takes beyond its destination, whatever its size: a strip or tile
     * that must be decoded whole (stored and decoded). 0 for formats read row by row.
     */
    default long blockBytes() {
        return 0;
    }

    /**
     * True when disjoint row bands can be read at the same time through separately opened sources, each decoding
     * only its own rows (raw rows; TIFF strips or tiles with subsetting).
     */
    default boolean readsRowsIndependently() {
        return false;
    }

    /** How stored values unpack to elevations, after the no-data rule (identity for most files). */
    default ValueScale valueScale() {
        return ValueScale.IDENTITY;
    }

    @Override
    void close() throws IOException;
}
