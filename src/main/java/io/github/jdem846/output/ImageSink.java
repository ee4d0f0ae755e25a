package io.github.jdem846.output;

import java.io.IOException;

/**
 * An image file written band of rows after band of rows, north to south, for pictures made piece by piece.
 * Nothing appears under the target name until {@link #commit()}: {@link #close()} without a commit (a failure, an
 * interrupted job) deletes what was staged and leaves an existing file of that name unchanged. The bytes written
 * are those {@link ImageOutput#writeRgba} or {@link ImageOutput#writeGray} write for the whole picture with the
 * same options, however the rows are cut into bands. The rows are encoded as they arrive: memory is bounded by a
 * band and the encoder's buffers, not by the picture.
 *
 * <p>Open one with {@link ImageOutput#openRgba} or {@link ImageOutput#openGray}. Not thread-safe.
 */
public interface ImageSink extends AutoCloseable {

    /** {@return pixels across} */
    int width();

    /** {@return pixels down} */
    int height();

    /** {@return rows appended so far} */
    int rowsWritten();

    /**
     * Appends {@code rows} rows of RGBA pixels (a sink opened with {@link ImageOutput#openRgba}).
     *
     * @param argb   non-premultiplied 0xAARRGGBB pixels, row-major, {@code width × rows} from index 0 (the array
     *               may be longer; it is not kept, and may be reused for the next band)
     * @param rows   how many rows (0 does nothing)
     * @throws IllegalStateException    when the sink holds gray pixels, the rows would pass the bottom, or an earlier
     *                                  failure or the commit ended the sink
     * @throws IllegalArgumentException when the array holds fewer than {@code width × rows} pixels
     * @throws IOException              when the file cannot be written
     */
    void appendRgba(int[] argb, int rows) throws IOException;

    /**
     * Appends {@code rows} rows of 8-bit gray samples (a sink opened with {@link ImageOutput#openGray}).
     *
     * @param gray 0..255 samples, row-major, {@code width × rows} from index 0 (the array may be longer; it is not
     *             kept, and may be reused for the next band)
     * @param rows how many rows (0 does nothing)
     * @throws IllegalStateException    when the sink holds RGBA pixels, the rows would pass the bottom, or an earlier
     *                                  failure or the commit ended the sink
     * @throws IllegalArgumentException when the array holds fewer than {@code width × rows} samples
     * @throws IOException              when the file cannot be written
     */
    void appendGray(byte[] gray, int rows) throws IOException;

    /**
     * Finishes the file and its sidecars and moves them into place, once every row was appended.
     *
     * @return the files written and notices for the user
     * @throws IllegalStateException when rows are missing
     * @throws IOException           when the files cannot be written or moved
     */
    WriteResult commit() throws IOException;

    /** Deletes what was staged unless {@link #commit()} succeeded. */
    @Override
    void close() throws IOException;
}
