package io.github.jdem846.spark;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.job.JobListener;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.tiles.TileJob;
import io.github.jdem846.tiles.TileReport;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import org.apache.spark.SparkConf;
import org.apache.spark.TaskContext;
import org.apache.spark.api.java.JavaSparkContext;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The Spark job on {@code local[2]} against the single-machine {@link TileJob#run} of the same arguments, on a
 * mosaic of four GridFloat tiles cut from the Jacksboro SRTM 3″ DEM: the same PMTiles archive byte for byte and the
 * same {@code z/x/y.png} files, with cast shadows from a low western sun that run across the mosaic's seams and the
 * partitions' borders; the same after a task fails part-way and Spark retries it; the range measured in many bands
 * equals the one-machine range; bad input gives one line and leaves nothing.
 */
class SparkTilesTest {

    static final Path JACKSBORO = Path.of("..", "testdata", "dem", "jacksboro_srtm3s_wgs84");

    @TempDir
    static Path dir;
    static JavaSparkContext sc;
    static List<String> mosaic;

    @BeforeAll
    static void start() throws IOException {
        // two cores, and up to 4 attempts per task so that a failed task is retried
        sc = new JavaSparkContext(new SparkConf().setMaster("local[2,4]").setAppName("SparkTilesTest")
                .set("spark.ui.enabled", "false").set("spark.driver.host", "127.0.0.1")
                .set("spark.ui.showConsoleProgress", "false")
                .set("spark.hadoop.fs." + RemoteLikeFileSystem.SCHEME + ".impl", RemoteLikeFileSystem.class.getName()));
        sc.setLogLevel("ERROR");
        mosaic = GridFloatCuts.quarters(JACKSBORO, 200, 170, dir.resolve("mosaic")).stream()
                .map(Path::toString).toList();
    }

    @AfterAll
    static void stop() {
        if (sc != null) {
            sc.close();
        }
    }

    static List<String> args(String output) {
        List<String> a = new ArrayList<>(mosaic);
        a.addAll(List.of("--zoom", "8-11", "--shadows", "sweep", "--sun-azimuth", "280", "--sun-elevation", "8",
                "--png-level", "1", "-o", output));
        return a;
    }

    /** The single machine's run of the same arguments, as {@code jdem846 tiles} does it. */
    static TileReport single(Path output) throws Exception {
        TileArguments a = TileArguments.of(args(output.toString()));
        TileJob job = a.job(a.files(), new PrintWriter(new StringWriter()));
        return job.run(output, JobListener.NONE);
    }

    @Test
    void pmtilesEqualTheSingleMachineArchive() throws Exception {
        Path one = dir.resolve("one.pmtiles");
        TileReport expected = single(one);
        Path spark = dir.resolve("spark.pmtiles");
        TileReport report = SparkTiles.run(sc, args(spark.toString()), JobListener.NONE);
        assertArrayEquals(Files.readAllBytes(one), Files.readAllBytes(spark));
        assertEquals(expected.written(), report.written());
        assertEquals(expected.bytes(), report.bytes());
        assertTrue(report.written() > 16, "more than one group of tiles: " + report.written());
        assertNoStaging(dir);
    }

    @Test
    void inputsAndOutputOnAnotherFileSystemGiveTheSameArchive() throws Exception {
        Path one = dir.resolve("one-for-remote.pmtiles");
        single(one);
        Path remote = dir.resolve("remote.pmtiles");
        String scheme = RemoteLikeFileSystem.SCHEME + "://";
        List<String> a = new ArrayList<>(List.of(scheme + dir.resolve("mosaic").toAbsolutePath() + "/*.flt"));
        a.addAll(args(scheme + remote.toAbsolutePath()).subList(mosaic.size(), args("x").size()));
        SparkTiles.run(sc, a, JobListener.NONE);
        assertArrayEquals(Files.readAllBytes(one), Files.readAllBytes(remote));
        assertNoStaging(dir);
    }

    @Test
    void directoryEqualsTheSingleMachineDirectoryAfterARetriedTask() throws Exception {
        Path one = dir.resolve("one-dir");
        single(one);
        Path spark = dir.resolve("spark-dir");
        Path fired = dir.resolve("probe-fired");
        String marker = fired.toString();
        TaskProbe failOnce = group -> {
            TaskContext task = TaskContext.get();
            if (task.partitionId() == 0 && task.attemptNumber() == 0) {
                Files.writeString(Path.of(marker), group.toString());
                throw new IOException("a task failed part-way on purpose");
            }
        };
        SparkTiles.run(sc, args(spark.toString()), JobListener.NONE, failOnce, SparkTiles.CELLS_PER_BAND);
        assertTrue(Files.exists(fired), "the first attempt of partition 0 failed after writing a group");
        Map<String, byte[]> a = files(one);
        Map<String, byte[]> b = files(spark);
        assertEquals(a.keySet(), b.keySet(), "the same tiles, no temporaries left");
        for (String k : a.keySet()) {
            assertArrayEquals(a.get(k), b.get(k), k);
        }
        assertNoStaging(dir);
    }

    @Test
    void rangeInManyBandsEqualsTheWholeRange() throws Exception {
        Path spark = dir.resolve("banded.pmtiles");
        Path one = dir.resolve("unbanded.pmtiles");
        single(one);
        // 403 × 344 cells in bands of 403 × 5 rows: 69 tasks
        SparkTiles.run(sc, args(spark.toString()), JobListener.NONE, TaskProbe.NONE, 403 * 5);
        assertArrayEquals(Files.readAllBytes(one), Files.readAllBytes(spark));
        assertEquals(69, SparkTiles.bands(403, 344, 403 * 5).size());
        ElevationStatistics whole = io.github.jdem846.io.DemReader.statistics(
                io.github.jdem846.io.DemInput.of(mosaic.stream().map(Path::of).toList()));
        assertFalse(whole.isEmpty());
    }

    @Test
    void aDamagedTileFailsTheJobWithOneLineAndLeavesNothing() throws Exception {
        Path bad = dir.resolve("bad");
        List<Path> tiles = GridFloatCuts.quarters(JACKSBORO, 200, 170, bad);
        Path damaged = tiles.get(3);
        byte[] bytes = Files.readAllBytes(damaged);
        Files.write(damaged, java.util.Arrays.copyOf(bytes, bytes.length / 2));
        List<String> a = new ArrayList<>(tiles.stream().map(Path::toString).toList());
        Path out = dir.resolve("never.pmtiles");
        a.addAll(List.of("--zoom", "8-9", "-o", out.toString()));
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = SparkTilesMain.run(a.toArray(String[]::new), new PrintStream(new ByteArrayOutputStream()),
                new PrintStream(err, true, StandardCharsets.UTF_8), sc);
        String message = err.toString(StandardCharsets.UTF_8).strip();
        assertEquals(1, status, message);
        assertEquals(1, message.lines().count(), message);
        assertTrue(message.contains(damaged.getFileName().toString()), message);
        assertFalse(Files.exists(out));
        assertNoStaging(dir);
    }

    @Test
    void aTileThatFailsOnTheExecutorsFailsTheJobWithOneLine() throws Exception {
        // a GeoTIFF whose header reads but whose Deflate strips do not (3000 bytes from 120 000 on overwritten: the
        // CLI says "cannot decode rows 0–343 … Unexpected end of ZLIB input stream"): found by the tasks
        Path bad = Files.createDirectories(dir.resolve("corrupt")).resolve("jacksboro.tif");
        byte[] tif = Files.readAllBytes(Path.of(JACKSBORO + ".tif"));
        java.util.Arrays.fill(tif, 120_000, 123_000, (byte) 0xff);
        Files.write(bad, tif);
        Path out = dir.resolve("corrupt").resolve("tiles");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = SparkTilesMain.run(new String[] {bad.toString(), "--zoom", "8-9", "-o", out.toString()},
                new PrintStream(new ByteArrayOutputStream()), new PrintStream(err, true, StandardCharsets.UTF_8), sc);
        String message = err.toString(StandardCharsets.UTF_8).strip();
        assertEquals(1, status, message);
        assertEquals(1, message.lines().count(), message);
        assertTrue(message.startsWith("jdem846-spark: " + bad + ": cannot decode"), message);
        assertFalse(Files.exists(out));
        assertNoStaging(out.getParent());
    }

    @Test
    void badUsageExitsTwoBeforeSparkStarts() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        Integer status = SparkTilesMain.checkUsage(new String[] {mosaic.get(0), "--zoom", "99", "-o", "x.pmtiles"},
                new PrintStream(new ByteArrayOutputStream()), new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(2, status);
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("zoom"), err.toString(StandardCharsets.UTF_8));
    }

    private static Map<String, byte[]> files(Path root) throws IOException {
        Map<String, byte[]> out = new TreeMap<>();
        try (Stream<Path> all = Files.walk(root)) {
            for (Path p : all.filter(Files::isRegularFile).toList()) {
                out.put(root.relativize(p).toString(), Files.readAllBytes(p));
            }
        }
        return out;
    }

    private static void assertNoStaging(Path parent) throws IOException {
        try (Stream<Path> all = Files.list(parent)) {
            List<Path> left = all.filter(p -> p.getFileName().toString().contains("jdem846-")).toList();
            assertEquals(List.of(), left, "no staging left behind");
        }
    }
}
