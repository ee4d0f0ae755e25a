package io.github.jdem846.spark;

import io.github.jdem846.tiles.TileGroup;
import java.io.Serializable;

/**
 * Called on the executor after each group of tiles is written: a hook for tests that make a task fail part-way, to
 * check that Spark's retry leaves the output as it would be without the failure.
 */
@FunctionalInterface
interface TaskProbe extends Serializable {

    /** Does nothing. */
    TaskProbe NONE = group -> { };

    /** Called after {@code group}'s tiles are written. */
    void groupWritten(TileGroup group) throws Exception;
}
