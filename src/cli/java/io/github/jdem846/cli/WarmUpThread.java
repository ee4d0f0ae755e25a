package io.github.jdem846.cli;

/**
 * A daemon thread for work done ahead of time that the command does again if needed (warm-ups): it never prints
 * and never fails the command, whatever it throws, out of memory included. The JVM option
 * {@code -Djdem846.warmUp=off} (e.g. in {@code JDEM846_OPTS}) starts none, to measure what they earn
 * (docs/performance.md, "Start-up and class-data sharing").
 */
final class WarmUpThread {

    private WarmUpThread() {
    }

    /** The system property that turns the warm-ups off when {@code off}. */
    static final String PROPERTY = "jdem846.warmUp";

    /** True unless the system property {@value #PROPERTY} is {@code off}. */
    static boolean enabled() {
        return !"off".equals(System.getProperty(PROPERTY));
    }

    /**
     * Starts a daemon thread of this name running {@code work}, anything it throws dropped; none when the warm-ups
     * are off ({@link #enabled()}).
     */
    static void start(String name, Runnable work) {
        if (!enabled()) {
            return;
        }
        Thread t = new Thread(() -> {
            try {
                work.run();
            } catch (RuntimeException | LinkageError | OutOfMemoryError e) {
                // dropped: the command does the work itself and reports its own errors
            }
        }, name);
        t.setDaemon(true);
        t.setUncaughtExceptionHandler((thread, e) -> { });
        t.start();
    }
}
