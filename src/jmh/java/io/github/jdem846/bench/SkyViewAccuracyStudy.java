package io.github.jdem846.bench;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.shadow.SkyView;
import io.github.jdem846.shadow.SkyViewOptions;
import io.github.jdem846.testing.HorizonReference;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.concurrent.ForkJoinPool;

/**
 * The sky-view factor of the sweep ({@link SkyView}) against the brute-force horizon search ({@link
 * HorizonReference}: rays in ⅛-cell steps on the bilinear surface) for D = 8, 16, 32, 64 on the DEMs of testdata,
 * with the sweep's run time on the whole grid. Prints one Markdown table row per DEM and D (docs/accuracy.md).
 *
 * <p>Usage: {@code SkyViewAccuracyStudy [--sample N] [--threads T] [--testdata DIR] DEM...}; the brute force is
 * evaluated on every valid cell of a DEM with at most N valid cells, else on N distinct cells drawn with
 * {@code SplittableRandom(846)}.
 */
public final class SkyViewAccuracyStudy {

    private SkyViewAccuracyStudy() {
    }

    public static void main(String[] args) throws IOException {
        int sample = 20000;
        int threads = 2;
        Path testdata = Path.of("testdata");
        List<String> dems = new ArrayList<>();
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--sample" -> sample = Integer.parseInt(args[++i]);
                case "--threads" -> threads = Integer.parseInt(args[++i]);
                case "--testdata" -> testdata = Path.of(args[++i]);
                default -> dems.add(args[i]);
            }
        }
        ForkJoinPool pool = new ForkJoinPool(threads);
        // warm-up on the smallest DEM
        Dem warm = StudyDem.load("maungawhau", testdata).dem();
        for (int k = 0; k < 20; k++) {
            SkyView.compute(warm, SkyViewOptions.DEFAULTS, pool);
        }
        System.out.println("| DEM | D | cells compared | mean abs. error | max abs. error | sweep s (whole grid) "
                + "| Mcells/s |");
        System.out.println("|---|---:|---:|---:|---:|---:|---:|");
        for (String name : dems) {
            Dem dem = StudyDem.load(name, testdata).dem();
            int[] cells = cells(dem, sample);
            HorizonReference ref = new HorizonReference(dem, 0.125, 1);
            for (int d : new int[] {8, 16, 32, 64}) {
                SkyViewOptions o = SkyViewOptions.DEFAULTS.withDirections(d);
                double best = Double.POSITIVE_INFINITY;
                float[] s = null;
                for (int rep = 0; rep < 3; rep++) {
                    long t0 = System.nanoTime();
                    s = SkyView.compute(dem, o, pool);
                    best = Math.min(best, (System.nanoTime() - t0) / 1e9);
                }
                float[] sv = s;
                double[] err = new double[cells.length];
                pool.submit(() -> java.util.stream.IntStream.range(0, cells.length).parallel().forEach(k -> {
                    int c = cells[k];
                    err[k] = Math.abs(sv[c] - ref.skyView(c % dem.width(), c / dem.width(), d));
                })).join();
                double sum = 0;
                double max = 0;
                for (double e : err) {
                    sum += e;
                    max = Math.max(max, e);
                }
                System.out.printf(Locale.ROOT, "| %s | %d | %d | %.5f | %.4f | %.3f | %.1f |%n", name, d,
                        cells.length, sum / cells.length, max, best, (double) dem.width() * dem.height() / best / 1e6);
            }
        }
        pool.shutdown();
    }

    /** Every valid cell when there are at most {@code sample}, else {@code sample} distinct ones at random. */
    private static int[] cells(Dem dem, int sample) {
        float[] v = dem.backingArray();
        List<Integer> valid = new ArrayList<>();
        for (int i = 0; i < v.length; i++) {
            if (v[i] == v[i]) {
                valid.add(i);
            }
        }
        if (valid.size() > sample) {
            SplittableRandom rnd = new SplittableRandom(846);
            for (int i = 0; i < sample; i++) {
                int j = i + rnd.nextInt(valid.size() - i);
                Integer t = valid.get(i);
                valid.set(i, valid.get(j));
                valid.set(j, t);
            }
            valid = valid.subList(0, sample);
        }
        return valid.stream().mapToInt(Integer::intValue).toArray();
    }
}
