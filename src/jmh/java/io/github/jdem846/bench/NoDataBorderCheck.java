package io.github.jdem846.bench;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.ShadowOptions;
import java.util.Arrays;
import java.util.Locale;
import java.util.concurrent.ForkJoinPool;

/**
 * How much of a method's disagreement with {@code exact} comes from the grid's edge: the same DEM, framed by a
 * border of no-data cells, makes every method see "no terrain" beyond the original edge (instead of each its own
 * convention: clamped heights up to half a cell for the march and exact, up to a cell for the sweep). Both versions
 * use a metric grid with the DEM's metric cell size (projected DEMs).
 */
final class NoDataBorderCheck {

    private NoDataBorderCheck() {
    }

    static String header() {
        return "| elev. | azim. | cells ≠ exact | of which the method shades | with a no-data border: cells ≠ exact "
                + "| of which the method shades | exact itself changes on |\n|---:|---:|---:|---:|---:|---:|---:|";
    }

    static String row(Dem dem, StudyMethod method, int border, double elevation, double azimuth, ForkJoinPool pool) {
        int w = dem.width();
        int h = dem.height();
        double cell = dem.geometry().cellWidthMeters(h / 2);
        int pw = w + 2 * border;
        float[] v = new float[pw * (h + 2 * border)];
        Arrays.fill(v, Float.NaN);
        for (int r = 0; r < h; r++) {
            System.arraycopy(dem.backingArray(), r * w, v, (r + border) * pw + border, w);
        }
        Dem plain = new Dem(dem.backingArray(), GridGeometry.metric(w, h, cell));
        Dem framed = new Dem(v, GridGeometry.metric(pw, h + 2 * border, cell));
        LightDirection light = new LightDirection(azimuth, elevation);
        float[] m0 = method.algorithm.compute(plain, light, method.options, pool).backingArray();
        float[] x0 = ShadowAlgorithm.EXACT.compute(plain, light, ShadowOptions.DEFAULTS, pool).backingArray();
        float[] m1 = method.algorithm.compute(framed, light, method.options, pool).backingArray();
        float[] x1 = ShadowAlgorithm.EXACT.compute(framed, light, ShadowOptions.DEFAULTS, pool).backingArray();
        long d0 = 0;
        long s0 = 0;
        long d1 = 0;
        long s1 = 0;
        long exactChanges = 0;
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                int i = r * w + c;
                int j = (r + border) * pw + c + border;
                boolean a = m0[i] >= 0.5f;
                boolean b = m1[j] >= 0.5f;
                if (a != (x0[i] >= 0.5f)) {
                    d0++;
                    s0 += a ? 1 : 0;
                }
                if (b != (x1[j] >= 0.5f)) {
                    d1++;
                    s1 += b ? 1 : 0;
                }
                exactChanges += (x0[i] >= 0.5f) != (x1[j] >= 0.5f) ? 1 : 0;
            }
        }
        return String.format(Locale.ROOT, "| %s | %s | %d | %d | %d | %d | %d |", AccuracyPlot.fmt(elevation),
                AccuracyPlot.fmt(azimuth), d0, s0, d1, s1, exactChanges);
    }
}
