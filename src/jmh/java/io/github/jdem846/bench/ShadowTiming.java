package io.github.jdem846.bench;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.ShadowMask;
import io.github.jdem846.shadow.ShadowOptions;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.ForkJoinPool;

/**
 * Wall time of one shadow computation in a fresh JVM, the first (cold: interpreter and JIT warm-up included, as in
 * one CLI run) and the best of the following ones, on the seeded fractal DEM or, when DEM_FILE is given, on the
 * north-west {@code SIZE × SIZE} cells of that file (e.g. a {@link MirroredDem}). Complements
 * {@link RayTraceBenchmark} (one thread, warm) with the multi-threaded numbers a CLI run sees.
 *
 * <pre>java -cp target/benchmarks.jar io.github.jdem846.bench.ShadowTiming SIZE ALGORITHM AZIMUTH ELEVATION THREADS RUNS [DEM_FILE]</pre>
 */
public final class ShadowTiming {

    private ShadowTiming() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length != 6 && args.length != 7) {
            System.err.println("usage: ShadowTiming SIZE ALGORITHM AZIMUTH ELEVATION THREADS RUNS [DEM_FILE]");
            System.exit(2);
        }
        int size = Integer.parseInt(args[0]);
        ShadowAlgorithm algorithm = ShadowAlgorithm.valueOf(args[1].trim().toUpperCase(Locale.ROOT));
        LightDirection light = new LightDirection(Double.parseDouble(args[2]), Double.parseDouble(args[3]));
        int threads = Integer.parseInt(args[4]);
        int runs = Integer.parseInt(args[5]);
        Dem dem = args.length == 7 ? northWest(DemReader.read(Path.of(args[6])), size) : FractalDem.dem(size, 846L);
        dem.statistics();
        ForkJoinPool pool = new ForkJoinPool(threads);
        double first = 0;
        double best = Double.POSITIVE_INFINITY;
        long shadowed = 0;
        for (int r = 0; r < runs; r++) {
            long t0 = System.nanoTime();
            ShadowMask mask = algorithm.compute(dem, light, ShadowOptions.DEFAULTS, pool);
            double ms = (System.nanoTime() - t0) / 1e6;
            shadowed = mask.shadowedCount();
            if (r == 0) {
                first = ms;
            } else {
                best = Math.min(best, ms);
            }
        }
        pool.shutdown();
        double cells = (double) size * size;
        System.out.printf(Locale.ROOT, "%s %s %d² sun %s/%s threads %d: first %.1f ms (%.1f Mcells/s), best of %d more"
                        + " %.1f ms (%.1f Mcells/s), shadowed %.3f %%%n", algorithm.name().toLowerCase(Locale.ROOT),
                args.length == 7 ? args[6] : "fractal", size, args[2], args[3],
                threads, first, cells / first / 1e3, runs - 1, best, cells / best / 1e3, 100.0 * shadowed / cells);
    }

    /** The north-west {@code size × size} cells of {@code dem} ({@code dem} itself when that is all of it). */
    private static Dem northWest(Dem dem, int size) {
        return dem.width() == size && dem.height() == size ? dem : dem.crop(0, 0, size, size);
    }
}
