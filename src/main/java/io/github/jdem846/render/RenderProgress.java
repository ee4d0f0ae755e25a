package io.github.jdem846.render;

/**
 * Receives progress of a render from the worker threads. Implementations must be thread-safe and cheap; they are
 * called once per finished unit of work.
 */
@FunctionalInterface
public interface RenderProgress {

    /** Ignores all progress. */
    RenderProgress NONE = (stage, done, total) -> { };

    /**
     * @param stage a short name of the running stage ("shadows", "shading")
     * @param done  units finished so far in this stage
     * @param total units in this stage
     */
    void update(String stage, long done, long total);
}
