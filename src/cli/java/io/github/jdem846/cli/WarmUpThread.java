package io.github.jdem846.cli;

/**
 * A daemon thread for work done ahead of time that the command does again if needed (warm-ups): it never prints
 * and never fails the command, whatever it throws, out of memory included. Off unless the JVM option
 * {@code -Djdem846.warmUp=on} (e.g. in {@code JDEM846_OPTS}) is given: with the launcher's class cache, the direct
 * reads and the row kernels they no longer earn their keep on 2 cores (they cost 5–19 % of a hillshade command's
 * time, docs/performance.md, "Start-up and class-data sharing").
 */
final class WarmUpThread {

    private WarmUpThread() {
    }

    /** The system property that turns the warm-ups on when {@code on}. */
    static final String PROPERTY = "jdem846.warmUp";

    /** True when the system property {@value #PROPERTY} is {@code on}. */
    static boolean enabled() {
        return "on".equals(System.getProperty(PROPERTY));
    }

    /**
     * Starts a daemon thread of this name running {@code work}, anything it throws dropped; none unless the
     * warm-ups are on ({@link #enabled()}).
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
