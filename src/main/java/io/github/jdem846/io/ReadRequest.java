package io.github.jdem846.io;

/**
 * What to read of a DEM: an optional window, a decimation factor and a memory limit.
 *
 * <p>With decimation {@code d > 1} each output cell is the mean of the valid cells of a {@code d × d} block of
 * the window (NaN when all are no-data); the last block of a row or column may be partial and averages what it
 * holds. The geometry is {@code GridGeometry.window(...).decimate(d, d)}.
 *
 * @param window      the part to read, or {@code null} for the whole grid
 * @param decimation  block size ≥ 1 (1 = every cell)
 * @param memoryLimit most heap bytes the read may take: the grid plus the working buffers (row bands and the
 *                    strips or tiles decoded at once); a read that would need more is refused before it allocates,
 *                    as one that does not fit in the heap always is. {@link Long#MAX_VALUE}: the heap is the limit
 */
public record ReadRequest(Window window, int decimation, long memoryLimit) {

    /** The whole grid at full resolution. */
    public static final ReadRequest FULL = new ReadRequest(null, 1);

    /**
     * Checks that the decimation is ≥ 1 and the memory limit ≥ 0.
     *
     * @param window the part to read, or {@code null} for the whole grid
     * @param decimation block size ≥ 1 (1 = every cell)
     * @param memoryLimit most heap bytes the read may take: the grid plus the working buffers (row bands and the strips
     *     or tiles decoded at once); a read that would need more is refused before it allocates, as one that does not
     *     fit in the heap always is. {@link Long#MAX_VALUE}: the heap is the limit
     */
    public ReadRequest {
        if (decimation < 1) {
            throw new IllegalArgumentException("decimation must be a whole number ≥ 1, got " + decimation);
        }
        if (memoryLimit < 0) {
            throw new IllegalArgumentException("memory limit must be ≥ 0 bytes, got " + memoryLimit);
        }
    }

    /**
     * A request limited only by the heap.
     *
     * @param window     the part to read, or {@code null} for the whole grid
     * @param decimation block size ≥ 1
     */
    public ReadRequest(Window window, int decimation) {
        this(window, decimation, Long.MAX_VALUE);
    }

    /**
     * A window at full resolution.
     *
     * @param window the part to read
     * @return the request
     */
    public static ReadRequest of(Window window) {
        return new ReadRequest(window, 1);
    }

    /**
     * The whole grid, box-averaged.
     *
     * @param factor the block size: {@code factor × factor} cells make one
     * @return the request
     */
    public static ReadRequest decimated(int factor) {
        return new ReadRequest(null, factor);
    }

    /**
     * A copy with a memory limit.
     *
     * @param bytes most heap bytes the read may take
     * @return the new request
     */
    public ReadRequest withMemoryLimit(long bytes) {
        return new ReadRequest(window, decimation, bytes);
    }
}
