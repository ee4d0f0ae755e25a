package io.github.jdem846.bench;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.Dem;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Wall time of {@link DemReader#read(Path)} of whole files in one JVM: the first read of the JVM (cold: class
 * loading, interpreter and JIT warm-up included, as in one CLI run) and the best of the following ones (warm).
 * Each file's values are summed so that the reads cannot be optimised away and two versions can be compared.
 *
 * <pre>java -cp target/benchmarks.jar io.github.jdem846.bench.ReadTiming RUNS FILE...</pre>
 */
public final class ReadTiming {

    private ReadTiming() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 2) {
            System.err.println("usage: ReadTiming RUNS FILE...");
            System.exit(2);
        }
        int runs = Integer.parseInt(args[0]);
        for (int f = 1; f < args.length; f++) {
            Path file = Path.of(args[f]);
            double first = 0;
            double best = Double.POSITIVE_INFINITY;
            double checksum = 0;
            for (int r = 0; r < runs; r++) {
                long t0 = System.nanoTime();
                Dem dem = DemReader.read(file);
                double ms = (System.nanoTime() - t0) / 1e6;
                checksum = checksum(dem.backingArray());
                if (r == 0) {
                    first = ms;
                } else {
                    best = Math.min(best, ms);
                }
            }
            System.out.printf(Locale.ROOT, "%s: first %.0f ms, best of %d more %.0f ms, checksum %.6e%n",
                    file.getFileName(), first, runs - 1, best, checksum);
        }
    }

    /** The sum of the valid cells, each weighted by its index mod 7 (a change in any cell shows). */
    private static double checksum(float[] values) {
        double sum = 0;
        for (int i = 0; i < values.length; i++) {
            float v = values[i];
            if (v == v) {
                sum += v * (1 + i % 7);
            }
        }
        return sum;
    }
}
