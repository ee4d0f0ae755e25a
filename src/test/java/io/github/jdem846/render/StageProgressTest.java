package io.github.jdem846.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

class StageProgressTest {

    /** Records updates; fails on two calls at once. */
    private static final class Recorder implements RenderProgress {
        final List<long[]> updates = new ArrayList<>();
        private boolean inside;

        @Override
        public void update(String stage, long done, long total) {
            if (inside) {
                throw new AssertionError("called by two threads at once");
            }
            inside = true;
            updates.add(new long[] {done, total});
            Thread.onSpinWait();
            inside = false;
        }
    }

    @Test
    void unitsCountedOnManyThreadsReachTheListenerGrowingThinnedAndEndingAtTheTotal() throws Exception {
        Recorder recorder = new Recorder();
        long total = 100_000;
        StageProgress progress = new StageProgress(recorder, "read", total).start();
        ExecutorService pool = Executors.newFixedThreadPool(4);
        try {
            List<Future<?>> parts = new ArrayList<>();
            for (int t = 0; t < 4; t++) {
                parts.add(pool.submit(() -> {
                    for (int i = 0; i < total / 4; i++) {
                        progress.add(1);
                    }
                }));
            }
            for (Future<?> f : parts) {
                f.get();
            }
        } finally {
            pool.shutdown();
            assertTrue(pool.awaitTermination(10, TimeUnit.SECONDS));
        }
        progress.finish();
        long last = -1;
        for (long[] u : recorder.updates) {
            assertEquals(total, u[1]);
            assertTrue(u[0] > last, "grows");
            last = u[0];
        }
        assertEquals(0, recorder.updates.get(0)[0], "starts at 0");
        assertEquals(total, last, "ends at the total");
        // one update per step of total / STEPS, the start and possibly the end again
        assertTrue(recorder.updates.size() >= StageProgress.STEPS / 2
                && recorder.updates.size() <= StageProgress.STEPS + 2, "updates: " + recorder.updates.size());
    }

    @Test
    void reachedTakesCountsInAnyOrderAndNeverPassesTheTotal() {
        Recorder recorder = new Recorder();
        StageProgress progress = new StageProgress(recorder, "shadows", 10);
        progress.reached(3);
        progress.reached(2);                       // a worker late with an older count
        progress.reached(7);
        progress.reached(12);                      // more than the total: reported as the total
        progress.finish();
        assertEquals(List.of(3L, 7L, 10L), recorder.updates.stream().map(u -> u[0]).toList());
    }

    @Test
    void anEmptyStageEndsAtZeroOfZero() {
        Recorder recorder = new Recorder();
        new StageProgress(recorder, "write", 0).start().finish();
        assertEquals(1, recorder.updates.size());
        assertEquals(0, recorder.updates.get(0)[0]);
        assertEquals(0, recorder.updates.get(0)[1]);
        assertThrows(IllegalArgumentException.class, () -> new StageProgress(recorder, "write", -1));
    }
}
