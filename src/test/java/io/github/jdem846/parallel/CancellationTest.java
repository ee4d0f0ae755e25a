package io.github.jdem846.parallel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.testing.InterruptedRun;
import io.github.jdem846.testing.PoolExtension;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicIntegerArray;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

class CancellationTest {

    @RegisterExtension
    static final PoolExtension POOLS = new PoolExtension(1, 2, 3);

    @Test
    void everyPartRunsOnceOnAnyPool() {
        for (ForkJoinPool pool : new ForkJoinPool[] {POOLS.get(1), POOLS.get(3), ForkJoinPool.commonPool()}) {
            for (int parts : new int[] {0, 1, 2, 7, 1000}) {
                AtomicIntegerArray runs = new AtomicIntegerArray(parts);
                Cancellation.invokeAll(pool, parts, (i, c) -> runs.incrementAndGet(i));
                for (int i = 0; i < parts; i++) {
                    assertEquals(1, runs.get(i), "part " + i + " of " + parts);
                }
            }
        }
    }

    @Test
    void aWorkerOfThePoolMayCallItWithoutDeadlock() {
        ForkJoinPool one = POOLS.get(1);
        AtomicInteger runs = new AtomicInteger();
        one.submit(() -> Cancellation.invokeAll(one, 50, (i, c) -> runs.incrementAndGet())).join();
        assertEquals(50, runs.get());
    }

    @Test
    void aFailingPartStopsTheOthersAndItsExceptionReachesTheCaller() {
        IllegalStateException boom = new IllegalStateException("boom");
        AtomicInteger started = new AtomicInteger();
        // Parts after the failing one wait until the work is cancelled (at most 10 s), so the outcome does not
        // depend on how the threads are scheduled: a worker busy with part 4 or later sees the failure of part 3,
        // and no worker may start another part after it. Without cancellation every part would run (after 10 s).
        long deadline = System.nanoTime() + 10_000_000_000L;
        IllegalStateException thrown = assertThrows(IllegalStateException.class,
                () -> Cancellation.invokeAll(POOLS.get(2), 10_000, (i, c) -> {
                    started.incrementAndGet();
                    if (i == 3) {
                        throw boom;
                    }
                    while (i > 3 && !c.isCancelled() && System.nanoTime() < deadline) {
                        Thread.onSpinWait();
                    }
                }));
        assertSame(boom, thrown);
        // parts 0–3, plus at most the one part each of the two workers had taken when part 3 failed
        assertTrue(started.get() <= 6, started.get() + " parts started");
    }

    @Test
    void anInterruptedCallerStartsNothing() {
        AtomicInteger runs = new AtomicInteger();
        Thread.currentThread().interrupt();
        try {
            assertThrows(CancellationException.class,
                    () -> Cancellation.invokeAll(ForkJoinPool.commonPool(), 10, (i, c) -> runs.incrementAndGet()));
            assertTrue(Thread.currentThread().isInterrupted(), "the interrupt status stays set");
        } finally {
            Thread.interrupted();
        }
        assertEquals(0, runs.get());
    }

    @Test
    void anInterruptEndsTheCallOnlyOnceNoPartRuns() throws InterruptedException {
        for (ForkJoinPool pool : new ForkJoinPool[] {POOLS.get(2), ForkJoinPool.commonPool()}) {
            AtomicInteger running = new AtomicInteger();
            AtomicInteger runningAtEnd = new AtomicInteger(-1);
            InterruptedRun run = InterruptedRun.of(() -> {
                try {
                    Cancellation.invokeAll(pool, 100, (i, c) -> {
                        running.incrementAndGet();
                        long until = System.nanoTime() + 20_000_000L;  // 20 ms after cancelling
                        while (!c.isCancelled() || System.nanoTime() < until) {
                            if (!c.isCancelled()) {
                                until = System.nanoTime() + 20_000_000L;
                            }
                            Thread.onSpinWait();
                        }
                        running.decrementAndGet();
                    });
                } finally {
                    runningAtEnd.set(running.get());
                }
                return null;
            }, 100);
            assertInstanceOf(CancellationException.class, run.thrown());
            assertTrue(run.interruptStatusAtEnd());
            assertEquals(0, runningAtEnd.get(), "parts still running when the call ended");
        }
    }

    @Test
    void isCancelledFollowsTheCallersInterruptStatus() {
        ForkJoinPool pool = POOLS.get(2);
        boolean[] seen = new boolean[2];
        Cancellation.invokeAll(pool, 1, (i, c) -> seen[0] = c.isCancelled());
        assertFalse(seen[0]);
        Thread caller = Thread.currentThread();
        assertThrows(CancellationException.class, () -> Cancellation.invokeAll(pool, 1, (i, c) -> {
            caller.interrupt();
            seen[1] = c.isCancelled();
        }));
        assertTrue(Thread.interrupted(), "the interrupt status stays set");
        assertTrue(seen[1]);
    }

    @Test
    void anInterruptDoesNotWaitForPartsQueuedBehindOtherWorkOfTheSharedPool() throws InterruptedException {
        ForkJoinPool one = new ForkJoinPool(1);
        java.util.concurrent.CountDownLatch release = new java.util.concurrent.CountDownLatch(1);
        try {
            one.execute(() -> {                 // another caller's work holding the pool's only thread
                try {
                    release.await();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            });
            AtomicInteger runs = new AtomicInteger();
            InterruptedRun run = InterruptedRun.of(() -> {
                Cancellation.invokeAll(one, 4, (i, c) -> runs.incrementAndGet());
                return null;
            }, 100);
            assertInstanceOf(CancellationException.class, run.thrown(), "ended by " + run.thrown());
            assertTrue(run.millisAfterInterrupt() < 500, run.millisAfterInterrupt() + " ms after the interrupt");
            release.countDown();
            assertTrue(one.awaitQuiescence(10, java.util.concurrent.TimeUnit.SECONDS));
            assertEquals(0, runs.get(), "a queued part does not start after the call has returned");
        } finally {
            release.countDown();
            one.shutdownNow();
        }
    }
}
