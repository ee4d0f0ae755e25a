package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

class KernelWarmUpTest {

    @BeforeEach
    void warmUpsOn() {
        System.setProperty(WarmUpThread.PROPERTY, "on");
    }

    @AfterEach
    void warmUpsAsBefore() {
        System.clearProperty(WarmUpThread.PROPERTY);
    }

    @Test
    void runsTheStageOnASmallRealisticGridUntilStopped() throws Exception {
        AtomicInteger rounds = new AtomicInteger();
        CountDownLatch first = new CountDownLatch(1);
        float[] seen = new float[2];
        KernelWarmUp warmUp = KernelWarmUp.start(dem -> {
            seen[0] = (float) dem.statistics().min();
            seen[1] = (float) dem.statistics().max();
            rounds.incrementAndGet();
            first.countDown();
            Thread.sleep(5);
        }, null);
        assertTrue(first.await(10, TimeUnit.SECONDS), "the warm-up never ran");
        warmUp.stop();
        Thread.sleep(50);
        int afterStop = rounds.get();
        Thread.sleep(100);
        assertEquals(afterStop, rounds.get(), "rounds kept running after stop()");
        assertTrue(seen[1] - seen[0] > 100, "the synthetic grid has relief: " + seen[0] + " … " + seen[1]);
    }

    @Test
    void aFailingStageIsIgnoredAndEndsTheWarmUp() throws Exception {
        AtomicInteger rounds = new AtomicInteger();
        KernelWarmUp.start((Dem dem) -> {
            rounds.incrementAndGet();
            throw new IllegalStateException("deliberate");
        }, null);
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (rounds.get() == 0 && System.nanoTime() < deadline) {
            Thread.sleep(5);
        }
        Thread.sleep(100);
        assertEquals(1, rounds.get(), "the warm-up must stop at its first failure");
    }

    /** The synthetic grid is of the input's kind: the sweep takes another loop on lat/lon grids. */
    @Test
    void theGridIsOfTheInputsKind() {
        GridGeometry latLon = KernelWarmUp.geometryLike(Path.of("testdata/dem/jacksboro_srtm3s_wgs84.tif"));
        assertTrue(latLon.crs().isGeographic(), "a lat/lon input gets a lat/lon grid");
        assertEquals(1.0 / 3600, latLon.cellWidth(), 1e-15);
        assertTrue(Math.abs(latLon.originY() - (36.7329167 - 172.0 / 1200)) < 1e-6,
                "at the input's latitude (the middle row of Jacksboro's 344 rows of 3″): " + latLon.originY());
        GridGeometry utm = KernelWarmUp.geometryLike(Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif"));
        assertTrue(utm.crs() == null || !utm.crs().isGeographic(), "a projected input gets a metric grid");
        assertEquals(30, utm.cellWidth());
        assertEquals(30, KernelWarmUp.geometryLike(null).cellWidth(), "no file: the bundled sample, projected");
        assertEquals(30, KernelWarmUp.geometryLike(Path.of("no/such/file.tif")).cellWidth(), "unreadable: metric");
    }
}
