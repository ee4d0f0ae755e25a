package io.github.jdem846.job;

import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.sun.SunPosition;

/**
 * Hears what a {@link ReliefJob} does: progress of its stages, notices for the user, the end of each phase and the
 * sun it computed. All methods have empty defaults; progress may be called from worker threads.
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
     * @param phase "read", then the product's stage ("render", "hillshade", "tint", "shadows"), then "write"
     */
    default void phaseDone(String phase) {
    }

    /**
     * The sun by date and time was computed.
     *
     * @param sun its position at the centre of the grid read
     */
    default void sun(SunPosition sun) {
    }
}
