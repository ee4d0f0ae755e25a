package io.github.jdem846.output;

import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.zip.Deflater;

/**
 * Deflaters of one level and wrapping, handed back after each block or segment and reset, so that a file's blocks
 * reuse as many as are in use at once: a new deflater allocates and clears some 270 KB, and a reset one makes the
 * same bytes as a new one. Thread-safe; {@link #end()} frees them.
 */
final class SpareDeflaters {

    private final ConcurrentLinkedQueue<Deflater> spare = new ConcurrentLinkedQueue<>();
    private final int level;
    private final boolean nowrap;

    /**
     * @param level  the deflate level, 0..9
     * @param nowrap raw deflate data (no zlib header and checksum), as {@link Deflater#Deflater(int, boolean)}
     */
    SpareDeflaters(int level, boolean nowrap) {
        this.level = level;
        this.nowrap = nowrap;
    }

    /** A fresh stream: a spare deflater, or a new one. */
    Deflater take() {
        Deflater d = spare.poll();
        return d != null ? d : new Deflater(level, nowrap);
    }

    /** Resets {@code deflater} and keeps it for a later {@link #take}; the caller no longer uses it. */
    void give(Deflater deflater) {
        deflater.reset();
        spare.offer(deflater);
    }

    /** Frees the spare deflaters; a later {@link #take} makes new ones. */
    void end() {
        for (Deflater d = spare.poll(); d != null; d = spare.poll()) {
            d.end();
        }
    }
}
