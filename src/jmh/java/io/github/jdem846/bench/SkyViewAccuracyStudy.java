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
 * with the sweep's run time on the whole grid (best of 5); then, at D = 32, the error against run time of the sweep
 * and of the brute force with coarser steps (1, ½, ¼ cell; best of 3). Prints two Markdown tables
 * (docs/accuracy.md) and, with {@code --plot DIR}, writes DIR/accuracy-skyview.png ({@link SkyViewAccuracyPlot}).
 *
 * <p>Usage: {@code SkyViewAccuracyStudy [--sample N] [--threads T] [--testdata DIR] [--plot DIR] DEM...}; the brute
 * force is evaluated on every valid cell of a DEM with at most N valid cells, else on N distinct cells drawn with
 * {@code SplittableRandom(846)}. Its speed is cells of the sample per second, the sweep's cells of the grid.
 */
public final class SkyViewAccuracyStudy {

    private SkyViewAccuracyStudy() {
    }

    /** Directions of the comparison of error against run time. */
    static final int PLOT_DIRECTIONS = 32;
    /** Steps of the coarser brute-force searches, in cells. */
    static final double[] BRUTE_STEPS = {1, 0.5, 0.25};
    /** Step of the reference, in cells. */
    static final double REFERENCE_STEP = 0.125;

    /** One method on one DEM: speed in cells per second (millions) and the absolute error of the factor. */
    record Point(String dem, String method, double mcellsPerSecond, double meanError, double maxError) {
    }

    public static void main(String[] args) throws IOException {
        int sample = 20000;
        int threads = 2;
        Path testdata = Path.of("testdata");
        Path plot = null;
        List<String> dems = new ArrayList<>();
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--sample" -> sample = Integer.parseInt(args[++i]);
                case "--threads" -> threads = Integer.parseInt(args[++i]);
                case "--testdata" -> testdata = Path.of(args[++i]);
                case "--plot" -> plot = Path.of(args[++i]);
                default -> dems.add(args[i]);
            }
        }
        ForkJoinPool pool = new ForkJoinPool(threads);
        // warm-up on the smallest DEM
        Dem warm = StudyDem.load("maungawhau", testdata).dem();
        for (int k = 0; k < 20; k++) {
            SkyView.compute(warm, SkyViewOptions.DEFAULTS, pool);
        }
        int[] warmCells = cells(warm, 500);
        for (double step : BRUTE_STEPS) {
            bruteForce(new HorizonReference(warm, step, 1), warm, warmCells, PLOT_DIRECTIONS, pool);
        }
        System.out.println("| DEM | D | cells compared | mean abs. error | max abs. error | sweep s (whole grid) "
                + "| Mcells/s |");
        System.out.println("|---|---:|---:|---:|---:|---:|---:|");
        List<Point> points = new ArrayList<>();
        List<String> speedRows = new ArrayList<>();
        for (String name : dems) {
            Dem dem = StudyDem.load(name, testdata).dem();
            int width = dem.width();
            int[] cells = cells(dem, sample);
            HorizonReference ref = new HorizonReference(dem, REFERENCE_STEP, 1);
            double[] reference32 = null;
            for (int d : new int[] {8, 16, 32, 64}) {
                SkyViewOptions o = SkyViewOptions.DEFAULTS.withDirections(d);
                double best = Double.POSITIVE_INFINITY;
                float[] s = null;
                for (int rep = 0; rep < 5; rep++) {
                    long t0 = System.nanoTime();
                    s = SkyView.compute(dem, o, pool);
                    best = Math.min(best, (System.nanoTime() - t0) / 1e9);
                }
                float[] sv = s;
                long t0 = System.nanoTime();
                double[] reference = bruteForce(ref, dem, cells, d, pool);
                double referenceSeconds = (System.nanoTime() - t0) / 1e9;
                double[] sweep = new double[cells.length];
                for (int k = 0; k < cells.length; k++) {
                    sweep[k] = sv[cells[k]];
                }
                double[] e = errors(sweep, reference);
                double mcells = (double) width * dem.height() / best / 1e6;
                System.out.printf(Locale.ROOT, "| %s | %d | %d | %.5f | %.4f | %.3f | %.1f |%n", name, d,
                        cells.length, e[0], e[1], best, mcells);
                points.add(new Point(name, "sweep D=" + d, mcells, e[0], e[1]));
                if (d == PLOT_DIRECTIONS) {
                    reference32 = reference;
                    speedRows.add(String.format(Locale.ROOT, "| %s | brute force, ⅛ cell (the reference) | %.4f "
                            + "| 0 | 0 |", name, cells.length / referenceSeconds / 1e6));
                    speedRows.add(String.format(Locale.ROOT, "| %s | sweep | %.1f | %.5f | %.4f |", name, mcells,
                            e[0], e[1]));
                }
            }
            for (double step : BRUTE_STEPS) {
                HorizonReference coarse = new HorizonReference(dem, step, 1);
                double best = Double.POSITIVE_INFINITY;
                double[] found = null;
                for (int rep = 0; rep < 3; rep++) {
                    long t0 = System.nanoTime();
                    found = bruteForce(coarse, dem, cells, PLOT_DIRECTIONS, pool);
                    best = Math.min(best, (System.nanoTime() - t0) / 1e9);
                }
                double[] e = errors(found, reference32);
                double mcells = cells.length / best / 1e6;
                String method = "brute force, step " + stepName(step);
                points.add(new Point(name, method, mcells, e[0], e[1]));
                speedRows.add(String.format(Locale.ROOT, "| %s | %s | %.4f | %.5f | %.4f |", name, method, mcells,
                        e[0], e[1]));
            }
        }
        pool.shutdown();
        System.out.println();
        System.out.println("| DEM (D = " + PLOT_DIRECTIONS + ") | method | Mcells/s | mean abs. error "
                + "| max abs. error |");
        System.out.println("|---|---|---:|---:|---:|");
        speedRows.forEach(System.out::println);
        if (plot != null) {
            System.out.println("\n" + SkyViewAccuracyPlot.write(points, dems, plot));
        }
    }

    /** The brute-force factor of {@code cells} with {@code directions} azimuths, the cells split over the pool. */
    private static double[] bruteForce(HorizonReference ref, Dem dem, int[] cells, int directions,
                                       ForkJoinPool pool) {
        int width = dem.width();
        double[] out = new double[cells.length];
        pool.submit(() -> java.util.stream.IntStream.range(0, cells.length).parallel().forEach(k ->
                out[k] = ref.skyView(cells[k] % width, cells[k] / width, directions))).join();
        return out;
    }

    /** {mean, max} of |a − b|. */
    private static double[] errors(double[] a, double[] b) {
        double sum = 0;
        double max = 0;
        for (int k = 0; k < a.length; k++) {
            double e = Math.abs(a[k] - b[k]);
            sum += e;
            max = Math.max(max, e);
        }
        return new double[] {sum / a.length, max};
    }

    /** 1, ½, ¼ … cell. */
    static String stepName(double step) {
        return step == 1 ? "1 cell" : step == 0.5 ? "½ cell" : step == 0.25 ? "¼ cell" : step + " cell";
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
