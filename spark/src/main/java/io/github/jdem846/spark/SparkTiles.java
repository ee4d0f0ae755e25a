package io.github.jdem846.spark;

import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.job.JobListener;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.tiles.TileGroup;
import io.github.jdem846.tiles.TileJob;
import io.github.jdem846.tiles.TilePlan;
import io.github.jdem846.tiles.TileReport;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;
import org.apache.hadoop.conf.Configuration;
import org.apache.spark.api.java.JavaSparkContext;
import org.apache.spark.broadcast.Broadcast;

/**
 * {@code jdem846 tiles} on Apache Spark: the same arguments, the same tiles, byte for byte.
 *
 * <p>Three stages, none of which loops over cells on the driver: the elevation range measured in row bands of the
 * DEM (or mosaic) on the executors and merged; the {@link TilePlan}'s groups of up to 4 × 4 tiles spread over tasks,
 * each task preparing the plan from the arguments and that range (reading only headers) and rendering its groups
 * with the library's code, cast-shadow halos included, so shadows run on across partitions exactly as across a
 * single machine's threads; the staged tiles moved into place by the driver ({@link TileStaging}).
 *
 * <pre>{@code
 * try (JavaSparkContext sc = new JavaSparkContext(new SparkConf().setAppName("relief"))) {
 *     TileReport report = SparkTiles.run(sc, List.of("hdfs:///dem/*.tif", "--zoom", "0-12",
 *             "--shadows", "sweep", "-o", "hdfs:///tiles/relief.pmtiles"), JobListener.NONE);
 * }
 * }</pre>
 */
public final class SparkTiles {

    /** Cells of the DEM read by one task of the range stage. */
    static final long CELLS_PER_BAND = 1L << 24;
    /**
     * Tasks of the render stage per core, at most: enough that cores which finish early take more, few enough that
     * Spark's cost per task (tens of milliseconds) stays small against a task's groups.
     */
    static final int TASKS_PER_CORE = 16;

    private SparkTiles() {
    }

    /**
     * Renders the pyramid the arguments of {@code jdem846 tiles} describe.
     *
     * @param tilesArguments FILE… (local paths, or paths of any Hadoop file system with globs and directories),
     *                       {@code --zoom}, {@code -o} (a local path or a Hadoop path) and any shading option of
     *                       {@code jdem846 tiles}; {@code --threads} does not apply (Spark's cores do)
     * @param listener       told of notices, the sun computed and the phases' ends
     * @return what was written
     * @throws picocli.CommandLine.ParameterException for bad usage, saying what is wrong
     * @throws IOException                            naming the file that cannot be read or the output that cannot
     *                                                be written; nothing is left at the output
     * @throws IllegalArgumentException               for settings that do not make sense for map tiles
     * @throws org.apache.spark.SparkException        when a task fails after Spark's retries (its message holds
     *                                                the task's error)
     */
    public static TileReport run(JavaSparkContext sc, List<String> tilesArguments, JobListener listener)
            throws IOException {
        return run(sc, tilesArguments, listener, TaskProbe.NONE, CELLS_PER_BAND);
    }

    static TileReport run(JavaSparkContext sc, List<String> tilesArguments, JobListener listener, TaskProbe probe,
                          long cellsPerBand) throws IOException {
        TileArguments arguments = TileArguments.of(tilesArguments);
        Configuration conf = sc.hadoopConfiguration();
        Path copies = Files.createTempDirectory("jdem846-spark-inputs");
        try {
            InputRefs inputs = InputRefs.resolve(arguments.files(), sc, conf, copies);
            StringWriter notes = new StringWriter();
            TileJob job = arguments.job(inputs.driverFiles(), new PrintWriter(notes, true));
            notes.toString().lines().map(l -> l.replaceFirst("^jdem846: note: ", "")).forEach(listener::notice);
            String output = arguments.output();
            String localOutput = InputRefs.localPath(output);
            if (localOutput != null) {
                job.checkOutput(Path.of(localOutput));
            }
            job.requireTileable();
            DemInfo info = DemReader.inspect(job.input());
            info.notices().forEach(listener::notice);

            List<int[]> bands = bands(info.width(), info.height(), cellsPerBand);
            ElevationStatistics range = sc.parallelize(bands, bands.size())
                    .map(new RangeTask(arguments, inputs))
                    .reduce(ElevationStatistics::merge);
            if (range.isEmpty()) {
                throw new IOException(info.source() + " holds no elevations (every cell is no-data)");
            }
            listener.phaseDone("read");

            TilePlan plan = TilePlan.prepare(job, range, listener);
            TileStaging staging = TileStaging.create(output, conf);
            boolean committed = false;
            try {
                List<TileGroup> groups = plan.groups();
                int slices = Math.max(1, Math.min(groups.size(), TASKS_PER_CORE * sc.defaultParallelism()));
                Broadcast<PlanSource> source = sc.broadcast(new PlanSource(arguments, inputs, range));
                RenderedPart total;
                try {
                    total = sc.parallelize(groups, slices)
                            .mapPartitions(new GroupTask(source, staging, new HadoopConf(conf), probe))
                            .reduce(RenderedPart::plus);
                } finally {
                    source.destroy();
                }
                listener.phaseDone("render");
                if (total.written() == 0) {
                    throw new IOException("no tile of zoom " + job.zooms() + " holds data of " + info.source()
                            + ": nothing written");
                }
                staging.commit(plan, conf);
                committed = true;
                listener.phaseDone("write");
                return plan.report(Path.of(localOutput != null ? localOutput : output), staging.format(),
                        total.writtenByZoom(), total.bytes());
            } finally {
                if (!committed) {
                    staging.abort(conf);
                }
            }
        } finally {
            deleteTree(copies);
        }
    }

    /** Row bands of about {@code cellsPerBand} cells: {first row, rows, width}. */
    static List<int[]> bands(int width, int height, long cellsPerBand) {
        int rows = (int) Math.max(1, Math.min(height, cellsPerBand / Math.max(1, width)));
        List<int[]> out = new ArrayList<>();
        for (int r = 0; r < height; r += rows) {
            out.add(new int[] {r, Math.min(rows, height - r), width});
        }
        return out;
    }

    private static void deleteTree(Path root) throws IOException {
        try (Stream<Path> all = Files.walk(root)) {
            for (Path p : all.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        }
    }
}
