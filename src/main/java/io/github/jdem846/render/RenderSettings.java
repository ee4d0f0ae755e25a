package io.github.jdem846.render;

/**
 * How the renderer uses the machine: threads and tile size. The output does not depend on either.
 *
 * @param parallelism number of worker threads, 1 to {@link #MAX_PARALLELISM}
 * @param tileSize    tile edge in cells, {@link #MIN_TILE_SIZE} to {@link #MAX_TILE_SIZE}
 */
public record RenderSettings(int parallelism, int tileSize) {

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

    public RenderSettings {
        if (parallelism < 1 || parallelism > MAX_PARALLELISM) {
            throw new IllegalArgumentException("threads must be 1 to " + MAX_PARALLELISM + ", got " + parallelism);
        }
        if (tileSize < MIN_TILE_SIZE || tileSize > MAX_TILE_SIZE) {
            throw new IllegalArgumentException("tile size must be " + MIN_TILE_SIZE + " to " + MAX_TILE_SIZE
                    + " cells, got " + tileSize);
        }
    }

    /** @return all available processors (at most {@link #MAX_PARALLELISM}) and the default tile size */
    public static RenderSettings defaults() {
        return new RenderSettings(Math.min(MAX_PARALLELISM, Runtime.getRuntime().availableProcessors()),
                DEFAULT_TILE_SIZE);
    }
}
