package io.github.jdem846.bench;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.shade.IlluminationStage;
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
        dem = FractalDem.dem(SIZE, 846L);
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
}
