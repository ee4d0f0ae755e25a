package io.github.jdem846.render;

import io.github.jdem846.parallel.Cancellation;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ForkJoinPool;

/**
 * Runs one task per tile of a raster on a {@link ForkJoinPool}, reporting progress and stopping promptly when the
 * calling thread is interrupted. The renderer owns threads and tiles; stages are pure functions of a rectangle.
 */
final class TileExecutor {

    /** Work on one rectangle {@code [col0, col0 + w) × [row0, row0 + h)}. Must be thread-safe. */
    @FunctionalInterface
    interface TileTask {
        void run(int col0, int row0, int w, int h);
    }

    private final ForkJoinPool pool;
    private final int tileSize;

    /**
     * @param pool     the pool to run on (the caller owns it)
     * @param tileSize tile edge in cells, ≥ 1
     */
    TileExecutor(ForkJoinPool pool, int tileSize) {
        if (tileSize < 1) {
            throw new IllegalArgumentException("tile size must be at least 1, got " + tileSize);
        }
        this.pool = pool;
        this.tileSize = tileSize;
    }

    /**
     * Runs {@code task} on every tile of a {@code width × height} raster and waits for all of them, reporting
     * {@code stage} in tiles ({@link StageProgress}).
     *
     * @throws InterruptedException if the calling thread is interrupted: tiles not yet started are skipped, the call
     *                              returns once the running ones have finished, and the interrupt status is cleared
     */
    void forEachTile(int width, int height, String stage, RenderProgress progress, TileTask task)
            throws InterruptedException {
        TileGrid grid = new TileGrid(width, height, tileSize);
        int n = grid.count();
        StageProgress done = new StageProgress(progress, stage, n).start();
        try {
            Cancellation.invokeAll(pool, n, (index, cancel) -> {
                task.run(grid.col0(index), grid.row0(index), grid.tileWidth(index), grid.tileHeight(index));
                done.add(1);
            });
        } catch (CancellationException e) {
            throw interrupted(e);
        }
    }

    /**
     * The {@link InterruptedException} of a render stopped by {@link Cancellation} (the interrupt status cleared, as
     * for any method that throws it).
     */
    static InterruptedException interrupted(CancellationException cause) {
        Thread.interrupted();
        InterruptedException e = new InterruptedException("render cancelled");
        e.initCause(cause);
        return e;
    }
}
