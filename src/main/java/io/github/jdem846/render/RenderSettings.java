package io.github.jdem846.render;

/**
 * How the renderer uses the machine: threads and tile size. The output does not depend on either.
 *
 * @param parallelism number of worker threads, ≥ 1
 * @param tileSize    tile edge in cells, ≥ 16
 */
public record RenderSettings(int parallelism, int tileSize) {

    /**
     * The default tile edge. Measured on a 4000² render (docs/performance.md): tiles of 128–512 cells are within
     * noise of each other; 256 keeps a tile's working set (256² floats ≈ 256 KiB per layer) in L2.
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
