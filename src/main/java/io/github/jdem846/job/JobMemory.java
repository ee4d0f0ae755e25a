package io.github.jdem846.job;

import io.github.jdem846.render.Scene;

/**
 * The heap a job's product holds, in bytes per pixel and per grid cell, to decide between rendering in memory and
 * in tiles and to size the tiles ({@link TileLayout}). What it counts: the grid read (float32 per cell, another for
 * an enlarged grid's coverage, and the decimated read a resampled grid is made from), the layers the stages hold per pixel (the shadowed fraction,
 * the soft shadows' levels) and the picture itself; one band of rows of the picture when rendered in tiles. Not
 * counted: the readers' and encoders' buffers and the JVM's own, which is why the default budget is half the heap.
 *
 * @param perPixel    bytes a stage holds per pixel of the picture (or of a tile), the picture's own included
 * @param outputBytes bytes of one pixel of the picture handed to the image file (4 RGBA, 1 gray)
 */
record JobMemory(int perPixel, int outputBytes) {

    /** The needs of {@code product} drawn with {@code scene} (the product's scene: stages it does not draw off). */
    static JobMemory of(Product product, Scene scene) {
        int shadow = !scene.hasShadows() ? 0 : scene.shadowOptions().softShadows() ? 12 : Float.BYTES;
        int sky = scene.hasAmbient() ? Float.BYTES : 0;
        // a drape's colours, the cells' coordinates in its CRS while they are sampled, and the image's pixels
        // under them (about as many, at the picture's resolution)
        int drape = scene.drape() != null ? 2 * Integer.BYTES + 2 * Double.BYTES : 0;
        return switch (product) {
            case RELIEF -> new JobMemory(Integer.BYTES + shadow + sky + drape, Integer.BYTES);
            case SKY_VIEW -> new JobMemory(Byte.BYTES + Float.BYTES, Byte.BYTES);
            case TINT -> new JobMemory(Integer.BYTES + drape, Integer.BYTES);
            case HILLSHADE -> new JobMemory(Byte.BYTES, Byte.BYTES);
            case SHADOWS -> new JobMemory(Byte.BYTES + shadow, Byte.BYTES);
        };
    }

    /**
     * Bytes of a grid of {@code cells} at the picture's resolution, read through a decimated read of {@code
     * readCells} cells when it is resampled from one (0 otherwise): both are held while it is made. An enlarged
     * grid also holds a coverage per cell (anti-aliased no-data edges).
     */
    static long gridBytes(long cells, long readCells, boolean enlarged) {
        return Float.BYTES * ((enlarged ? 2 : 1) * cells + readCells);
    }

    /** Bytes of rendering {@code pixels} at once from a grid of {@code gridBytes}. */
    long render(long gridBytes, long pixels) {
        return gridBytes + pixels * perPixel;
    }
}
