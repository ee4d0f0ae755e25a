package io.github.jdem846.spark;

import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.tiles.TileJob;
import io.github.jdem846.tiles.TilePlan;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Serializable;
import java.io.StringWriter;

/**
 * What an executor needs to prepare the job's {@link TilePlan}: the arguments, where the files are and the range
 * measured on the driver. Shipped as a Spark broadcast, which each executor deserializes once and keeps, so the plan
 * (and the whole-DEM overview its small zooms read on first use) is prepared once per executor and shared by its
 * tasks, as one machine's threads share it.
 */
final class PlanSource implements Serializable {

    private static final long serialVersionUID = 1L;

    private final TileArguments arguments;
    private final InputRefs inputs;
    private final ElevationStatistics range;
    /** Guarded by this; prepared on first use in each process. */
    private transient TilePlan plan;

    PlanSource(TileArguments arguments, InputRefs inputs, ElevationStatistics range) {
        this.arguments = arguments;
        this.inputs = inputs;
        this.range = range;
    }

    /** @return the plan, prepared on first use from the executor's copies of the files */
    synchronized TilePlan plan() throws IOException {
        if (plan == null) {
            TileJob job = arguments.job(inputs.executorFiles(), new PrintWriter(new StringWriter()));
            plan = TilePlan.prepare(job, range);
        }
        return plan;
    }
}
