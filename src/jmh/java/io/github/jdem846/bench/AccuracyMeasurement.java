package io.github.jdem846.bench;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.BitSet;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.ForkJoinPool;
import java.util.function.Supplier;

/**
 * Measures every {@link StudyMethod} against {@code exact} on one DEM: which cells disagree and how fast each
 * method runs. The evaluated cells are every valid cell, or, when {@code sampleSize} is smaller than that, a
 * seeded uniform random sample of distinct valid cells (the same for every sun), sorted by index.
 */
final class AccuracyMeasurement {

    /** Timed runs repeat until their total passes this many seconds or {@link #MAX_RUNS} runs. */
    private static final double MIN_TOTAL_SECONDS = 0.3;
    private static final int MAX_RUNS = 5;

    private final StudyDem study;
    private final ForkJoinPool pool;
    private final int[] cells;
    private final boolean exhaustive;

    AccuracyMeasurement(StudyDem study, ForkJoinPool pool, int sampleSize, long seed) {
        this.study = study;
        this.pool = pool;
        int[] valid = validCells(study.dem());
        if (sampleSize <= 0 || sampleSize >= valid.length) {
            this.cells = valid;
            this.exhaustive = true;
        } else {
            this.cells = sample(valid, sampleSize, seed);
            this.exhaustive = false;
        }
    }

    int evaluatedCells() {
        return cells.length;
    }

    boolean exhaustive() {
        return exhaustive;
    }

    /** Runs every method once, untimed, on a crop of at most 256² cells so that the timed runs are compiled. */
    void warmUp() {
        Dem dem = study.dem();
        int w = Math.min(256, dem.width());
        int h = Math.min(256, dem.height());
        Dem crop = dem.crop((dem.width() - w) / 2, (dem.height() - h) / 2, w, h);
        int[] all = validCells(crop);
        for (int round = 0; round < 2; round++) {
            for (StudyMethod m : StudyMethod.values()) {
                for (double az : new double[] {160, 250}) {
                    LightDirection light = new LightDirection(az, 10);
                    if (m.wholeGrid()) {
                        m.algorithm.compute(crop, light, m.options, pool);
                    } else {
                        m.algorithm.computeCells(crop, light, m.options, pool, all);
                    }
                }
            }
        }
    }

    /** All methods for one sun; the first row is {@code exact} itself. */
    List<AccuracyRow> measure(double elevation, double azimuth) {
        Dem dem = study.dem();
        LightDirection light = new LightDirection(azimuth, elevation);
        long grid = (long) dem.width() * dem.height();
        List<AccuracyRow> rows = new ArrayList<>();
        float[] reference = null;
        for (StudyMethod m : StudyMethod.values()) {
            Timed t;
            if (m.wholeGrid()) {
                t = time(() -> m.algorithm.compute(dem, light, m.options, pool).backingArray());
                t = new Timed(pick(t.result, cells), t.seconds, t.runs);
            } else {
                t = time(() -> m.algorithm.computeCells(dem, light, m.options, pool, cells));
            }
            if (reference == null) {
                reference = t.result;
            }
            long disagree = 0;
            long falseShadow = 0;
            long falseLit = 0;
            long exactShadow = 0;
            for (int q = 0; q < cells.length; q++) {
                boolean ref = reference[q] >= 0.5f;
                boolean got = t.result[q] >= 0.5f;
                exactShadow += ref ? 1 : 0;
                if (ref != got) {
                    disagree++;
                    if (got) {
                        falseShadow++;
                    } else {
                        falseLit++;
                    }
                }
            }
            long timedCells = m.wholeGrid() ? grid : cells.length;
            rows.add(new AccuracyRow(study.name(), grid, cells.length, exhaustive, elevation, azimuth, m, disagree,
                    falseShadow, falseLit, exactShadow, timedCells, t.seconds, t.runs));
        }
        return rows;
    }

    private record Timed(float[] result, double seconds, int runs) {
    }

    /** Fastest of repeated runs (each run's result is the same; the first is kept). */
    private static Timed time(Supplier<float[]> run) {
        float[] result = null;
        double best = Double.POSITIVE_INFINITY;
        double total = 0;
        int runs = 0;
        while (runs < MAX_RUNS && total < MIN_TOTAL_SECONDS) {
            long t0 = System.nanoTime();
            float[] r = run.get();
            double s = (System.nanoTime() - t0) * 1e-9;
            if (result == null) {
                result = r;
            }
            best = Math.min(best, s);
            total += s;
            runs++;
        }
        return new Timed(result, best, runs);
    }

    private static float[] pick(float[] all, int[] cells) {
        float[] out = new float[cells.length];
        for (int q = 0; q < cells.length; q++) {
            out[q] = all[cells[q]];
        }
        return out;
    }

    static int[] validCells(Dem dem) {
        float[] v = dem.backingArray();
        int n = 0;
        for (float z : v) {
            n += z == z ? 1 : 0;
        }
        int[] out = new int[n];
        int k = 0;
        for (int i = 0; i < v.length; i++) {
            if (v[i] == v[i]) {
                out[k++] = i;
            }
        }
        return out;
    }

    /** {@code size} distinct entries of {@code valid}, uniformly at random from {@code seed}, in ascending order. */
    static int[] sample(int[] valid, int size, long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        BitSet chosen = new BitSet(valid.length);
        int n = 0;
        while (n < size) {
            int q = rnd.nextInt(valid.length);
            if (!chosen.get(q)) {
                chosen.set(q);
                n++;
            }
        }
        int[] out = new int[size];
        int k = 0;
        for (int q = chosen.nextSetBit(0); q >= 0; q = chosen.nextSetBit(q + 1)) {
            out[k++] = valid[q];
        }
        Arrays.sort(out);
        return out;
    }
}
