package io.github.jdem846.render;

import java.util.concurrent.ConcurrentLinkedQueue;

/**
 * Float arrays for the tiles of one picture, handed back after each tile, so that the tiles reuse as many arrays as
 * there are workers instead of allocating one each: fresh heap costs the operating system a page fault and a
 * cleared page per 4 KiB, which a one-shot command pays in full (64 MB for a 4000² hillshade). Thread-safe.
 */
final class TileBuffers {

    private final ConcurrentLinkedQueue<float[]> spare = new ConcurrentLinkedQueue<>();

    /**
     * An array of at least {@code cells} values, holding whatever an earlier tile left in it.
     *
     * @param cells the values the tile needs
     * @return a spare array if one is large enough, else a new one
     */
    float[] take(int cells) {
        float[] buffer = spare.poll();
        return buffer != null && buffer.length >= cells ? buffer : new float[cells];
    }

    /** Hands {@code buffer} back for a later tile; the caller no longer uses it. */
    void give(float[] buffer) {
        spare.offer(buffer);
    }
}
