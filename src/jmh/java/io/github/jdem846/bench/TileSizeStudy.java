package io.github.jdem846.bench;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import java.util.Arrays;
import java.util.Locale;

/**
 * In-process timing of the renderer's tiled stages by tile size and thread count, after warm-up (the whole-command
 * times in docs/performance.md also hold JVM start-up, reading and PNG encoding). For each configuration: warm-up
 * runs, then the median and best of the timed runs of {@code Renderer.render} (default scene: table-2 tint ×
 * jdem846 hillshade) and of {@code Renderer.hillshadeGray} (horn), on the seeded fractal.
 *
 * <pre>java -cp target/benchmarks.jar io.github.jdem846.bench.TileSizeStudy 4000 3 7 64,128,256,512,1024 1,2</pre>
 */
public final class TileSizeStudy {

    private TileSizeStudy() {
    }

    public static void main(String[] args) throws InterruptedException {
        int size = Integer.parseInt(args[0]);
        int warmups = Integer.parseInt(args[1]);
        int runs = Integer.parseInt(args[2]);
        int[] tiles = Arrays.stream(args[3].split(",")).mapToInt(Integer::parseInt).toArray();
        int[] threads = Arrays.stream(args[4].split(",")).mapToInt(Integer::parseInt).toArray();
        Dem dem = FractalDem.dem(size, 846L);
        LightField light = LightField.uniform(new LightDirection(315, 45));
        Scene scene = Scene.defaults();
        System.out.println("| stage | threads | tile | median ms | best ms | Mcells/s (median) |");
        System.out.println("|---|---:|---:|---:|---:|---:|");
        for (String stage : new String[] {"render", "hillshade horn"}) {
            for (int t : threads) {
                for (int tile : tiles) {
                    Renderer renderer = new Renderer(new RenderSettings(t, tile));
                    long[] ns = new long[runs];
                    for (int i = -warmups; i < runs; i++) {
                        long start = System.nanoTime();
                        if (stage.equals("render")) {
                            renderer.render(dem, scene, RenderProgress.NONE);
                        } else {
                            renderer.hillshadeGray(dem, HillshadeMethod.HORN, HillshadeOptions.DEFAULTS, light,
                                    RenderProgress.NONE);
                        }
                        if (i >= 0) {
                            ns[i] = System.nanoTime() - start;
                        }
                    }
                    Arrays.sort(ns);
                    double median = ns[runs / 2] / 1e6;
                    System.out.println(String.format(Locale.ROOT, "| %s | %d | %d | %.0f | %.0f | %.1f |", stage, t,
                            tile, median, ns[0] / 1e6, (double) size * size / median / 1e3));
                }
            }
        }
    }
}
