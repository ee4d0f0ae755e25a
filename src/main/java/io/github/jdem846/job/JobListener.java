package io.github.jdem846.job;

import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.sun.SunPosition;

/**
 * Hears what a {@link ReliefJob} does: progress of its stages, notices for the user, the end of each phase and the
 * sun it computed. All methods have empty defaults; progress may be called from worker threads. A picture rendered
 * in tiles reports one stage, named after the product's phase, counting the picture's pixels (a {@code long}: there
 * may be more than 2³¹), and only ever growing.
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
