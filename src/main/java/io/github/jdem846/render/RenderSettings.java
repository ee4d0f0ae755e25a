package io.github.jdem846.render;

/**
 * How the renderer uses the machine: threads and tile size. The output does not depend on either.
 *
 * @param parallelism number of worker threads, ≥ 1
 * @param tileSize    tile edge in cells, ≥ 16
 */
public record RenderSettings(int parallelism, int tileSize) {

    /**
     * The default tile edge, 256 cells. Measured (docs/performance.md, "Tile size"; {@code TileSizeStudy} on the
     * 4000² fractal, 1 and 2 threads, render and hillshade): tiles of 64 to 1024 cells are within about 5 % of each
     * other, inside the run-to-run noise, so the size is not critical; 256 is in the middle of that range.
     */
    public static final int DEFAULT_TILE_SIZE = 256;

    public RenderSettings {
        if (parallelism < 1) {
            throw new IllegalArgumentException("threads must be at least 1, got " + parallelism);
        }
        if (tileSize < 16) {
            throw new IllegalArgumentException("tile size must be at least 16 cells, got " + tileSize);
        }
    }

    /** All available processors and the default tile size. */
    public static RenderSettings defaults() {
        return new RenderSettings(Runtime.getRuntime().availableProcessors(), DEFAULT_TILE_SIZE);
    }
}
