package io.github.jdem846.parallel;

import java.util.concurrent.CancellationException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinWorkerThread;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.IntConsumer;

/**
 * The parts of one computation run on a {@link ForkJoinPool} for the calling thread, stopped when that thread is
 * interrupted: the one cancellation mechanism of the shadow algorithms and the renderer's tiles.
 *
 * <p>{@link #invokeAll} runs parts {@code 0 … n − 1} and waits for them. A part does not start once the work is
 * cancelled; a long part also tests {@link #isCancelled()} itself every few lines (not per cell, although it is only
 * two volatile reads) and returns early. When the calling thread is interrupted (before or during the call),
 * {@code invokeAll} waits until no part runs any more (helpers still queued behind other work of a shared pool are
 * withdrawn, not awaited), so nothing of the call is left on the pool, and throws
 * {@link CancellationException} with the thread's interrupt status set. A part's exception stops the other parts
 * the same way and is rethrown to the caller.
 *
 * <p>Threads: up to the pool's parallelism of its workers take parts in index order. The calling thread takes parts
 * too when the pool is the common pool (whose parallelism leaves one processor to the caller) or when it is one of
 * the pool's own workers; otherwise it only waits. The calling thread never waits inside the pool's join, which
 * would clear its interrupt status while it waits.
 */
public final class Cancellation {

    /** One part of the work. */
    @FunctionalInterface
    public interface Part {
        /** Runs part {@code index}; returns early, leaving its output incomplete, when {@code c} is cancelled. */
        void run(int index, Cancellation c);
    }

    private final Thread caller;
    private final int parts;
    private final Part part;
    private final AtomicInteger next = new AtomicInteger();
    private final AtomicReference<Throwable> failure = new AtomicReference<>();
    private final IntConsumer partsDone;
    private int reported;
    private volatile boolean cancelled;

    private Cancellation(Thread caller, int parts, Part part, IntConsumer partsDone) {
        this.caller = caller;
        this.parts = parts;
        this.part = part;
        this.partsDone = partsDone;
    }

    /** True once the work should stop: the calling thread was interrupted, or a part failed. */
    public boolean isCancelled() {
        return cancelled || caller.isInterrupted();
    }

    /**
     * Runs {@code part} for every index in [0, {@code parts}) on {@code pool} and waits until all have returned.
     *
     * @throws CancellationException when the calling thread is interrupted; its interrupt status stays set
     */
    public static void invokeAll(ForkJoinPool pool, int parts, Part part) {
        invokeAll(pool, parts, part, null);
    }

    /**
     * {@link #invokeAll(ForkJoinPool, int, Part)}, telling {@code partsDone} how many parts have returned (without
     * being cancelled) after each one: from the worker threads, one at a time, the counts only growing.
     *
     * @param partsDone told the number of parts done so far, or {@code null}
     * @throws CancellationException when the calling thread is interrupted; its interrupt status stays set
     */
    public static void invokeAll(ForkJoinPool pool, int parts, Part part, IntConsumer partsDone) {
        checkInterrupted();
        Thread caller = Thread.currentThread();
        Cancellation c = new Cancellation(caller, parts, part, partsDone);
        boolean callerWorks = pool == ForkJoinPool.commonPool()
                || caller instanceof ForkJoinWorkerThread w && w.getPool() == pool;
        int helpers = Math.max(0, Math.min(parts - (callerWorks ? 1 : 0), pool.getParallelism()));
        CountDownLatch ended = new CountDownLatch(helpers);
        AtomicBoolean[] started = new AtomicBoolean[helpers];
        RuntimeException refused = null;
        for (int h = 0; h < helpers; h++) {
            AtomicBoolean mine = started[h] = new AtomicBoolean();
            try {
                pool.execute(() -> {
                    if (mine.compareAndSet(false, true)) {
                        try {
                            c.work();
                        } finally {
                            ended.countDown();
                        }
                    }
                });
            } catch (RuntimeException e) {      // the pool is shut down
                refused = e;
                c.cancelled = true;
                break;
            }
        }
        if (callerWorks && refused == null) {
            c.work();
        }
        if (callerWorks || refused != null) {   // no part is left to start
            for (int h = 0; h < helpers; h++) {
                if (started[h] == null || started[h].compareAndSet(false, true)) {
                    ended.countDown();          // a helper that has not started will not start now
                }
            }
        }
        try {
            ended.await();
        } catch (InterruptedException e) {
            c.cancelled = true;
            for (int h = 0; h < helpers; h++) {
                if (started[h] != null && started[h].compareAndSet(false, true)) {
                    ended.countDown();          // still queued (behind other work on a shared pool): never starts
                }
            }
            awaitUninterruptibly(ended);        // every part now returns at its next test
            caller.interrupt();
        }
        if (refused != null) {
            throw refused;
        }
        Throwable failed = c.failure.get();
        if (failed instanceof RuntimeException re) {
            throw re;
        }
        if (failed instanceof Error er) {
            throw er;
        }
        if (failed != null) {
            throw new IllegalStateException(failed);
        }
        checkInterrupted();
    }

    /**
     * For the calling thread's own work between parts: throws {@link CancellationException} (the interrupt status
     * kept) when the thread is interrupted.
     */
    public static void checkInterrupted() {
        if (Thread.currentThread().isInterrupted()) {
            throw cancelled();
        }
    }

    /** Takes parts in index order until none is left or the work is cancelled. */
    private void work() {
        for (int i = next.getAndIncrement(); i < parts && !isCancelled(); i = next.getAndIncrement()) {
            try {
                part.run(i, this);
                if (partsDone != null && !isCancelled()) {
                    reportDone();
                }
            } catch (Throwable t) {
                failure.compareAndSet(null, t);
                cancelled = true;
            }
        }
    }

    /** Tells the listener one more part is done, the counts in order. */
    private synchronized void reportDone() {
        partsDone.accept(++reported);
    }

    private static void awaitUninterruptibly(CountDownLatch latch) {
        while (true) {
            try {
                latch.await();
                return;
            } catch (InterruptedException again) {
                // the work is already cancelled; the status is set again afterwards
            }
        }
    }

    private static CancellationException cancelled() {
        return new CancellationException("cancelled: the calling thread was interrupted");
    }
}
