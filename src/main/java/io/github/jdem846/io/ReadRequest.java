package io.github.jdem846.io;

/**
 * What to read of a DEM: an optional window and a decimation factor.
 *
 * <p>With decimation {@code d > 1} each output cell is the mean of the valid cells of a {@code d × d} block of
 * the window (NaN when all are no-data); the last block of a row or column may be partial and averages what it
 * holds. The geometry is {@code GridGeometry.window(...).decimate(d, d)}.
 *
 * @param window     the part to read, or {@code null} for the whole grid
 * @param decimation block size ≥ 1 (1 = every cell)
 */
public record ReadRequest(Window window, int decimation) {

    /** The whole grid at full resolution. */
    public static final ReadRequest FULL = new ReadRequest(null, 1);

    public ReadRequest {
        if (decimation < 1) {
            throw new IllegalArgumentException("decimation must be a whole number ≥ 1, got " + decimation);
        }
    }

    /** A window at full resolution. */
    public static ReadRequest of(Window window) {
        return new ReadRequest(window, 1);
    }

    /** The whole grid, box-averaged over {@code factor × factor} blocks. */
    public static ReadRequest decimated(int factor) {
        return new ReadRequest(null, factor);
    }
}
