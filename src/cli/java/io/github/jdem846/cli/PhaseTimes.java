package io.github.jdem846.cli;

import java.io.PrintWriter;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Wall-clock time of a command's phases (start-up, read, compute, encode …), printed on stderr with
 * {@code --verbose}: where a whole command spends its time (docs/performance.md).
 */
final class PhaseTimes {

    private final long startNanos = System.nanoTime();
    private final List<String> phases = new ArrayList<>();
    private long last = startNanos;

    /** Starts timing now; the printout also gives the time from the JVM's start to now (JVM, class loading). */
    PhaseTimes() {
    }

    /** Ends the current phase, naming it. */
    void lap(String phase) {
        long now = System.nanoTime();
        phases.add(phase + " " + (now - last) / 1_000_000 + " ms");
        last = now;
    }

    /** Prints the phases on one line when {@code verbose}. */
    void print(boolean verbose, PrintWriter err) {
        if (verbose) {
            long since = (System.nanoTime() - startNanos) / 1_000_000;
            long startUp = ManagementFactory.getRuntimeMXBean().getUptime() - since;
            err.println(String.format(Locale.ROOT, "jdem846: timing: start-up %d ms, %s; total %d ms", startUp,
                    String.join(", ", phases), startUp + since));
            err.flush();
        }
    }
}
