package io.github.jdem846.render;

import java.util.Objects;
import java.util.concurrent.ForkJoinPool;

/**
 * How the renderer uses the machine: threads, tile size and, optionally, a pool shared with other work. The output
 * does not depend on any of them.
 *
 * <p>Without a pool, each render runs on a pool of its own of {@code parallelism} threads, created for the call
 * and shut down after it; several renders at once then each start that many threads. With a shared pool
 * ({@link #withPool}), every render submits its work to that pool, so renders running at once from several
 * threads share its threads; the renderer never creates, shuts down or resizes it (its owner does), and
 * {@code parallelism} is the pool's.
 *
 * <p>Immutable and safe to share between threads.
 *
 * @param parallelism number of worker threads, 1 to {@link #MAX_PARALLELISM}; with a pool, its parallelism (at most
 *                    {@link #MAX_PARALLELISM}) whatever is given
 * @param tileSize    tile edge in cells, {@link #MIN_TILE_SIZE} to {@link #MAX_TILE_SIZE}
 * @param pool        the pool every render runs on, owned by the caller, or {@code null} for a pool of its own per
 *                    render
 */
public record RenderSettings(int parallelism, int tileSize, ForkJoinPool pool) {

    /**
     * The default tile edge, 256 cells. Measured (docs/performance.md, "Tile size"; {@code TileSizeStudy} on the
     * 4000² fractal, 1 and 2 threads, render and hillshade): tiles of 64 to 1024 cells are within about 5 % of each
     * other, inside the run-to-run noise, so the size is not critical; 256 is in the middle of that range.
     */
    public static final int DEFAULT_TILE_SIZE = 256;

    /** Smallest tile edge: below it the per-tile overhead dominates. */
    public static final int MIN_TILE_SIZE = 16;

    /**
     * Largest tile edge, 4096 cells: each worker holds buffers of a whole tile (64 MiB of float32 at this size),
     * and tiles this large leave most workers idle on any but the largest pictures.
     */
    public static final int MAX_TILE_SIZE = 4096;

    /**
     * Most worker threads, 1024: far more than the cores of today's machines (more threads than cores only cost
     * memory, a stack each), and the same limit on every machine so that a command that works on one works on all.
     */
    public static final int MAX_PARALLELISM = 1024;

    /**
     * Checks the thread count and tile size; with a pool, the thread count becomes the pool's parallelism (at most
     * {@link #MAX_PARALLELISM}).
     *
     * @param parallelism number of worker threads, 1 to {@link #MAX_PARALLELISM}; with a pool, its parallelism (at most
     *     {@link #MAX_PARALLELISM}) whatever is given
     * @param tileSize tile edge in cells, {@link #MIN_TILE_SIZE} to {@link #MAX_TILE_SIZE}
     * @param pool the pool every render runs on, owned by the caller, or {@code null} for a pool of its own per render
     */
    public RenderSettings {
        if (pool != null) {
            parallelism = Math.min(MAX_PARALLELISM, pool.getParallelism());
        }
        if (parallelism < 1 || parallelism > MAX_PARALLELISM) {
            throw new IllegalArgumentException("threads must be 1 to " + MAX_PARALLELISM + ", got " + parallelism);
        }
        if (tileSize < MIN_TILE_SIZE || tileSize > MAX_TILE_SIZE) {
            throw new IllegalArgumentException("tile size must be " + MIN_TILE_SIZE + " to " + MAX_TILE_SIZE
                    + " cells, got " + tileSize);
        }
    }

    /**
     * Settings without a shared pool: each render starts {@code parallelism} threads of its own.
     *
     * @param parallelism number of worker threads, 1 to {@link #MAX_PARALLELISM}
     * @param tileSize    tile edge in cells, {@link #MIN_TILE_SIZE} to {@link #MAX_TILE_SIZE}
     */
    public RenderSettings(int parallelism, int tileSize) {
        this(parallelism, tileSize, null);
    }

    /**
     * A copy whose renders run on {@code pool} (shared by all renders given these settings, never shut down by
     * them), with the pool's parallelism.
     *
     * @param pool a pool the caller owns and keeps open while renders use it
     * @return the new settings
     */
    public RenderSettings withPool(ForkJoinPool pool) {
        return new RenderSettings(parallelism, tileSize, Objects.requireNonNull(pool, "pool"));
    }

    /**
     * A copy with {@code value} threads per render: without a shared pool, a pool of that many threads per render;
     * with one, the pool is kept and its parallelism counts.
     *
     * @param value number of worker threads, 1 to {@link #MAX_PARALLELISM}
     * @return the new settings
     */
    public RenderSettings withParallelism(int value) {
        return new RenderSettings(value, tileSize, pool);
    }

    /** {@return all available processors (at most {@link #MAX_PARALLELISM}) and the default tile size} */
    public static RenderSettings defaults() {
        return new RenderSettings(Math.min(MAX_PARALLELISM, Runtime.getRuntime().availableProcessors()),
                DEFAULT_TILE_SIZE);
    }
}
