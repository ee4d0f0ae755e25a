package io.github.jdem846.bench;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.ShadowMask;
import io.github.jdem846.shadow.ShadowOptions;
import io.github.jdem846.testing.SyntheticDems;
import java.io.IOException;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Cast shadows of a whole DEM, sun at azimuth 300° (off the grid axes and diagonals), on a pool of one thread: the
 * score is milliseconds per whole grid, so score / cells is the cost of one ray ({@code march}, {@code exact}) or of
 * one cell ({@code sweep}, {@code sweepThinFeatures}, {@code sweepSoft}). {@code exact} runs at 512² only. The DEM
 * ({@code dem} parameter) is the seeded fractal ({@link FractalDem}, seed 846, 30 m cells; the default) or
 * {@code mirrored}: Big Tujunga SRTM 30 m mirror-tiled
 * ({@link MirroredDem}; real mountains, read from testdata, so run from the worktree root), or
 * {@code mirrored-latlon}: the same on a 1″ lat/lon grid ({@link #onLatLonGrid}), where the step length changes from
 * row to row.
 *
 * <pre>./mvnw -B -o -q -Pjmh package -DskipTests
 * java -jar target/benchmarks.jar RayTraceBenchmark -f 1 -wi 2 -i 3
 * java -jar target/benchmarks.jar 'RayTraceBenchmark.(sweep|march)' -p dem=mirrored -p size=2048 -p elevation=5
 * java -jar target/benchmarks.jar 'RayTraceBenchmark.sweepSoft' -p dem=fractal,mirrored-latlon -p size=2048</pre>
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 2, time = 1)
@Measurement(iterations = 3, time = 1)
@Fork(1)
public class RayTraceBenchmark {

    /** Sun azimuth of every run, degrees. */
    public static final double AZIMUTH = 300;

    /** The DEM {@code name} ({@code fractal} or {@code mirrored}) at {@code size}². */
    static Dem dem(String name, int size) throws IOException {
        return switch (name) {
            case "fractal" -> FractalDem.dem(size, 846L);
            case "mirrored" -> MirroredDem.bigTujunga(size);
            case "mirrored-latlon" -> onLatLonGrid(MirroredDem.bigTujunga(size));
            default -> throw new IllegalArgumentException("dem must be fractal, mirrored or mirrored-latlon, not '"
                    + name + "'");
        };
    }

    /**
     * The same elevations on a 1″ WGS 84 grid whose north edge is at 35° N (as SRTM 1″ or Copernicus GLO-30 tiles):
     * a step length per row, the sweep's lat/lon path.
     */
    static Dem onLatLonGrid(Dem dem) {
        return SyntheticDems.geographic(dem.width(), dem.height(), -118.5, 35.0, 1.0 / 3600, dem.backingArray());
    }

    /** A DEM, the sun and a one-thread pool; the grid's size is the subclass's. */
    @State(Scope.Benchmark)
    public abstract static class SunOverDem {
        @Param({"fractal"})
        public String dem;

        @Param({"2", "5", "20", "45"})
        public double elevation;

        Dem grid;
        LightDirection light;
        ForkJoinPool pool;

        abstract int gridSize();

        @Setup(Level.Trial)
        public void setUp() throws IOException {
            grid = dem(dem, gridSize());
            light = new LightDirection(AZIMUTH, elevation);
            pool = new ForkJoinPool(1);
        }

        @TearDown(Level.Trial)
        public void tearDown() {
            pool.shutdownNow();
        }
    }

    /** {@link SunOverDem} at 512² and 2048². */
    @State(Scope.Benchmark)
    public static class Grid extends SunOverDem {
        @Param({"512", "2048"})
        public int size;

        @Override
        int gridSize() {
            return size;
        }
    }

    /** {@link SunOverDem} at 512² only, for the slow reference. */
    @State(Scope.Benchmark)
    public static class SmallGrid extends SunOverDem {
        @Override
        int gridSize() {
            return 512;
        }
    }

    /** The article's march: its step (eq. 9) and nearest-cell sampling. */
    @Benchmark
    public ShadowMask march(Grid g) {
        return ShadowAlgorithm.MARCH.compute(g.grid, g.light, ShadowOptions.DEFAULTS, g.pool);
    }

    /** The O(cells) sweep, bilinear, with the first-cell test (the defaults). */
    @Benchmark
    public ShadowMask sweep(Grid g) {
        return ShadowAlgorithm.SWEEP.compute(g.grid, g.light, ShadowOptions.DEFAULTS, g.pool);
    }

    /** The sweep with its own-ray test for thin features ({@link ShadowOptions#withThinFeatures}). */
    @Benchmark
    public ShadowMask sweepThinFeatures(Grid g) {
        return ShadowAlgorithm.SWEEP.compute(g.grid, g.light, ShadowOptions.DEFAULTS.withThinFeatures(true), g.pool);
    }

    /**
     * Soft shadows by the sweep ({@link ShadowOptions#withSoftShadows}): the 17 elevations across the sun's disk in
     * one walk of the lines ({@code LevelsWalk}, uniform or lat/lon by the grid), then each cell's hidden fraction.
     */
    @Benchmark
    public ShadowMask sweepSoft(Grid g) {
        return ShadowAlgorithm.SWEEP.compute(g.grid, g.light, ShadowOptions.DEFAULTS.withSoftShadows(true), g.pool);
    }

    /** The reference: eighth-cell steps on the bilinear surface. */
    @Benchmark
    public ShadowMask exact(SmallGrid g) {
        return ShadowAlgorithm.EXACT.compute(g.grid, g.light, ShadowOptions.DEFAULTS, g.pool);
    }
}
