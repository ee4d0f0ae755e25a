package io.github.jdem846.testing;

import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

/**
 * The outcome of work run on a thread of its own that is interrupted {@code delayMillis} after it started: what it
 * threw (null if it returned), when it was interrupted ({@link System#nanoTime()}), how long after the interrupt it
 * ended, and its interrupt status at the end.
 */
public record InterruptedRun(Throwable thrown, long interruptedAt, double millisAfterInterrupt,
                             boolean interruptStatusAtEnd) {

    /** The longest wait for the work to end after the interrupt: a test fails on its assertions long before. */
    private static final long JOIN_SECONDS = 120;

    public static InterruptedRun of(Callable<?> work, long delayMillis) throws InterruptedException {
        Throwable[] thrown = new Throwable[1];
        long[] end = new long[1];
        boolean[] status = new boolean[1];
        Thread caller = new Thread(() -> {
            try {
                work.call();
            } catch (Throwable t) {
                thrown[0] = t;
            }
            end[0] = System.nanoTime();
            status[0] = Thread.currentThread().isInterrupted();
        }, "interrupted-run");
        caller.start();
        Thread.sleep(delayMillis);
        long interruptedAt = System.nanoTime();
        caller.interrupt();
        caller.join(TimeUnit.SECONDS.toMillis(JOIN_SECONDS));
        if (caller.isAlive()) {
            throw new AssertionError("still running " + JOIN_SECONDS + " s after the interrupt");
        }
        return new InterruptedRun(thrown[0], interruptedAt, (end[0] - interruptedAt) / 1e6, status[0]);
    }

    /** Names of the live threads that start with {@code prefix}. */
    public static Set<String> liveThreads(String prefix) {
        return Thread.getAllStackTraces().keySet().stream().filter(Thread::isAlive).map(Thread::getName)
                .filter(n -> n.startsWith(prefix)).collect(Collectors.toSet());
    }
}
