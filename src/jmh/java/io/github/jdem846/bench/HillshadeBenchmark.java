package io.github.jdem846.bench;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.shade.IlluminationStage;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Throughput of the hillshade kernels, single-threaded, on a seeded 2048² fractal DEM (diamond-square, 30 m cells).
 * The score is cells per microsecond, i.e. Mcells/s.
 *
 * <pre>./mvnw -Pjmh -o package -DskipTests &amp;&amp; java -jar target/benchmarks.jar HillshadeBenchmark</pre>
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 2, time = 2)
@Measurement(iterations = 3, time = 2)
@Fork(1)
public class HillshadeBenchmark {

    private static final int SIZE = 2048;

    @Param({"JDEM846", "HORN", "MULTIDIRECTIONAL"})
    public HillshadeMethod method;

    private Dem dem;
    private IlluminationStage stage;
    private final LightDirection light = new LightDirection(320, 25);
    private float[] out;

    @Setup
    public void setUp() {
        dem = new Dem(fractal(SIZE, 846L), GridGeometry.metric(SIZE, SIZE, 30));
        stage = method.stage(HillshadeOptions.DEFAULTS);
        out = new float[SIZE * SIZE];
    }

    /** The whole DEM; returns the output so that the work cannot be eliminated. */
    @Benchmark
    @OperationsPerInvocation(SIZE * SIZE)
    public float[] illuminate() {
        stage.illuminate(dem, light, 0, 0, SIZE, SIZE, out);
        return out;
    }

    /** A size × size diamond-square terrain (roughness 0.5, relief about ±1000 m) from {@code seed}. */
    static float[] fractal(int size, long seed) {
        int n = size; // power of two; the lattice has n + 1 points per side
        double[] h = new double[(n + 1) * (n + 1)];
        SplittableRandom rnd = new SplittableRandom(seed);
        double amplitude = 1000;
        for (int step = n; step > 1; step /= 2, amplitude *= 0.5) {
            int half = step / 2;
            for (int y = half; y < n; y += step) {           // diamond: centres of squares
                for (int x = half; x < n; x += step) {
                    double mean = (h[(y - half) * (n + 1) + x - half] + h[(y - half) * (n + 1) + x + half]
                            + h[(y + half) * (n + 1) + x - half] + h[(y + half) * (n + 1) + x + half]) / 4;
                    h[y * (n + 1) + x] = mean + amplitude * (rnd.nextDouble() * 2 - 1);
                }
            }
            for (int y = 0; y <= n; y += half) {               // square: edge midpoints
                for (int x = (y / half) % 2 == 0 ? half : 0; x <= n; x += step) {
                    double sum = 0;
                    int count = 0;
                    if (y >= half) { sum += h[(y - half) * (n + 1) + x]; count++; }
                    if (y + half <= n) { sum += h[(y + half) * (n + 1) + x]; count++; }
                    if (x >= half) { sum += h[y * (n + 1) + x - half]; count++; }
                    if (x + half <= n) { sum += h[y * (n + 1) + x + half]; count++; }
                    h[y * (n + 1) + x] = sum / count + amplitude * (rnd.nextDouble() * 2 - 1);
                }
            }
        }
        float[] v = new float[size * size];
        for (int y = 0; y < size; y++) {
            for (int x = 0; x < size; x++) {
                v[y * size + x] = (float) (1500 + h[y * (n + 1) + x]);
            }
        }
        return v;
    }
}
