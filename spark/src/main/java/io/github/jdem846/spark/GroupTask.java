package io.github.jdem846.spark;

import io.github.jdem846.tiles.EncodedTile;
import io.github.jdem846.tiles.TileGroup;
import io.github.jdem846.tiles.TilePlan;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import org.apache.hadoop.conf.Configuration;
import org.apache.spark.TaskContext;
import org.apache.spark.api.java.function.FlatMapFunction;
import org.apache.spark.broadcast.Broadcast;

/**
 * One Spark task: renders its partition's tile groups one after another with the library's code, from the plan its
 * executor prepared once ({@link PlanSource}), and writes their tiles to the staging directory.
 */
final class GroupTask implements FlatMapFunction<Iterator<TileGroup>, RenderedPart> {

    private static final long serialVersionUID = 1L;

    private final Broadcast<PlanSource> source;
    private final TileStaging staging;
    private final HadoopConf conf;
    private final TaskProbe probe;

    GroupTask(Broadcast<PlanSource> source, TileStaging staging, HadoopConf conf, TaskProbe probe) {
        this.source = source;
        this.staging = staging;
        this.conf = conf;
        this.probe = probe;
    }

    @Override
    public Iterator<RenderedPart> call(Iterator<TileGroup> groups) throws Exception {
        if (!groups.hasNext()) {
            return List.<RenderedPart>of().iterator();
        }
        TilePlan plan = source.value().plan();
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
