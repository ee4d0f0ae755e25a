package io.github.jdem846.cli;

/**
 * A daemon thread for work done ahead of time that the command does again if needed (warm-ups): it never prints
 * and never fails the command, whatever it throws, out of memory included.
 */
final class WarmUpThread {

    private WarmUpThread() {
    }

    /** A started daemon thread of this name running {@code work}; anything it throws is dropped. */
    static Thread start(String name, Runnable work) {
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
        return t;
    }
}
