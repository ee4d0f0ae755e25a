package io.github.jdem846.shadow;

/**
 * Hears how far a cast-shadow computation has come ({@link ShadowAlgorithm#computeWindow(io.github.jdem846.raster.Dem,
 * io.github.jdem846.light.LightDirection, ShadowOptions, java.util.concurrent.ForkJoinPool, CellWindow,
 * ShadowProgress)}): blocks of sweep lines (for soft shadows, of every elevation across the sun's disk) or rows of
 * marched rays. Called from the worker threads, one call at a time, after each block; {@code done} never decreases,
 * {@code total} stays the same within a computation, and the last call has {@code done == total}.
 */
@FunctionalInterface
public interface ShadowProgress {

    /** Hears nothing. */
    ShadowProgress NONE = (done, total) -> { };

    /**
     * Hears that {@code done} of {@code total} units are finished.
     *
     * @param done  units finished so far
     * @param total units in all
     */
    void update(long done, long total);
}
