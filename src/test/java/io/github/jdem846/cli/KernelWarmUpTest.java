package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.raster.Dem;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

class KernelWarmUpTest {

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
        });
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
        });
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (rounds.get() == 0 && System.nanoTime() < deadline) {
            Thread.sleep(5);
        }
        Thread.sleep(100);
        assertEquals(1, rounds.get(), "the warm-up must stop at its first failure");
    }
}
