package io.github.jdem846.job;

import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.sun.SunPosition;

/**
 * Hears what a {@link ReliefJob} does: progress of its stages, notices for the user, the end of each phase and the
 * sun it computed. All methods have empty defaults.
 *
 * <p>Progress ({@link #update}) comes stage after stage, as {@link RenderProgress} describes: {@code read} (rows of
 * the grid read), {@code statistics} (rows of the whole file streamed, when a window's tint or shadows need the
 * file's range), {@code shadows} (blocks of sweep lines or rows of rays), {@code shading} or {@code hillshade}
 * (tiles), then {@code write} (rows written into the file; for a COG, the rows of every level) for
 * {@link ReliefJob#runAndWrite}. Each stage reports at most a few hundred times, its {@code done} only growing up to
 * {@code done == total}, possibly from worker threads (one call at a time per stage). A picture rendered in tiles
 * reports {@code statistics}, then one stage named after the product's phase ("render", "hillshade", "tint",
 * "shadows") counting the picture's pixels (a {@code long}: there may be more than 2³¹) as its tiles are read,
 * rendered and written. Progress changes nothing in the picture.
 */
public interface JobListener extends RenderProgress {

    /** Hears nothing. */
    JobListener NONE = new JobListener() {
    };

    @Override
    default void update(String stage, long done, long total) {
    }

    /**
     * Something the user should know.
     *
     * @param message one line: an assumed CRS, a band ignored, a projection's scale factor, …
     */
    default void notice(String message) {
    }

    /**
     * A phase ended.
     *
     * @param phase "read", then the product's stage ("render", "hillshade", "tint", "shadows"), then "write". For
     *              a picture rendered in tiles, "read" ends once the header is read and the file's statistics
     *              streamed, the product's stage covers reading, rendering and writing the tiles, and "write"
     *              finishing the file
     */
    default void phaseDone(String phase) {
    }

    /**
     * The sun by date and time was computed.
     *
     * @param sun its position at the centre of the picture
     */
    default void sun(SunPosition sun) {
    }
}
