package io.github.jdem846.bench;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.shadow.Sampling;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.ShadowOptions;
import io.github.jdem846.shadow.StepSize;
import java.util.Locale;
import java.util.concurrent.ForkJoinPool;

/**
 * How far the {@code exact} reference (eighth-cell steps on the bilinear surface) is from finer marches on the same
 * surface: the fraction of cells where it disagrees with 1/16- and 1/32-cell bilinear marches. This bounds the
 * error of the reference itself, below which the study's disagreements mean nothing.
 */
final class ReferenceConvergence {

    private ReferenceConvergence() {
    }

    /** Markdown table header. */
    static String header() {
        return "| elev. | azim. | exact ≠ march 1/16 cell | exact ≠ march 1/32 cell | 1/16 ≠ 1/32 |\n"
                + "|---:|---:|---:|---:|---:|";
    }

    /** One row: the three disagreements, in % of {@code cells}. */
    static String row(Dem dem, ForkJoinPool pool, double elevation, double azimuth, int[] cells) {
        LightDirection light = new LightDirection(azimuth, elevation);
        float[] exact = ShadowAlgorithm.EXACT.computeCells(dem, light, ShadowOptions.DEFAULTS, pool, cells);
        float[] s16 = march(dem, pool, light, cells, 1.0 / 16);
        float[] s32 = march(dem, pool, light, cells, 1.0 / 32);
        return String.format(Locale.ROOT, "| %s | %s | %.4f %% | %.4f %% | %.4f %% |", AccuracyPlot.fmt(elevation),
                AccuracyPlot.fmt(azimuth), differ(exact, s16), differ(exact, s32), differ(s16, s32));
    }

    private static float[] march(Dem dem, ForkJoinPool pool, LightDirection light, int[] cells, double step) {
        ShadowOptions o = ShadowOptions.DEFAULTS.withStep(StepSize.ofCells(step)).withSampling(Sampling.BILINEAR);
        return ShadowAlgorithm.MARCH.computeCells(dem, light, o, pool, cells);
    }

    private static double differ(float[] a, float[] b) {
        long n = 0;
        for (int i = 0; i < a.length; i++) {
            n += (a[i] >= 0.5f) != (b[i] >= 0.5f) ? 1 : 0;
        }
        return 100.0 * n / a.length;
    }
}
