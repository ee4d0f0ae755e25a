package io.github.jdem846.job;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.Window;
import io.github.jdem846.output.GeoReference;
import io.github.jdem846.output.ImageOutput;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Scene;
import io.github.jdem846.render.StageProgress;
import io.github.jdem846.shadow.ShadowAlgorithm;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Progress of a whole job on real data (Big Tujunga, SRTM 30 m, 1197 × 643 cells): every stage reports, in order,
 * growing to its total in many steps, and the listener changes no byte of the file.
 */
class JobProgressTest {

    private static final Path TUJUNGA = Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif");
    private static final int HEIGHT = 643;

    @TempDir
    Path dir;

    private static ReliefJob job(ShadowAlgorithm shadows) {
        return ReliefJob.of(TUJUNGA).withScene(Scene.defaults().withShadows(shadows))
                .withExecution(new RenderSettings(2, 128));
    }

    @Test
    void sweepToPngReportsEveryStageInOrderAndWritesTheSameBytes() throws Exception {
        RecordingListener listener = new RecordingListener();
        Path png = dir.resolve("sweep.png");
        job(ShadowAlgorithm.SWEEP).runAndWrite(png, WriteOptions.defaults(), listener);

        assertEquals(List.of("read", "shadows", "shading", "write"), listener.order());
        listener.assertStage(RenderProgress.READ, 20);
        assertEquals(HEIGHT, listener.of("read").get(0).total(), "read counts the grid's rows");
        listener.assertStage(RenderProgress.SHADOWS, 20);
        listener.assertStage(RenderProgress.SHADING, 20);           // 10 × 6 tiles of 128
        // a 1197-pixel RGBA row is 4789 filtered bytes: 218 rows per 1 MiB deflate segment, 3 segments
        listener.assertStage(RenderProgress.WRITE, 2);
        assertEquals(HEIGHT, listener.of("write").get(0).total(), "write counts the picture's rows");

        Path quiet = dir.resolve("quiet.png");
        job(ShadowAlgorithm.SWEEP).run(JobListener.NONE).write(quiet, WriteOptions.defaults());
        assertArrayEquals(Files.readAllBytes(quiet), Files.readAllBytes(png), "progress changed the file");
    }

    @Test
    void marchToCogCountsTheRowsOfEveryLevelAndWritesTheSameBytes() throws Exception {
        WriteOptions cog = WriteOptions.defaults().withTiffLayout(WriteOptions.TiffLayout.COG).withCogTileSize(32);
        RecordingListener listener = new RecordingListener();
        Path tif = dir.resolve("march.tif");
        job(ShadowAlgorithm.MARCH).runAndWrite(tif, cog, listener);

        assertEquals(List.of("read", "shadows", "shading", "write"), listener.order());
        listener.assertStage(RenderProgress.READ, 20);
        listener.assertStage(RenderProgress.SHADOWS, 20);            // 65 runs of 10 rows
        listener.assertStage(RenderProgress.SHADING, 20);
        listener.assertStage(RenderProgress.WRITE, 20);              // tile rows of 32 on 7 levels
        // levels halve (rounded down) until one tile holds the smallest: 643, 321, 160, 80, 40, 20, 10 rows
        assertEquals(643 + 321 + 160 + 80 + 40 + 20 + 10, listener.of("write").get(0).total());

        Path quiet = dir.resolve("quiet.tif");
        job(ShadowAlgorithm.MARCH).run(JobListener.NONE).write(quiet, cog);
        assertArrayEquals(Files.readAllBytes(quiet), Files.readAllBytes(tif), "progress changed the file");
    }

    @Test
    void softShadowsAndAHillshadeReportTheirOwnStages() throws Exception {
        RecordingListener soft = new RecordingListener();
        job(ShadowAlgorithm.SWEEP).withScene(Scene.defaults().withShadows(ShadowAlgorithm.SWEEP)
                .withShadowOptions(io.github.jdem846.shadow.ShadowOptions.DEFAULTS.withSoftShadows(true)))
                .withProduct(Product.SHADOWS).runAndWrite(dir.resolve("soft.png"), WriteOptions.defaults(), soft);
        assertEquals(List.of("read", "shadows", "write"), soft.order());
        soft.assertStage(RenderProgress.SHADOWS, 20);
        soft.assertStage(RenderProgress.WRITE, 0);                   // a gray picture of 0.77 MB: one segment

        RecordingListener hillshade = new RecordingListener();
        job(ShadowAlgorithm.NONE).withProduct(Product.HILLSHADE)
                .runAndWrite(dir.resolve("hillshade.tif"), WriteOptions.defaults(), hillshade);
        assertEquals(List.of("read", "hillshade", "write"), hillshade.order());
        hillshade.assertStage(RenderProgress.HILLSHADE, 20);
        hillshade.assertStage(RenderProgress.WRITE, 10);             // 12 strips of 54 rows (64 KiB)
    }

    @Test
    void aWindowWithShadowsStreamsTheFileStatisticsAsAStageOfItsOwn() throws Exception {
        RecordingListener listener = new RecordingListener();
        ElevationStatistics whole = DemReader.statistics(TUJUNGA);
        job(ShadowAlgorithm.SWEEP).withWindow(Window.cells(300, 200, 400, 300)).run(listener);
        assertEquals("statistics", listener.order().get(0), listener.order().toString());
        listener.assertStage(RenderProgress.STATISTICS, 20);
        assertEquals(HEIGHT, listener.of("statistics").get(0).total(), "the whole file is streamed");
        listener.assertStage(RenderProgress.READ, 20);
        listener.assertStage(RenderProgress.SHADOWS, 5);
        assertTrue(whole.validCount() > 0);
    }

    @Test
    void aPictureInTilesReportsItsPixelsGrowingToTheTotal() throws Exception {
        RecordingListener listener = new RecordingListener();
        Path png = dir.resolve("tiled.png");
        job(ShadowAlgorithm.SWEEP).withMemory(1 << 20).runAndWrite((picture, rgba) -> ImageOutput.openRgba(png,
                picture.width(), picture.height(), GeoReference.of(picture), WriteOptions.defaults()),
                result -> fail("a budget of 1 MiB must not hold the picture"), listener,
                (plan, halo, unit, needs, budget) -> TileLayout.sized(plan, halo, needs, 256, 128));
        assertEquals(List.of("statistics", "render"), listener.order());
        listener.assertStage(RenderProgress.STATISTICS, 20);
        listener.assertStage("render", 20);
        assertEquals(1197L * HEIGHT, listener.of("render").get(0).total());
        assertTrue(listener.of("render").size() <= StageProgress.STEPS + 2, "thinned to about 200 updates");
    }

    @Test
    void anInterruptWhileReadingEndsTheJobAsAnInterruptAndLeavesNoFile() throws Exception {
        // the listener hears the read on the calling thread (one part: the file has fewer than 2²¹ cells)
        for (String stage : new String[] {RenderProgress.READ}) {
            Path png = dir.resolve("interrupted-" + stage + ".png");
            JobListener interrupting = new JobListener() {
                @Override
                public void update(String s, long done, long total) {
                    if (s.equals(stage) && done > 0) {
                        Thread.currentThread().interrupt();
                    }
                }
            };
            assertThrows(InterruptedException.class, () -> job(ShadowAlgorithm.NONE).runAndWrite(png,
                    WriteOptions.defaults(), interrupting), stage);
            assertFalse(Thread.interrupted(), stage + ": the exception reports the interrupt, the status is cleared");
            try (java.util.stream.Stream<Path> left = Files.list(dir)) {
                assertEquals(List.of(), left.toList(), stage + ": nothing is left");
            }
        }
    }
}
