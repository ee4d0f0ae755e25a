package io.github.jdem846.bench;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;

/**
 * {@code Renderer.hillshadeGray} (kernel, gray bytes, tiles of 256) on the seeded fractal, 8 rounds in one JVM,
 * milliseconds per round (docs/performance.md, "Hillshade kernels (JMH)").
 * Usage: {@code HillshadeGrayTiming SIZE THREADS JDEM846|HORN|MULTIDIRECTIONAL}.
 */
public final class HillshadeGrayTiming {

    private HillshadeGrayTiming() {
    }

    public static void main(String[] args) throws InterruptedException {
        Dem dem = FractalDem.dem(Integer.parseInt(args[0]), 846L);
        int threads = Integer.parseInt(args[1]);
        HillshadeMethod method = HillshadeMethod.valueOf(args[2]);
        LightField light = LightField.uniform(new LightDirection(315, 45));
        Renderer renderer = new Renderer(new RenderSettings(threads, 256));
        StringBuilder times = new StringBuilder();
        for (int i = 0; i < 8; i++) {
            long t0 = System.nanoTime();
            renderer.hillshadeGray(dem, method, HillshadeOptions.DEFAULTS, light, RenderProgress.NONE);
            times.append(' ').append((System.nanoTime() - t0) / 1_000_000);
        }
        System.out.println(method + ", " + threads + " thread(s), ms per round:" + times);
    }
}
