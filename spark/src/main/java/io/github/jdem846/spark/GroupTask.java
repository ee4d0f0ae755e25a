package io.github.jdem846.spark;

import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.tiles.EncodedTile;
import io.github.jdem846.tiles.TileGroup;
import io.github.jdem846.tiles.TileJob;
import io.github.jdem846.tiles.TilePlan;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import org.apache.hadoop.conf.Configuration;
import org.apache.spark.TaskContext;
import org.apache.spark.api.java.function.FlatMapFunction;

/**
 * One Spark task: prepares the job's {@link TilePlan} from the arguments and the range measured on the driver
 * (reading only the DEM's headers), renders its partition's tile groups one after another with the library's code,
 * and writes their tiles to the staging directory.
 */
final class GroupTask implements FlatMapFunction<Iterator<TileGroup>, RenderedPart> {

    private static final long serialVersionUID = 1L;

    private final TileArguments arguments;
    private final InputRefs inputs;
    private final ElevationStatistics range;
    private final TileStaging staging;
    private final HadoopConf conf;
    private final TaskProbe probe;

    GroupTask(TileArguments arguments, InputRefs inputs, ElevationStatistics range, TileStaging staging,
              HadoopConf conf, TaskProbe probe) {
        this.arguments = arguments;
        this.inputs = inputs;
        this.range = range;
        this.staging = staging;
        this.conf = conf;
        this.probe = probe;
    }

    @Override
    public Iterator<RenderedPart> call(Iterator<TileGroup> groups) throws Exception {
        if (!groups.hasNext()) {
            return List.<RenderedPart>of().iterator();
        }
        TileJob job = arguments.job(inputs.executorFiles(), new PrintWriter(new StringWriter()));
        TilePlan plan = TilePlan.prepare(job, range);
        TaskContext task = TaskContext.get();
        String attempt = task == null ? "0" : task.taskAttemptId() + "-" + task.attemptNumber();
        Configuration hadoop = conf.get();
        Map<Integer, Long> written = new HashMap<>();
        long bytes = 0;
        while (groups.hasNext()) {
            TileGroup g = groups.next();
            for (EncodedTile t : plan.render(g)) {
                staging.write(t, hadoop, attempt);
                written.merge(g.z(), 1L, Long::sum);
                bytes += t.png().length;
            }
            probe.groupWritten(g);
        }
        return List.of(new RenderedPart(written, bytes)).iterator();
    }
}
