package io.github.jdem846.bench;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.ShadowOptions;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.concurrent.ForkJoinPool;

/**
 * The sweep with and without {@link ShadowOptions#withThinFeatures thin features} against {@code exact}: per DEM
 * and sun elevation, the share of valid cells where each disagrees with exact, split into shadow missed and shadow
 * added, and the time of each sweep (best of 3, 2 threads). DEMs: crops of the real ones in testdata and
 * "poles", flat 1 m ground with 1 % of its cells raised 3–20 m (a lidar surface with poles and trees).
 *
 * <pre>java -cp target/benchmarks.jar io.github.jdem846.bench.ThinFeatureStudy</pre>
 */
public final class ThinFeatureStudy {

    private static final double[] AZIMUTHS = {30, 100, 160, 215, 250, 300};
    private static final double[] ELEVATIONS = {5, 20};

    private ThinFeatureStudy() {
    }

    public static void main(String[] args) throws IOException {
        ForkJoinPool pool = new ForkJoinPool(2);
        Path testdata = Path.of("testdata");
        Dem bt = StudyDem.load("bigtujunga", testdata).dem().crop(420, 120, 400, 300);
        Dem jb = StudyDem.load("jacksboro", testdata).dem();
        Dem coarse = StudyDem.load("bigtujunga-210m", testdata).dem();
        System.out.println("| DEM | sun elevation | plain: differ (missed / added) | thin: differ (missed / added) "
                + "| plain ms | thin ms |");
        System.out.println("|---|---:|---:|---:|---:|---:|");
        row("Big Tujunga 30 m, 400×300 crop", bt, pool);
        row("Jacksboro 3″, 403×344", jb, pool);
        row("Big Tujunga ≈ 210 m, 171×92", coarse, pool);
        Dem poles = poles(400, 846);
        row("poles: flat 1 m, 1 % of cells +3…20 m, 400×400", poles, pool);
        marchRow("poles, march ½ cell bilinear", poles, pool);
        pool.shutdown();
    }

    private static void row(String name, Dem dem, ForkJoinPool pool) {
        ShadowOptions plain = ShadowOptions.DEFAULTS;
        ShadowOptions thin = ShadowOptions.DEFAULTS.withThinFeatures(true);
        for (double e : ELEVATIONS) {
            long cells = 0;
            long[] p = new long[2];
            long[] t = new long[2];
            double plainMs = 0;
            double thinMs = 0;
            for (double a : AZIMUTHS) {
                LightDirection light = new LightDirection(a, e);
                float[] ref = ShadowAlgorithm.EXACT.compute(dem, light, plain, pool).backingArray();
                float[] sp = ShadowAlgorithm.SWEEP.compute(dem, light, plain, pool).backingArray();
                float[] st = ShadowAlgorithm.SWEEP.compute(dem, light, thin, pool).backingArray();
                float[] v = dem.backingArray();
                for (int i = 0; i < ref.length; i++) {
                    if (v[i] != v[i]) {
                        continue;
                    }
                    cells++;
                    count(ref[i], sp[i], p);
                    count(ref[i], st[i], t);
                }
                plainMs += best(dem, light, plain, pool);
                thinMs += best(dem, light, thin, pool);
            }
            System.out.printf(Locale.ROOT,
                    "| %s | %.0f° | %.3f %% (%.3f / %.3f) | %.3f %% (%.3f / %.3f) | %.1f | %.1f |%n", name, e, pct(p[0] + p[1], cells), pct(p[0], cells), pct(p[1], cells), pct(t[0] + t[1], cells),
                    pct(t[0], cells), pct(t[1], cells), plainMs / AZIMUTHS.length, thinMs / AZIMUTHS.length);
        }
    }

    /** The bilinear half-cell march on the same suns: disagreement with exact and time (one run). */
    private static void marchRow(String name, Dem dem, ForkJoinPool pool) {
        ShadowOptions march = ShadowOptions.DEFAULTS.withStep(io.github.jdem846.shadow.StepSize.HALF_CELL)
                .withSampling(io.github.jdem846.shadow.Sampling.BILINEAR);
        for (double e : ELEVATIONS) {
            long cells = 0;
            long[] d = new long[2];
            double ms = 0;
            for (double a : AZIMUTHS) {
                LightDirection light = new LightDirection(a, e);
                float[] ref = ShadowAlgorithm.EXACT.compute(dem, light, ShadowOptions.DEFAULTS, pool).backingArray();
                long t0 = System.nanoTime();
                float[] m = ShadowAlgorithm.MARCH.compute(dem, light, march, pool).backingArray();
                ms += (System.nanoTime() - t0) / 1e6;
                for (int i = 0; i < ref.length; i++) {
                    cells++;
                    count(ref[i], m[i], d);
                }
            }
            System.out.printf(Locale.ROOT, "| %s | %.0f° | %.3f %% (%.3f / %.3f) | | %.1f | |%n", name, e,
                    pct(d[0] + d[1], cells), pct(d[0], cells), pct(d[1], cells), ms / AZIMUTHS.length);
        }
    }

    private static void count(float ref, float got, long[] missedAdded) {
        boolean r = ref >= 0.5f;
        boolean g = got >= 0.5f;
        if (r && !g) {
            missedAdded[0]++;
        } else if (g && !r) {
            missedAdded[1]++;
        }
    }

    private static double pct(long n, long of) {
        return 100.0 * n / of;
    }

    private static double best(Dem dem, LightDirection light, ShadowOptions o, ForkJoinPool pool) {
        double best = Double.POSITIVE_INFINITY;
        for (int r = 0; r < 3; r++) {
            long t0 = System.nanoTime();
            ShadowAlgorithm.SWEEP.compute(dem, light, o, pool);
            best = Math.min(best, (System.nanoTime() - t0) / 1e6);
        }
        return best;
    }

    /** Flat ground at 100 m in 1 m cells with 1 % of the cells raised by 3–20 m (seeded). */
    static Dem poles(int n, long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        float[] v = new float[n * n];
        java.util.Arrays.fill(v, 100f);
        for (int k = 0; k < n * n / 100; k++) {
            v[rnd.nextInt(v.length)] = (float) (100 + 3 + 17 * rnd.nextDouble());
        }
        return new Dem(v, GridGeometry.metric(n, n, 1));
    }
}
