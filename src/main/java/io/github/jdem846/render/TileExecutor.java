package io.github.jdem846.render;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import java.util.concurrent.RecursiveAction;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Runs one task per tile of a raster on a {@link ForkJoinPool}, reporting progress and stopping promptly when the
 * calling thread is interrupted. The renderer owns threads and tiles; stages are pure functions of a rectangle.
 */
public final class TileExecutor {

    /** Work on one rectangle {@code [col0, col0 + w) × [row0, row0 + h)}. Must be thread-safe. */
    @FunctionalInterface
    public interface TileTask {
        void run(int col0, int row0, int w, int h);
    }

    private final ForkJoinPool pool;
    private final int tileSize;

    /**
     * @param pool     the pool to run on (the caller owns it)
     * @param tileSize tile edge in cells, ≥ 1
     */
    public TileExecutor(ForkJoinPool pool, int tileSize) {
        if (tileSize < 1) {
            throw new IllegalArgumentException("tile size must be at least 1, got " + tileSize);
        }
        this.pool = pool;
        this.tileSize = tileSize;
    }

    /**
     * Runs {@code task} on every tile of a {@code width × height} raster and waits for all of them.
     *
     * @throws InterruptedException  if the calling thread is interrupted; tiles not yet started are skipped
     */
    public void forEachTile(int width, int height, String stage, RenderProgress progress, TileTask task)
            throws InterruptedException {
        TileGrid grid = new TileGrid(width, height, tileSize);
        int n = grid.count();
        AtomicLong done = new AtomicLong();
        CancelFlag cancel = new CancelFlag();
        List<RecursiveAction> actions = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            int index = i;
            actions.add(new RecursiveAction() {
                @Override
                protected void compute() {
                    if (cancel.cancelled) {
                        return;
                    }
                    task.run(grid.col0(index), grid.row0(index), grid.tileWidth(index), grid.tileHeight(index));
                    progress.update(stage, done.incrementAndGet(), n);
                }
            });
        }
        ForkJoinTask<?> all = pool.submit(() -> ForkJoinTask.invokeAll(actions));
        try {
            all.get();
        } catch (InterruptedException e) {
            cancel.cancelled = true;
            all.cancel(true);
            throw e;
        } catch (java.util.concurrent.ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof RuntimeException re) {
                throw re;
            }
            if (cause instanceof Error er) {
                throw er;
            }
            throw new IllegalStateException(cause);
        } catch (CancellationException e) {
            throw new InterruptedException("render cancelled");
        }
    }

    private static final class CancelFlag {
        volatile boolean cancelled;
    }
}
