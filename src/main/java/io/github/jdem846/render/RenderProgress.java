package io.github.jdem846.render;

/**
 * Receives progress of a render, a read or a write, stage by stage, from the worker threads. Implementations must be
 * thread-safe and cheap; they are called once per finished band of rows, block of sweep lines or tile, never per
 * cell, and at most a few hundred times per stage ({@link StageProgress}).
 *
 * <p>The library's stages report in this order (each only when it runs): {@value #READ} (rows of the grid read,
 * at the read's resolution), {@value #STATISTICS} (rows of the whole file streamed for its elevation range, when a
 * window or a tiled picture needs it), {@value #SHADOWS} (blocks of sun-parallel sweep lines, or rows of marched
 * rays; for soft shadows every elevation across the sun's disk), {@value #SHADING} (tiles tinted, lit and
 * composited) or {@value #HILLSHADE} (tiles lit), then {@value #WRITE} (rows encoded into the file: PNG segments,
 * TIFF strips, COG tile rows of every level, overviews included). A picture rendered in tiles reports one stage
 * named after the product's phase instead, counting the picture's pixels. Within a stage, {@code done} only grows,
 * never passes {@code total}, and a stage that finishes ends with {@code done == total}; {@code total} stays the
 * same within a stage.
 */
@FunctionalInterface
public interface RenderProgress {

    /** Ignores all progress. */
    RenderProgress NONE = (stage, done, total) -> { };

    /** The read of the grid: rows. */
    String READ = "read";
    /** The whole file streamed for its elevation range: rows. */
    String STATISTICS = "statistics";
    /** Cast shadows: blocks of sweep lines or rows of rays. */
    String SHADOWS = "shadows";
    /** Tint, illumination and composition of a relief or a tint: tiles. */
    String SHADING = "shading";
    /** The illumination of a hillshade product: tiles. */
    String HILLSHADE = "hillshade";
    /** The picture encoded into its file: rows (of every level of a COG). */
    String WRITE = "write";

    /**
     * Hears that {@code done} of {@code total} units of {@code stage} are finished.
     *
     * @param stage a short name of the running stage ({@link #READ}, {@link #SHADOWS}, …)
     * @param done  units finished so far in this stage, 0 ≤ done ≤ total
     * @param total units in this stage
     */
    void update(String stage, long done, long total);
}
